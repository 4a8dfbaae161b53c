// The harness fits' forward model: the nominal NetworkSpec changed by a model at x, solved (warm
// from the last equilibrium), and the offsets of the observed points from it, in noise units.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "cablefit/core/network/network_simulation.h"
#include "harness_effects.h"
#include "levenberg_marquardt.h"

namespace cablefit::internal {

/// The observed points one branch contributes to the fits (thinned), with their arc-length
/// estimates along it.
struct BranchPoints {
  Eigen::Matrix3Xd points;  // 3 x n [m]
  Eigen::VectorXd s;        // n [m]
  /// n [1/m]: 1 / sqrt(sigma^2 + e^2), the recording's noise sigma and the forward model's own
  /// error e at the point (its discretisation, largest where the cable drapes over an edge).
  Eigen::VectorXd weight;
};

/// Offsets (3 x n per branch [m]) of the points from `shapes` (per branch centrelines).
std::vector<Eigen::Matrix3Xd> PointOffsets(const std::vector<BranchPoints>& points,
                                           const std::vector<Polyline>& shapes);

class HarnessResidual {
 public:
  /// `points` per branch of `nominal`; offsets are weighted by each point's weight.
  HarnessResidual(const NetworkSpec& nominal, const std::vector<BranchPoints>& points,
                  double element_length);

  /// Residual of `model` at x (or of the nominal when `model` is null): 3 per observed point,
  /// branch by branch. False when the changed harness cannot be solved. `shapes` (optional)
  /// receives the solved branch centrelines.
  bool Evaluate(const HarnessEffectModel* model, const Eigen::VectorXd& x, Eigen::VectorXd* r,
                std::vector<Polyline>* shapes = nullptr);
  /// The weighted offsets of `points` from given branch shapes (no solve).
  Eigen::VectorXd Offsets(const std::vector<Polyline>& shapes) const;
  int size() const { return size_; }
  int solves() const { return solves_; }
  /// The last converged solution (junction moments, tangents).
  const NetworkSolution& last() const { return last_; }

 private:
  const NetworkSpec* nominal_;
  const std::vector<BranchPoints>* points_;
  NetworkOptions options_;
  int size_ = 0;
  int solves_ = 0;
  NetworkSolution last_;  // warm start
};

/// A fitted model: its parameters, residual and cost (1/2 |r|^2).
struct HarnessFit {
  Eigen::VectorXd x;
  Eigen::VectorXd residual;
  double cost = 0.0;
  bool ok = false;
  int solves = 0;
};

/// Levenberg-Marquardt of `model` from `start` against the observation.
HarnessFit FitHarnessModel(const HarnessEffectModel& model, const Eigen::VectorXd& start,
                           const NetworkSpec& nominal, const std::vector<BranchPoints>& points,
                           double element_length, int max_iterations);

/// The linearised fit of the model's amplitudes at its neutral start (one difference solve per
/// amplitude): the start it suggests and the cost it predicts.
struct HarnessScreen {
  Eigen::VectorXd start;
  double predicted_cost = 0.0;
  int solves = 0;
};
HarnessScreen ScreenHarnessModel(const HarnessEffectModel& model, const Eigen::VectorXd& nominal_residual,
                                 const NetworkSpec& nominal, const std::vector<BranchPoints>& points,
                                 double element_length);

}  // namespace cablefit::internal
