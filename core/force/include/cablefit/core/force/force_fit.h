// Fitting one candidate model of force_diagnosis.h to a recorded curve: linear least squares in
// (ratio, offset, Iwan slip forces) with non-negativity (force_nnls.h) and the offset prior,
// with the noise level profiled out (the prior weight is updated by fixed-point iteration).
#pragma once

#include <Eigen/Core>

#include "cablefit/core/force/force_diagnosis.h"

namespace cablefit {

/// The data one fit needs, per recorded row.
struct ForceFitProblem {
  Eigen::VectorXd x;        // n [m] or [rad], recorded displacement/angle
  Eigen::VectorXd y;        // n [N] or [N m], recorded force/moment
  Eigen::VectorXd nominal;  // n [N] or [N m], nominal response at x
  double peak = 0.0;        // [N] or [N m], max |nominal|, sets the offset prior and floors
};

/// Steps of complexity from `none`: 0, 1, 2 for none, stiffness, hysteresis.
int ComplexityRank(ForceEffect effect);

/// Fits `effect` to `problem`. Fills every ForceCandidate field except `score`.
/// ComplexityRank(effect) times options.complexity_margin is included in `criterion`.
ForceCandidate FitForceCandidate(ForceEffect effect, const ForceFitProblem& problem,
                                 const ForceDiagnosisOptions& options);

}  // namespace cablefit
