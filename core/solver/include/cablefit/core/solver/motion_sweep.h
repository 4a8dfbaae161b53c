// A quasi-static motion sweep: some supports of a rod follow a rigid motion (a door hinge, a
// seat rail) through a list of poses, each solved warm from the previous one (natural-parameter
// continuation along the equilibrium branch, RodSimulator::Resimulate). The stability verdict
// of every pose is that of the branch followed (the solver does not escape saddles here); where
// the branch is lost -- the pose is an unstable equilibrium, or the shape jumps (a fold of the
// branch: snap-through) -- the sweep says so and goes on along the stable branch it lands on.
// (Continuation and folds: Allgower & Georg, "Introduction to Numerical Continuation Methods"
// (1990), ch. 1-2.)
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include "cablefit/core/rod/rod_spec.h"
#include "cablefit/core/solver/rod_simulation.h"

namespace cablefit {

/// `base` with supports `moving` (indices into base.supports) carried by the rigid motion `t`:
/// position -> t * position, tangent and normal rotated. Throws InvalidInput for a bad index.
RodSpec MovedSpec(const RodSpec& base, const std::vector<int>& moving, const Eigen::Isometry3d& t);

struct SweepOptions {
  /// Accuracy and solver settings of every pose (statics.escape_unstable is set by the sweep:
  /// off while following a branch, on to leave a lost one).
  SimulationOptions simulation;
  /// A pose whose centreline moves more than this many times the previous pose's step (and more
  /// than 10 x simulation.accuracy) jumped to another branch: a snap-through. Steps of a
  /// smooth sweep grow slowly (at most like 1/sqrt of the distance to a fold); a snap moves the
  /// cable by a good part of its length at once.
  double jump_factor = 5.0;
  /// A pose that does not converge warm is retried in this many sub-steps from the previous one.
  int substeps = 4;
  bool IsValid(std::string* why) const;
};

struct SweepPose {
  double q = 0.0;           ///< motion parameter [rad] or [m]
  SimulationResult result;  ///< the equilibrium reported at this pose (stable branch if escaped)
  bool converged = false;
  bool stable = false;  ///< of the reported equilibrium
  /// The branch followed so far ended here: the warm solve found an unstable equilibrium
  /// (`escaped_unstable`) or jumped (`jumped`).
  bool escaped_unstable = false;
  bool jumped = false;
  double step = 0.0;  ///< [m] largest centreline displacement from the previous pose
};

struct SweepSummary {
  std::vector<SweepPose> poses;  ///< one per requested parameter solved (fewer if it stopped)
  int branch_lost_pose = -1;     ///< first pose where the followed branch ended, -1 = never
  bool completed = false;        ///< every pose converged
  std::string message;           ///< why it stopped, empty when completed
  double seconds = 0.0;
};

/// Solves `base` at motion parameter 0 from `initial` (the drawn shape; null: a smooth curve
/// through the supports, as RodSimulator::Simulate), walks to q.front() in
/// steps no longer than the sweep's own (not reported), then solves every pose in `q` warm from
/// the previous one. `motion(q)` maps drawn support poses to moved ones. Throws InvalidInput for
/// an invalid spec or index; a pose that does not converge ends the sweep (summary.message).
SweepSummary SweepRod(const RodSpec& base, const Polyline* initial, const std::vector<int>& moving,
                      const std::function<Eigen::Isometry3d(double)>& motion,
                      const std::vector<double>& q, const SweepOptions& options = {});

}  // namespace cablefit
