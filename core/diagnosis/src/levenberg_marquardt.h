// A small dense Levenberg-Marquardt (Moré 1978 damping, Nielsen's update) for the effect fits:
// a handful of parameters, residuals from a forward rod solve, Jacobian by forward differences
// (optionally carried between them by Broyden's update).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace cablefit {

struct LmOptions {
  int max_iterations = 30;
  double relative_step = 1e-4;   // finite-difference step relative to `scale`
  double cost_tolerance = 1e-9;  // stop when the relative cost decrease is below this
  /// Accepted steps between difference Jacobians, the Jacobian carried by Broyden's update in
  /// between (0: a difference Jacobian every iteration). A stop is confirmed on a fresh one.
  int max_broyden_updates = 0;
};

struct LmResult {
  Eigen::VectorXd x;
  double cost = 0.0;  // 1/2 |r|^2
  int iterations = 0;
  int evaluations = 0;
  bool ok = false;    // at least one successful evaluation
  /// The cost stopped decreasing (relative decrease below cost_tolerance, or no damped step
  /// lowers it); false when the iterations ran out or the Jacobian could not be evaluated.
  bool converged = false;
};

/// What is known at the start point already (e.g. from a fit of part of the model): its
/// residual, and those Jacobian columns that need no difference.
struct LmStart {
  Eigen::VectorXd residual;     // m
  Eigen::MatrixXd jacobian;     // m x n, read where `known_columns`
  std::vector<bool> known_columns;  // n
};

using ResidualFunction = std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd*)>;

/// The forward-difference Jacobian (m x n) of `residual` at x, where it is r (m), with steps
/// relative_step * scale (backward where the forward point cannot be evaluated); columns whose
/// `skip` entry is true (skip may be empty) are left as they are. False when a column can be
/// evaluated neither way. Counts the evaluations in `evaluations`.
bool DifferenceJacobian(const ResidualFunction& residual, const Eigen::VectorXd& x,
                        const Eigen::VectorXd& r, const Eigen::VectorXd& scale,
                        double relative_step, const std::vector<bool>& skip, int* evaluations,
                        Eigen::MatrixXd* jac);

/// `residual(x, &r)` returns false when the model cannot be evaluated at x (e.g. the solver did
/// not converge); such points are treated as infinitely bad. `scale` gives each parameter's
/// typical size (finite-difference steps and damping are scaled by it).
/// With `start`, x0's residual is not evaluated and only its unknown Jacobian columns are.
LmResult MinimiseLeastSquares(const ResidualFunction& residual, const Eigen::VectorXd& x0,
                              const Eigen::VectorXd& scale, const LmOptions& options,
                              const LmStart* start = nullptr);

}  // namespace cablefit
