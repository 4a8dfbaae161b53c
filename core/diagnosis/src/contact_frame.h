// The directions a support can push a cable in. A support the model does not have touches the
// cable without friction worth the name, so its force is normal to the cable where it touches:
// two components in the plane normal to the recorded tangent, not three. A fitted "contact" that
// mostly pulled along the cable would be no support at all, and with the axial component gone a
// point force can no longer stand in for a change of the whole cable's material.
#pragma once

#include <Eigen/Core>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::internal {

/// Orthonormal directions normal to the cable: `up` is the one closest to against gravity (the
/// push of a support the cable rests on), `side` = tangent x up.
struct ContactFrame {
  Vec3 tangent;
  Vec3 up;
  Vec3 side;
};

/// The recorded cable's directions at arc length `s` [m]: its tangent is the least-squares line
/// through the recorded `points` (3 x n [m], at arc lengths `point_s`, n [m]) within
/// `window` [m] of s, the window widened until it holds four points (gaps, sparse recordings).
/// `gravity` [m/s^2] sets `up`; without gravity, or along a vertical cable, up is the tangent's
/// fixed orthogonal. Needs at least two points.
ContactFrame RecordedContactFrame(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& point_s,
                                  double s, double window, const Vec3& gravity);

}  // namespace cablefit::internal
