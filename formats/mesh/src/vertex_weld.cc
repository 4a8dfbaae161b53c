#include "vertex_weld.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace cablefit::internal {
namespace {

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    return static_cast<std::size_t>(c[0] * 73856093 ^ c[1] * 19349663 ^ c[2] * 83492791);
  }
};

}  // namespace

TriangleMesh WeldNearVertices(const TriangleMesh& mesh) {
  const Eigen::Index nv = mesh.vertices.cols();
  if (nv == 0) return mesh;
  const Vec3 lo = mesh.vertices.rowwise().minCoeff(), hi = mesh.vertices.rowwise().maxCoeff();
  const double tolerance = 1e-6 * ((hi - lo).norm() + mesh.vertices.cwiseAbs().maxCoeff());
  if (!(tolerance > 0)) return mesh;
  // Each vertex goes to the first kept vertex within the tolerance, looked up in the cells around
  // it (cells as wide as the tolerance).
  std::unordered_map<Cell, std::vector<int>, CellHash> kept_in;
  std::vector<int> target(static_cast<size_t>(nv));
  std::vector<int> kept;
  const auto cell_of = [&](const Vec3& p) {
    return Cell{static_cast<std::int64_t>(std::floor(p.x() / tolerance)),
                static_cast<std::int64_t>(std::floor(p.y() / tolerance)),
                static_cast<std::int64_t>(std::floor(p.z() / tolerance))};
  };
  for (Eigen::Index v = 0; v < nv; ++v) {
    const Vec3 p = mesh.vertices.col(v);
    const Cell c = cell_of(p);
    int found = -1;
    for (std::int64_t dx = -1; dx <= 1 && found < 0; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && found < 0; ++dy)
        for (std::int64_t dz = -1; dz <= 1 && found < 0; ++dz) {
          const auto it = kept_in.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == kept_in.end()) continue;
          for (const int k : it->second)
            if ((mesh.vertices.col(kept[static_cast<size_t>(k)]) - p).norm() <= tolerance) {
              found = k;
              break;
            }
        }
    if (found < 0) {
      found = static_cast<int>(kept.size());
      kept.push_back(static_cast<int>(v));
      kept_in[c].push_back(found);
    }
    target[static_cast<size_t>(v)] = found;
  }
  if (kept.size() == static_cast<size_t>(nv)) return mesh;
  TriangleMesh out;
  out.vertices.resize(3, static_cast<Eigen::Index>(kept.size()));
  for (size_t k = 0; k < kept.size(); ++k)
    out.vertices.col(static_cast<Eigen::Index>(k)) = mesh.vertices.col(kept[k]);
  std::vector<Eigen::Vector3i> faces;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) {
    const Eigen::Vector3i t(target[static_cast<size_t>(mesh.faces(0, f))],
                            target[static_cast<size_t>(mesh.faces(1, f))],
                            target[static_cast<size_t>(mesh.faces(2, f))]);
    if (t(0) != t(1) && t(1) != t(2) && t(0) != t(2)) faces.push_back(t);
  }
  out.faces.resize(3, static_cast<Eigen::Index>(faces.size()));
  for (size_t i = 0; i < faces.size(); ++i) out.faces.col(static_cast<Eigen::Index>(i)) = faces[i];
  return out;
}

}  // namespace cablefit::internal
