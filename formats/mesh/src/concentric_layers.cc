#include "concentric_layers.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cablefit::internal {
namespace {

// Slack on "within the host's radius": the host's radius is fitted to its facets' vertices.
constexpr double kReachSlack = 0.02;
constexpr double kCentred = 0.25;

}  // namespace

std::optional<double> ConcentricLayerDiameter(const TriangleMesh& component, const MeshTube& host) {
  const Eigen::Matrix3Xd& route = host.centreline.points;  // 3 x n [m]
  const Eigen::Index segments = route.cols() - 1;
  if (segments < 1 || component.vertices.cols() == 0) return std::nullopt;
  const double reach = 0.5 * host.diameter * (1 + kReachSlack);
  // Per segment of the route: the sum of the vertices' offsets from it, their distances, count.
  std::vector<Vec3> offset_sum(static_cast<size_t>(segments), Vec3::Zero());
  std::vector<double> distance_sum(static_cast<size_t>(segments), 0.0);
  std::vector<int> count(static_cast<size_t>(segments), 0);
  double farthest = 0;
  for (Eigen::Index v = 0; v < component.vertices.cols(); ++v) {
    const Vec3 p = component.vertices.col(v);
    double best = std::numeric_limits<double>::infinity();
    Eigen::Index best_segment = 0;
    Vec3 best_offset = Vec3::Zero();
    for (Eigen::Index i = 0; i < segments; ++i) {
      const Vec3 a = route.col(i), ab = route.col(i + 1) - a;
      const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
      const Vec3 offset = p - (a + t * ab);
      if (offset.norm() < best) {
        best = offset.norm();
        best_segment = i;
        best_offset = offset;
      }
    }
    if (best > reach) return std::nullopt;
    farthest = std::max(farthest, best);
    offset_sum[static_cast<size_t>(best_segment)] += best_offset;
    distance_sum[static_cast<size_t>(best_segment)] += best;
    ++count[static_cast<size_t>(best_segment)];
  }
  for (size_t i = 0; i < offset_sum.size(); ++i) {
    if (count[i] < 3) continue;  // too few vertices there to say where their middle is
    if (offset_sum[i].norm() > kCentred * distance_sum[i]) return std::nullopt;
  }
  return 2 * farthest;
}

}  // namespace cablefit::internal
