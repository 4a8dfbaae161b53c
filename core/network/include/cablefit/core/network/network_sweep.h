// A quasi-static motion sweep of a rod network (a harness tree, or a cable in contact with
// solids): supports of some branches follow a rigid motion through a list of poses, every pose
// solved warm from the previous pose's equilibrium (its node positions and material frames), as
// SweepRod does for one rod. Each pose is solved at one resolution (`NetworkOptions`), not
// refined and extrapolated: the caller says how far that resolution is from its refined relax.
// Stability and branch loss are judged as in SweepRod (motion_sweep.h): an unstable equilibrium
// reached warm is left for a stable one, a jump of the shape is a snap-through; both are
// reported at the pose where they happen, and the sweep goes on along the stable branch.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/network/network_spec.h"

namespace cablefit {

/// One support that moves: `support` indexes `branch`'s supports.
struct NetworkMovingSupport {
  int branch = 0;
  int support = 0;
};

/// What a motion carries: supports, and obstacles (indices into NetworkSpec::obstacles: a door
/// panel the cable rests on moves with the door).
struct NetworkMoving {
  std::vector<NetworkMovingSupport> supports;
  std::vector<int> obstacles;
};

/// `base` with the `moving` supports (position, tangent and normal) and obstacles (their
/// vertices) carried by the rigid motion `t`. Throws InvalidInput for an index that does not
/// exist.
NetworkSpec MovedNetworkSpec(const NetworkSpec& base, const NetworkMoving& moving,
                             const Eigen::Isometry3d& t);

struct NetworkSweepOptions {
  /// Resolution and solver settings of every pose (statics.escape_unstable is set by the
  /// sweep: off while following a branch, on to leave a lost one). Warm starts are the
  /// sweep's: initial_routes and initial_normals are ignored.
  NetworkOptions network;
  /// As SweepOptions::jump_factor: a pose whose nodes move more than this many times the
  /// previous pose's largest move (and more than `jump_floor`) jumped to another branch.
  double jump_factor = 5.0;
  double jump_floor = 1e-5;  // [m]
  /// A pose that does not converge warm is retried in this many sub-steps from the previous one.
  int substeps = 4;
  bool IsValid(std::string* why) const;
};

struct NetworkSweepPose {
  double q = 0.0;             ///< motion parameter [rad] or [m]
  NetworkSolution solution;   ///< the equilibrium reported at this pose
  bool converged = false;
  bool stable = false;
  bool escaped_unstable = false;  ///< the branch followed ended here in an unstable equilibrium
  bool jumped = false;            ///< ... or in a jump (snap-through)
  double step = 0.0;              ///< [m] largest node move from the previous pose
};

struct NetworkSweepSummary {
  std::vector<NetworkSweepPose> poses;  ///< one per parameter solved (fewer if it stopped)
  int branch_lost_pose = -1;            ///< first pose where the followed branch ended
  bool completed = false;
  std::string message;                  ///< why it stopped, empty when completed
  int newton_iterations = 0;
  double seconds = 0.0;
};

/// Solves `base` at parameter 0 from its drawn routes, walks to q.front() in steps no longer
/// than the sweep's own (not reported), then every pose of `q` warm from the previous one.
/// Throws InvalidInput for an invalid spec or index; a pose that cannot be solved ends the
/// sweep (summary.message).
NetworkSweepSummary SweepNetwork(const NetworkSpec& base, const NetworkMoving& moving,
                                 const std::function<Eigen::Isometry3d(double)>& motion,
                                 const std::vector<double>& q,
                                 const NetworkSweepOptions& options = {});

}  // namespace cablefit
