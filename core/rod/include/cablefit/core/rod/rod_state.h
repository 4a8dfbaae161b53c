// What the statics solver changes: the frames of every item, the multipliers of the position
// constraints, and the continuation state (support targets, load factor).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

struct RodModel;
struct Polyline;

struct RodState {
  std::vector<Eigen::Vector4d> q;  // per item: unit quaternion (w, x, y, z) of its frame
  Eigen::VectorXd lambda;          // num_constraints [N]: multipliers (= -reaction force)
  // Continuation: current targets of every support (start at the initial shape's own poses and
  // are moved to the model's targets), and factors on loads and natural curvature.
  std::vector<Vec3> support_position;        // [m]
  std::vector<Eigen::Vector4d> support_q;    // frame targets as quaternions
  double load_factor = 1.0;
  double natural_factor = 1.0;
  // Rest curvature taken from a drawn shape (per edge, material frame [1/m]; empty = none),
  // added to the natural one with drawn_factor: at drawn_factor = 1 and natural_factor = 0 the
  // drawn shape is in equilibrium at zero load, the solved start of the drawn-rest homotopy.
  std::vector<Eigen::Vector3d> drawn_curvature;
  double drawn_factor = 0.0;

  /// Node positions (3 x (n+1)) [m] from the frames, anchored at the anchor support.
  Eigen::Matrix3Xd NodePositions(const RodModel& model) const;
};

}  // namespace cablefit
