// Nearest points on triangle meshes, for one-sided contact of the cable with solids.
// Closest point on a triangle: Ericson, "Real-Time Collision Detection" (2005), sec. 5.1.5.
#pragma once

#include <vector>

#include "cablefit/core/network_spec.h"

namespace cablefit {

struct ObstacleHit {
  int obstacle = -1;              // -1: nothing within range
  Vec3 point = Vec3::Zero();      // nearest surface point [m]
  Vec3 normal = Vec3::UnitZ();    // outward direction from the surface towards the query point
  double distance = 0.0;          // signed [m]: < 0 when the point is inside the solid
};

class ObstacleField {
 public:
  explicit ObstacleField(const std::vector<ObstacleSpec>& obstacles);
  bool empty() const { return triangles_.empty(); }
  /// The nearest surface point within `range` [m] of p (signed by the nearest face's side).
  ObstacleHit Nearest(const Vec3& p, double range) const;

 private:
  struct Triangle {
    Vec3 a, b, c, normal;
    Eigen::AlignedBox3d box;
    int obstacle;
  };
  std::vector<Triangle> triangles_;
};

/// Closest point to p on triangle (a, b, c).
Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace cablefit
