// The search of a tolerance box, shared by cables solved alone and networks: which set-ups to
// solve (every corner, or the worst ones by linearised sensitivity; then interior checks) and
// how far each one's shape went. Internal to relax_tolerance.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cablefit/app/tolerance/tolerance_cases.h"
#include "cablefit/core/base/geometry_types.h"

namespace cablefit::addin {

/// Solves the set-up at `eps` (one entry in [-1, 1] per varied quantity, times its tolerance)
/// starting from `start` (per branch), the solved shape of the set-up at `from` (the nominal one
/// when `from` is zero): one node centreline per branch (s from 0 [m]); false when it did not
/// converge, with the solver's reason in `why`. A set-up that cannot exist (a fixing shifted so
/// far that the cable between two supports is shorter than their distance) may throw
/// InvalidInput: it is caught as not buildable.
using ToleranceSolver = std::function<bool(
    const Eigen::VectorXd& eps, const Eigen::VectorXd& from, const std::vector<Polyline>& start,
    std::vector<Polyline>* shapes, std::string* why)>;

struct ToleranceOutcome {
  Eigen::VectorXd eps;
  bool converged = false;
  bool buildable = true;         ///< false when the set-up threw InvalidInput (cannot exist)
  std::string why;               ///< when not converged
  std::vector<Polyline> shapes;  ///< per branch when converged
};

struct ToleranceSearch {
  std::vector<ToleranceOutcome> corners, interior;
  bool all_corners = true;
  int sensitivity_solves = 0;
};

/// A set-up not reached from the nominal shape is walked to in 2, then 4 equal steps, each from
/// the last (a 2 % longer harness whose taut stretches all buckle at once is one such).
/// Solves the corners of the k-quantity box (all up to kExhaustiveQuantities, else the worst
/// kChosenCorners by central-difference sensitivities of the shapes' points, their slide along
/// the nominal cable taken out) and kInteriorChecks interior points (fixed seed: the same
/// set-ups on every run). `nominal`: per branch, the nominal node centreline solved the way
/// `solve` solves. The solves run on up to `threads` threads (`solve` must allow it); the
/// result does not depend on how many.
ToleranceSearch SearchToleranceBox(int k, const std::vector<Polyline>& nominal,
                                   const ToleranceSolver& solve, int threads);

/// How far a varied cable gets from the nominal one, as curves.
struct CurveExcursion {
  double distance = 0.0;      ///< [m] largest distance of a varied point to the nominal curve
  double s = 0.0;             ///< [m] nominal arc length of the point nearest to it
  Vec3 point = Vec3::Zero();  ///< [m] that varied point
};
CurveExcursion MeasureExcursion(const Polyline& nominal, const Polyline& varied);

/// Fills `ct`'s corners and interior cases from `search`, branch `branch` of its shapes:
/// `describe` gives a case's varied quantities from its eps; `yardstick` [m] is how much
/// further than the worst corner an interior case may go (solver accuracy) before the corners
/// are said not to bound the envelope.
void MeasureCases(const ToleranceSearch& search, int branch, const Polyline& nominal,
                  double yardstick, const std::function<ToleranceCase(const Eigen::VectorXd&)>& describe,
                  CableTolerance* ct);

}  // namespace cablefit::addin
