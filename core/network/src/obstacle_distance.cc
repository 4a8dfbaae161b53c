#include "obstacle_distance.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace cablefit {

Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

namespace {
constexpr int kLeafSize = 4;
// Squared distances closer than this count as a tie (a point on an edge shared by two faces).
constexpr double kTie = 1e-24;
}  // namespace

struct ObstacleField::Best {
  double d2 = std::numeric_limits<double>::infinity();
  const Triangle* triangle = nullptr;
  Vec3 point = Vec3::Zero();
};

ObstacleField::ObstacleField(const std::vector<ObstacleSpec>& obstacles,
                             const std::vector<char>& ignored) {
  for (size_t k = 0; k < obstacles.size(); ++k) {
    if (k < ignored.size() && ignored[k]) continue;
    const TriangleMesh& m = obstacles[k].mesh;
    for (int f = 0; f < m.faces.cols(); ++f) {
      Triangle t;
      t.a = m.vertices.col(m.faces(0, f));
      t.b = m.vertices.col(m.faces(1, f));
      t.c = m.vertices.col(m.faces(2, f));
      const Vec3 n = (t.b - t.a).cross(t.c - t.a);
      // Degenerate faces have no side to push from; a non-finite vertex would also break the
      // tree's median split (NaN has no order).
      if (!(n.norm() > 0) || !std::isfinite(n.norm()) || !t.a.allFinite() || !t.b.allFinite() ||
          !t.c.allFinite())
        continue;
      t.normal = n.normalized();
      t.box.extend(t.a);
      t.box.extend(t.b);
      t.box.extend(t.c);
      t.obstacle = static_cast<int>(k);
      triangles_.push_back(t);
    }
  }
  if (!triangles_.empty()) {
    tree_.reserve(2 * triangles_.size() / kLeafSize + 2);
    Build(0, static_cast<int>(triangles_.size()));
  }
}

int ObstacleField::Build(int begin, int end) {
  const int index = static_cast<int>(tree_.size());
  tree_.emplace_back();
  Eigen::AlignedBox3d box, centres;
  for (int i = begin; i < end; ++i) {
    box.extend(triangles_[i].box);
    centres.extend(triangles_[i].box.center());
  }
  tree_[index].box = box;
  tree_[index].begin = begin;
  tree_[index].end = end;
  if (end - begin <= kLeafSize) return index;
  int axis = 0;
  centres.sizes().maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  std::nth_element(triangles_.begin() + begin, triangles_.begin() + mid, triangles_.begin() + end,
                   [axis](const Triangle& x, const Triangle& y) {
                     return x.box.center()[axis] < y.box.center()[axis];
                   });
  Build(begin, mid);
  const int right = Build(mid, end);
  tree_[index].right = right;
  return index;
}

void ObstacleField::Consider(const Triangle& t, const Vec3& p, Best* best) const {
  const Vec3 c = ClosestPointOnTriangle(p, t.a, t.b, t.c);
  const double d = (p - c).squaredNorm();
  // Ties (edges and vertices shared by faces): prefer the face the point is in front of.
  if (d < best->d2 - kTie ||
      (d <= best->d2 + kTie && best->triangle &&
       (p - c).dot(t.normal) > (p - c).dot(best->triangle->normal))) {
    best->d2 = d;
    best->triangle = &t;
    best->point = c;
  }
}

ObstacleHit ObstacleField::Finish(const Vec3& p, double range, const Best& best) const {
  if (!best.triangle || std::sqrt(best.d2) > range) return ObstacleHit{};
  ObstacleHit hit;
  hit.obstacle = best.triangle->obstacle;
  hit.point = best.point;
  const Vec3 away = p - hit.point;
  const double dist = away.norm();
  const bool inside = away.dot(best.triangle->normal) < 0;
  hit.normal = dist > 1e-12 && !inside ? Vec3(away / dist) : best.triangle->normal;
  hit.distance = inside ? -dist : dist;
  return hit;
}

ObstacleHit ObstacleField::NearestByScan(const Vec3& p, double range) const {
  Best best;
  for (const Triangle& t : triangles_)
    if (t.box.exteriorDistance(p) <= range) Consider(t, p, &best);
  return Finish(p, range, best);
}

ObstacleHit ObstacleField::Nearest(const Vec3& p, double range) const {
  Best best;
  if (tree_.empty()) return ObstacleHit{};
  const double range2 = range * range;
  // Depth is about log2(n / kLeafSize); 64 levels hold any mesh that fits in memory.
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const TreeNode& node = tree_[stack[--top]];
    const double box2 = node.box.squaredExteriorDistance(p);
    if (box2 > range2 || box2 > best.d2 + kTie) continue;
    if (node.right < 0) {
      for (int i = node.begin; i < node.end; ++i) Consider(triangles_[i], p, &best);
      continue;
    }
    const int left = static_cast<int>(&node - tree_.data()) + 1;
    const double dl = tree_[left].box.squaredExteriorDistance(p);
    const double dr = tree_[node.right].box.squaredExteriorDistance(p);
    // The nearer child is searched first (pushed last), so its best prunes the other.
    if (dl <= dr) {
      stack[top++] = node.right;
      stack[top++] = left;
    } else {
      stack[top++] = left;
      stack[top++] = node.right;
    }
  }
  return Finish(p, range, best);
}

}  // namespace cablefit
