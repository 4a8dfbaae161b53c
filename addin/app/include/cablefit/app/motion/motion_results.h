// What a motion sweep found: every pose of every swept cable measured, the tracked points' paths
// and what could not be swept.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/core/network/clearance.h"
#include "cablefit/core/solver/rod_solution.h"

namespace cablefit::addin {

/// One pose of one cable.
struct MotionPose {
  double q = 0.0;  ///< [rad] or [m]
  bool converged = false, stable = false;
  bool escaped_unstable = false, jumped = false;  ///< the followed branch ended here (and how)
  double step = 0.0;                       ///< [m] largest centreline move from the previous pose
  double min_bend_radius = 0.0;            ///< [m] (infinity when straight)
  double min_bend_radius_s = 0.0;          ///< [m]
  bool bend_flag = false;                  ///< tighter than the cable's limit
  double max_tension = 0.0;                ///< [N]
  double max_tension_s = 0.0;              ///< [m]
  std::vector<SupportReaction> reactions;  ///< per support of the set-up, in order
  /// Least clearance to a solid it does not rest on or another cable (other cables at the same
  /// pose); `clearance_to` names it, `clearance_required` [m] is what harness.json asks.
  ClearanceHit clearance;
  std::string clearance_to;
  double clearance_required = 0.0;
  int newton_iterations = 0;
  Polyline centreline;  ///< sampled for output: s [m], points 3 x n [m]
};

/// The sweep of one cable.
struct CableMotion {
  int cable = 0;  ///< drawing cable index
  std::string name;
  std::vector<int> moving;  ///< indices of the set-up's supports that move
  std::vector<MotionPose> poses;
  int branch_lost_pose = -1;  ///< first pose where the followed branch ended, -1 = never
  bool completed = false;
  std::string message;  ///< why the sweep stopped early
  /// [m] largest distance between the first and the last pose's centreline (there and back:
  /// 0 up to solver accuracy unless the branch was lost); NaN when not there and back.
  double back_to_start = 0.0;
  /// Solved as one network with other cables (their names, comma separated), empty when alone.
  /// A network's poses are solved at one resolution (`elements` in the whole network), not
  /// refined: `resolution_error` [m] is how far that is from the refined relax at the drawn pose
  /// (NaN when the motion does not start there).
  std::string network;
  /// Nothing of the motion holds it (only solids move): its relaxed shape at every pose, listed
  /// so that its clearance to the moving solids is measured.
  bool held_still = false;
  int elements = 0;
  double resolution_error = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;
};

/// The path of one tracked point of a cable over the motion.
struct MotionTrack {
  std::string cable;
  double s = 0.0;            ///< [m] along the cable (clamped to its length)
  Eigen::Matrix3Xd points;   ///< 3 x poses [m] where the point is at each pose
  double travel = 0.0;       ///< [m] length of the path (pose to pose)
  double excursion = 0.0;    ///< [m] farthest distance from its place at the first pose
  int excursion_pose = 0;
};

/// The motion of one input.
struct FileMotion {
  MotionConfig config;
  std::vector<double> q;              ///< the pose parameters
  std::vector<CableMotion> cables;    ///< swept cables, in drawing order
  std::vector<int> moving_solids;     ///< drawing solids that move with the motion
  std::vector<std::string> moving_solid_names;
  std::vector<MotionTrack> tracks;    ///< the motion's tracked points, in its order
  std::vector<std::string> problems;  ///< moving supports that could not be swept, one line each
  double seconds = 0.0;
};

}  // namespace cablefit::addin
