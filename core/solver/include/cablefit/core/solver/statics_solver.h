// Static equilibrium of a RodModel by Newton's method on the KKT system of
//   min E(q)  subject to  c(q) = 0   (support positions),
// with the exact gradient and Hessian (block-tridiagonal, O(n) per step), inertia correction
// (the reduced Hessian is made positive definite so every step heads for a minimum), a
// backtracking line search on the exact-penalty merit E + nu |c|_1, and continuation in the
// support poses and loads when a direct solve fails. (Options/Summary follow Ceres' solver.h.)
#pragma once

#include <functional>
#include <string>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/rod_state.h"

namespace cablefit {

struct StaticsOptions {
  /// Newton iterations per solve (direct solve and each continuation step).
  int max_iterations = 60;
  /// Converged when the Lagrangian gradient is below this times force_scale * length [N m] ...
  double gradient_tolerance = 1e-11;
  /// ... and every position constraint below this times the length [m].
  double constraint_tolerance = 1e-12;
  /// Largest rotation of any frame in one Newton step [rad] (longer steps are scaled down).
  double max_step_rotation = 0.5;
  /// Continuation steps allowed in total when the direct solve fails.
  int max_continuation_steps = 200;
  /// Ramp gravity and point loads from 0 together with the support poses when continuing.
  bool ramp_loads = false;
  /// When the solution is an unstable equilibrium (a saddle reached from a symmetric start, e.g.
  /// a planar loop that would fall sideways), perturb it and solve again to find a stable one.
  /// Off for stability studies that want the verdict of the state they start from.
  bool escape_unstable = true;
  /// Gets every continuation step; returning false cancels (the solve throws Cancelled).
  ProgressCallback progress;

  bool IsValid(std::string* why) const;
};

enum class TerminationType {
  kConverged,          ///< gradient and constraint tolerances met
  kNoConvergence,      ///< iteration or continuation budget exhausted
  kLineSearchFailure,  ///< no step decreased the merit function (singular or degenerate set-up)
  kInvalidOptions,     ///< StaticsOptions::IsValid failed; the message says why, nothing solved
};
const char* ToString(TerminationType t);

struct StaticsSummary {
  TerminationType termination = TerminationType::kNoConvergence;
  std::string message;
  int iterations = 0;             // Newton iterations in total
  int continuation_steps = 0;     // 0 when the direct solve converged
  int second_order_corrections = 0;  // full steps taken with a second-order correction
  /// Folds of the continuation path crossed by snapping (the message says at which t): the
  /// result is on another branch than the drawing's, a state the cable jumps to.
  int folds_passed = 0;
  double initial_energy = 0.0;    // [J]
  double final_energy = 0.0;      // [J]
  double gradient_norm = 0.0;     // [N m] final max-norm of the Lagrangian gradient
  double constraint_norm = 0.0;   // [m] final max-norm of the position constraints
  double seconds = 0.0;
  /// Stability verdict at the solution: the Hessian of the Lagrangian restricted to the
  /// constraint manifold is positive definite (Sylvester inertia of the KKT matrix).
  bool stable = false;
  int negative_directions = 0;    // unstable directions on the constraint manifold
  bool converged() const { return termination == TerminationType::kConverged; }
  std::string BriefReport() const;
};

/// Newton solve at the state's current targets and factors (no continuation).
StaticsSummary SolveStaticsDirect(const RodModel& model, RodState* state,
                                  const StaticsOptions& options);

/// Full solve: sets the targets to the model's supports and full loads; tries a direct Newton
/// solve from `state`; on failure it follows a homotopy from `state` taken as stress-free (its own
/// curvature as rest curvature, its own support poses, no load: solved exactly there) to the real
/// rest curvature, support poses and loads; then continuation in the poses with loads ramped. A
/// continuation halves its step on failure and reports the folds it snapped through.
StaticsSummary SolveStatics(const RodModel& model, RodState* state, const StaticsOptions& options);

/// Stability verdict and inertia at the state (the solver calls it at convergence).
void EvaluateStability(const RodModel& model, const RodState& state, StaticsSummary* summary);

}  // namespace cablefit
