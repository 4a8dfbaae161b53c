// Nearest points on triangle meshes, for one-sided contact of the cable with solids.
// Closest point on a triangle: Ericson, "Real-Time Collision Detection" (2005), sec. 5.1.5.
// Body panels from CAD come with 10^4..10^6 triangles and every contact round asks for every
// node, so the triangles sit in a bounding-volume tree (median split on the longest axis of the
// centroids) and a query visits only the boxes that can still beat the best distance found.
#pragma once

#include <vector>

#include "cablefit/core/network/network_spec.h"

namespace cablefit {

struct ObstacleHit {
  int obstacle = -1;              // -1: nothing within range
  Vec3 point = Vec3::Zero();      // nearest surface point [m]
  Vec3 normal = Vec3::UnitZ();    // outward direction from the surface towards the query point
  double distance = 0.0;          // signed [m]: < 0 when the point is inside the solid
};

class ObstacleField {
 public:
  /// `ignored` (empty, or one flag per obstacle) leaves obstacles out while the others keep
  /// their index in `obstacles`.
  explicit ObstacleField(const std::vector<ObstacleSpec>& obstacles,
                         const std::vector<char>& ignored = {});
  bool empty() const { return triangles_.empty(); }
  int num_triangles() const { return static_cast<int>(triangles_.size()); }
  /// The nearest surface point within `range` [m] of p (signed by the nearest face's side).
  ObstacleHit Nearest(const Vec3& p, double range) const;
  /// The same answer by testing every triangle: the reference the tree is checked against.
  ObstacleHit NearestByScan(const Vec3& p, double range) const;

 private:
  struct Triangle {
    Vec3 a, b, c, normal;
    Eigen::AlignedBox3d box;
    int obstacle;
  };
  // Inner node: children left = this + 1 (stored next) and right; leaf: triangles [begin, end).
  struct TreeNode {
    Eigen::AlignedBox3d box;
    int right = -1;  // -1 for a leaf
    int begin = 0, end = 0;
  };
  struct Best;
  int Build(int begin, int end);
  void Consider(const Triangle& t, const Vec3& p, Best* best) const;
  ObstacleHit Finish(const Vec3& p, double range, const Best& best) const;

  std::vector<Triangle> triangles_;
  std::vector<TreeNode> tree_;
};

/// Closest point to p on triangle (a, b, c).
Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace cablefit
