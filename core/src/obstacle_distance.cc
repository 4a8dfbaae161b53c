#include "obstacle_distance.h"

#include <Eigen/Geometry>
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

ObstacleField::ObstacleField(const std::vector<ObstacleSpec>& obstacles) {
  for (size_t k = 0; k < obstacles.size(); ++k) {
    const TriangleMesh& m = obstacles[k].mesh;
    for (int f = 0; f < m.faces.cols(); ++f) {
      Triangle t;
      t.a = m.vertices.col(m.faces(0, f));
      t.b = m.vertices.col(m.faces(1, f));
      t.c = m.vertices.col(m.faces(2, f));
      const Vec3 n = (t.b - t.a).cross(t.c - t.a);
      if (n.norm() == 0) continue;  // degenerate face: no side to push from
      t.normal = n.normalized();
      t.box.extend(t.a);
      t.box.extend(t.b);
      t.box.extend(t.c);
      t.obstacle = static_cast<int>(k);
      triangles_.push_back(t);
    }
  }
}

ObstacleHit ObstacleField::Nearest(const Vec3& p, double range) const {
  ObstacleHit hit;
  double best = std::numeric_limits<double>::infinity();
  const Triangle* best_t = nullptr;
  for (const Triangle& t : triangles_) {
    if (t.box.exteriorDistance(p) > range) continue;
    const Vec3 c = ClosestPointOnTriangle(p, t.a, t.b, t.c);
    const double d = (p - c).squaredNorm();
    // Ties (edges and vertices shared by faces): prefer the face the point is in front of.
    if (d < best - 1e-24 || (d <= best + 1e-24 && best_t && (p - c).dot(t.normal) > (p - c).dot(best_t->normal))) {
      best = d;
      best_t = &t;
      hit.point = c;
    }
  }
  if (!best_t || std::sqrt(best) > range) return ObstacleHit{};
  hit.obstacle = best_t->obstacle;
  const Vec3 away = p - hit.point;
  const double dist = away.norm();
  const bool inside = away.dot(best_t->normal) < 0;
  hit.normal = dist > 1e-12 && !inside ? Vec3(away / dist) : best_t->normal;
  hit.distance = inside ? -dist : dist;
  return hit;
}

}  // namespace cablefit
