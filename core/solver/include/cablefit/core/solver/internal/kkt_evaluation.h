// The solver's Lagrangian and constraints at a state, exposed for derivative checks (gradient and
// Hessian against finite differences). Not part of the solver's interface: the solver itself
// never needs them in this form.
#pragma once

#include <Eigen/Core>

#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/rod_state.h"

namespace cablefit::internal {

/// Energy, gradient, Hessian of the Lagrangian (dense, for checks on small models) and the
/// position constraints with their Jacobian, all with respect to the body-frame rotation of
/// every item (3 per item), without masking.
struct KktEvaluation {
  double energy = 0.0;            // [J]
  Eigen::VectorXd gradient;       // 3 items [N m]
  Eigen::MatrixXd hessian;        // 3 items x 3 items [N m] (Lagrangian)
  Eigen::VectorXd constraints;    // m [m]
  Eigen::MatrixXd jacobian;       // m x 3 items [m]
};
KktEvaluation EvaluateKkt(const RodModel& model, const RodState& state,
                          const Eigen::VectorXd& lambda, bool dense_hessian);

/// q_i <- q_i * exp(theta_i) for every item (theta: 3 items).
void RotateFrames(const RodModel& model, const Eigen::VectorXd& theta, RodState* state);

}  // namespace cablefit::internal
