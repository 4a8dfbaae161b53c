#include "hollow_tubes.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace cablefit::internal {
namespace {

// Two faces meeting at more than this angle between their normals are a sharp edge: the rim of a
// hose's end (90 degrees), not the facets of its wall (30 degrees for 12 sides).
constexpr double kSharpCosine = 0.5;
// A region whose face normals all lie within this of their mean is flat (an end annulus).
constexpr double kFlatCosine = 0.999;

using Edge = std::pair<int, int>;

Edge Undirected(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

Vec3 FaceNormal(const TriangleMesh& m, Eigen::Index f) {
  const Vec3 a = m.vertices.col(m.faces(0, f)), b = m.vertices.col(m.faces(1, f)),
             c = m.vertices.col(m.faces(2, f));
  const Vec3 n = (b - a).cross(c - a);
  return n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
}

}  // namespace

int EulerCharacteristic(const TriangleMesh& mesh) {
  std::set<Edge> edges;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f)
    for (int k = 0; k < 3; ++k) edges.insert(Undirected(mesh.faces(k, f), mesh.faces((k + 1) % 3, f)));
  return static_cast<int>(mesh.vertices.cols()) - static_cast<int>(edges.size()) +
         static_cast<int>(mesh.faces.cols());
}

namespace {

using FacesOfEdge = std::map<Edge, std::vector<int>>;

// The faces of region `r` (`region` per face) closed by a fan over each of its boundary loops,
// oriented like the mesh; nullopt unless the region has exactly two simple boundary loops.
std::optional<TriangleMesh> CappedRegion(const TriangleMesh& mesh, const FacesOfEdge& faces_of,
                                         const std::vector<int>& region, int r) {
  std::vector<int> faces;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f)
    if (region[static_cast<size_t>(f)] == r) faces.push_back(static_cast<int>(f));
  // Boundary edges in the region's own direction, chained into loops.
  std::map<int, int> next;
  for (int f : faces) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces(k, f), b = mesh.faces((k + 1) % 3, f);
      const auto& pair = faces_of.at(Undirected(a, b));
      const int g = pair[0] == f ? pair[1] : pair[0];
      if (region[static_cast<size_t>(g)] == r) continue;
      if (next.count(a)) return std::nullopt;  // a boundary that touches itself: no simple loops
      next[a] = b;
    }
  }
  std::vector<std::vector<int>> loops;
  std::set<int> used;
  for (const auto& entry : next) {
    const int start = entry.first;
    if (used.count(start)) continue;
    std::vector<int> loop;
    int v = start;
    while (!used.count(v)) {
      const auto it = next.find(v);
      if (it == next.end()) return std::nullopt;
      used.insert(v);
      loop.push_back(v);
      v = it->second;
    }
    if (v != start) return std::nullopt;  // ran into another loop: not two simple rims
    loops.push_back(std::move(loop));
  }
  if (loops.size() != 2) return std::nullopt;
  // The region's vertices, renumbered, then a centre vertex per loop with a fan that runs each
  // boundary edge the other way (so the cap is oriented like the wall).
  std::map<int, int> local;
  for (int f : faces)
    for (int k = 0; k < 3; ++k) local.emplace(mesh.faces(k, f), static_cast<int>(local.size()));
  TriangleMesh wall;
  const int nv = static_cast<int>(local.size());
  wall.vertices.resize(3, nv + 2);
  for (const auto& [global, index] : local) wall.vertices.col(index) = mesh.vertices.col(global);
  int cap_faces = 0;
  for (const auto& loop : loops) cap_faces += static_cast<int>(loop.size());
  wall.faces.resize(3, static_cast<Eigen::Index>(faces.size()) + cap_faces);
  Eigen::Index row = 0;
  for (int f : faces)
    wall.faces.col(row++) << local[mesh.faces(0, f)], local[mesh.faces(1, f)],
        local[mesh.faces(2, f)];
  for (size_t l = 0; l < loops.size(); ++l) {
    const int centre = nv + static_cast<int>(l);
    Vec3 c = Vec3::Zero();
    for (int v : loops[l]) c += mesh.vertices.col(v);
    wall.vertices.col(centre) = c / static_cast<double>(loops[l].size());
    for (int a : loops[l]) wall.faces.col(row++) << local[next[a]], local[a], centre;
  }
  return wall;
}

// The bore of a hollow tube whose rims are rounded (lips with no sharp edge): the faces where the
// surface is concave, bent towards its outward normal as a bore is, while the outer wall and the
// lips around the ends are convex. Per vertex the umbrella Laplacian (mean of its neighbours minus
// itself) along the vertex normal: below zero where convex. A face is concave when all its
// vertices are. Returns region 0 for the concave faces, 1 for the others.
std::vector<int> ConcaveRegions(const TriangleMesh& mesh, const FacesOfEdge& faces_of) {
  const Eigen::Index nv = mesh.vertices.cols();
  Eigen::Matrix3Xd normal = Eigen::Matrix3Xd::Zero(3, nv);  // area-weighted, outward
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) {
    const Vec3 a = mesh.vertices.col(mesh.faces(0, f)), b = mesh.vertices.col(mesh.faces(1, f)),
               c = mesh.vertices.col(mesh.faces(2, f));
    const Vec3 n = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) normal.col(mesh.faces(k, f)) += n;
  }
  Eigen::Matrix3Xd sum = Eigen::Matrix3Xd::Zero(3, nv);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(nv);
  for (const auto& [edge, faces] : faces_of) {
    sum.col(edge.first) += mesh.vertices.col(edge.second);
    sum.col(edge.second) += mesh.vertices.col(edge.first);
    count(edge.first) += 1;
    count(edge.second) += 1;
  }
  std::vector<char> concave(static_cast<size_t>(nv), 0);
  for (Eigen::Index v = 0; v < nv; ++v)
    concave[static_cast<size_t>(v)] =
        count(v) > 0 && (sum.col(v) / count(v) - mesh.vertices.col(v)).dot(normal.col(v)) > 0;
  std::vector<int> region(static_cast<size_t>(mesh.faces.cols()), 1);
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f)
    if (concave[static_cast<size_t>(mesh.faces(0, f))] &&
        concave[static_cast<size_t>(mesh.faces(1, f))] &&
        concave[static_cast<size_t>(mesh.faces(2, f))])
      region[static_cast<size_t>(f)] = 0;
  return region;
}

}  // namespace

std::vector<TriangleMesh> CappedWalls(const TriangleMesh& mesh) {
  const Eigen::Index nf = mesh.faces.cols();
  std::map<Edge, std::vector<int>> faces_of;
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      faces_of[Undirected(mesh.faces(k, f), mesh.faces((k + 1) % 3, f))].push_back(static_cast<int>(f));
  for (const auto& [edge, faces] : faces_of)
    if (faces.size() != 2) return {};
  std::vector<Vec3> normal(static_cast<size_t>(nf));
  for (Eigen::Index f = 0; f < nf; ++f) normal[static_cast<size_t>(f)] = FaceNormal(mesh, f);
  // Regions: faces joined across edges that are not sharp.
  std::vector<int> region(static_cast<size_t>(nf), -1);
  int regions = 0;
  for (Eigen::Index seed = 0; seed < nf; ++seed) {
    if (region[static_cast<size_t>(seed)] >= 0) continue;
    std::vector<int> stack = {static_cast<int>(seed)};
    region[static_cast<size_t>(seed)] = regions;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const auto& pair = faces_of[Undirected(mesh.faces(k, f), mesh.faces((k + 1) % 3, f))];
        const int g = pair[0] == f ? pair[1] : pair[0];
        if (region[static_cast<size_t>(g)] >= 0 || normal[f].dot(normal[g]) < kSharpCosine) continue;
        region[static_cast<size_t>(g)] = regions;
        stack.push_back(g);
      }
    }
    ++regions;
  }
  std::vector<TriangleMesh> walls;
  for (int r = 0; r < regions; ++r) {
    Vec3 mean = Vec3::Zero();
    for (Eigen::Index f = 0; f < nf; ++f)
      if (region[static_cast<size_t>(f)] == r) mean += normal[static_cast<size_t>(f)];
    if (mean.norm() > 0) {
      mean.normalize();
      bool flat = true;
      for (Eigen::Index f = 0; f < nf && flat; ++f)
        flat = region[static_cast<size_t>(f)] != r ||
               normal[static_cast<size_t>(f)].dot(mean) > kFlatCosine;
      if (flat) continue;
    }
    if (std::optional<TriangleMesh> wall = CappedRegion(mesh, faces_of, region, r))
      walls.push_back(std::move(*wall));
  }
  if (walls.size() == 2) return walls;
  // No sharp rims: rounded lips. The concave faces are the bore, the convex ones the outer wall
  // with the lips, each with the two loops where they meet.
  const std::vector<int> concave = ConcaveRegions(mesh, faces_of);
  walls.clear();
  for (int r = 0; r < 2; ++r)
    if (std::optional<TriangleMesh> wall = CappedRegion(mesh, faces_of, concave, r))
      walls.push_back(std::move(*wall));
  if (walls.size() != 2) walls.clear();
  return walls;
}

}  // namespace cablefit::internal
