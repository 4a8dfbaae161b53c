#include "skeleton_routes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace cablefit {

namespace {

// Pairs the faces around an edge shared by more than two (`faces`, all using the edge a-b): each
// face joins the face across the wedge of solid it bounds. Touching solids meshed one by one and
// welded leave such edges where their rims' tessellations agree (a coax's jacket, dielectric and
// conductor, each closed): around the edge, every solid is the wedge between one face whose
// outward normal turns one way and the next face, whose normal turns the other. Returns the
// pairs, or nothing when the faces do not alternate so (then they all join, as before).
std::vector<std::pair<int, int>> WedgePairs(const TriangleMesh& mesh, int a, int b,
                                            const std::vector<int>& faces) {
  const Vec3 pa = mesh.vertices.col(a);
  const Vec3 e = (mesh.vertices.col(b) - pa).normalized();
  const Vec3 u = e.unitOrthogonal(), v = e.cross(u);
  struct Around {
    double angle;  // [rad] of the face's direction away from the edge, about e
    bool closes;   // its outward normal turns towards increasing angle: solid lies before it
    int face;
  };
  std::vector<Around> around;
  for (const int f : faces) {
    int c = -1;
    for (int k = 0; k < 3; ++k)
      if (mesh.faces(k, f) != a && mesh.faces(k, f) != b) c = mesh.faces(k, f);
    const Vec3 x0 = mesh.vertices.col(mesh.faces(0, f)), x1 = mesh.vertices.col(mesh.faces(1, f)),
               x2 = mesh.vertices.col(mesh.faces(2, f));
    const Vec3 normal = (x1 - x0).cross(x2 - x0);
    Vec3 d = mesh.vertices.col(c) - pa;
    d -= d.dot(e) * e;
    if (!(d.norm() > 0) || !(normal.norm() > 0)) return {};
    around.push_back({std::atan2(d.dot(v), d.dot(u)), normal.dot(e.cross(d)) > 0, f});
  }
  std::sort(around.begin(), around.end(),
            [](const Around& x, const Around& y) { return x.angle < y.angle; });
  // Faces within kSameDirection of one direction are two solids touching along one surface: their
  // own tessellations of it cross each other (by 2 degrees where a 16-gon meets a 20-gon, 7.5
  // where an 8-gon meets a 12-gon). The one that closes its solid comes first, so that each
  // solid's wedge lies between neighbours. The runs of such faces are found from a gap wider than
  // that, as the directions go round.
  constexpr double kSameDirection = 0.15;  // [rad], 8.6 degrees: no solid of a cable is that thin
  const size_t n = around.size();
  size_t start = 0;
  for (size_t i = 0; i < n; ++i) {
    const double gap = i + 1 < n ? around[i + 1].angle - around[i].angle
                                 : around[0].angle + 2 * M_PI - around[i].angle;
    if (gap > kSameDirection) {
      start = (i + 1) % n;
      break;
    }
  }
  std::rotate(around.begin(), around.begin() + static_cast<std::ptrdiff_t>(start), around.end());
  for (size_t i = 0; i < n;) {
    size_t j = i + 1;
    while (j < n && std::abs(std::remainder(around[j].angle - around[j - 1].angle, 2 * M_PI)) <=
                        kSameDirection)
      ++j;
    std::stable_partition(around.begin() + static_cast<std::ptrdiff_t>(i),
                          around.begin() + static_cast<std::ptrdiff_t>(j),
                          [](const Around& x) { return x.closes; });
    i = j;
  }
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < n; ++i) {
    if (around[i].closes) continue;
    const Around& next = around[(i + 1) % n];
    if (!next.closes) return {};
    pairs.emplace_back(around[i].face, next.face);
  }
  if (2 * pairs.size() != n) return {};
  return pairs;
}

}  // namespace

std::vector<TriangleMesh> ConnectedComponents(const TriangleMesh& mesh) {
  // Faces are connected through shared edges, not vertices: nested closed shells whose caps
  // were fanned from the same axis point (a coax drawn as concentric tubes) share that one
  // vertex once welded, and are still separate surfaces. Around an edge of more than two faces,
  // each face joins the one across the solid it bounds (WedgePairs).
  const int nf = static_cast<int>(mesh.faces.cols());
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int f) { return parent[f] == f ? f : parent[f] = find(parent[f]); };
  std::map<std::pair<int, int>, std::vector<int>> faces_of_edge;
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces(k, f), b = mesh.faces((k + 1) % 3, f);
      faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  for (const auto& [edge, faces] : faces_of_edge) {
    std::vector<std::pair<int, int>> pairs;
    if (faces.size() > 2) pairs = WedgePairs(mesh, edge.first, edge.second, faces);
    if (!pairs.empty()) {
      for (const auto& [f, g] : pairs) parent[find(f)] = find(g);
      continue;
    }
    for (size_t k = 1; k < faces.size(); ++k) parent[find(faces[k])] = find(faces[0]);
  }
  std::vector<int> component_of_root(nf, -1);
  std::vector<std::vector<int>> component_faces;
  for (int f = 0; f < nf; ++f) {
    const int root = find(f);
    if (component_of_root[root] < 0) {
      component_of_root[root] = static_cast<int>(component_faces.size());
      component_faces.emplace_back();
    }
    component_faces[component_of_root[root]].push_back(f);
  }
  // A vertex may belong to several components: each gets its own copy.
  std::vector<std::vector<int>> component_vertices(component_faces.size());
  std::vector<std::vector<int>> local_faces(component_faces.size());
  std::vector<int> local(mesh.vertices.cols(), -1);
  for (size_t c = 0; c < component_faces.size(); ++c) {
    for (const int f : component_faces[c])
      for (int k = 0; k < 3; ++k) {
        const int v = mesh.faces(k, f);
        if (local[v] < 0) {
          local[v] = static_cast<int>(component_vertices[c].size());
          component_vertices[c].push_back(v);
        }
        local_faces[c].push_back(local[v]);
      }
    for (const int v : component_vertices[c]) local[v] = -1;
  }
  std::vector<TriangleMesh> result(component_faces.size());
  for (size_t c = 0; c < result.size(); ++c) {
    TriangleMesh& m = result[c];
    m.vertices.resize(3, static_cast<Eigen::Index>(component_vertices[c].size()));
    for (size_t i = 0; i < component_vertices[c].size(); ++i) {
      m.vertices.col(static_cast<Eigen::Index>(i)) = mesh.vertices.col(component_vertices[c][i]);
    }
    m.faces.resize(3, static_cast<Eigen::Index>(component_faces[c].size()));
    for (size_t i = 0; i < component_faces[c].size(); ++i) {
      for (int k = 0; k < 3; ++k) m.faces(k, static_cast<Eigen::Index>(i)) = local_faces[c][3 * i + k];
    }
  }
  return result;
}

std::vector<SkeletonRoute> SplitSkeleton(const CurveSkeleton& skeleton, double min_spur) {
  const int n = static_cast<int>(skeleton.nodes.cols());
  std::vector<std::vector<int>> adjacent(n);
  for (const auto& [a, b] : skeleton.edges) {
    if (a == b) continue;
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  std::vector<bool> removed(n, false);
  auto degree = [&](int v) {
    int d = 0;
    for (int w : adjacent[v]) d += removed[w] ? 0 : 1;
    return d;
  };
  auto next_on_path = [&](int previous, int v) {
    for (int w : adjacent[v]) {
      if (!removed[w] && w != previous) return w;
    }
    return -1;
  };
  // Spurs: side branches that mean-curvature flow leaves at bumps and caps, short, or running
  // beside the axis inside the body (a single 1 m tube came back as three cables around a 41 mm
  // spur of that kind). A spur's reach is how far its free end gets from the rest of the
  // skeleton. One spur is removed at a time, the one that reaches least, so that of a true end
  // and an artefact running beside it the artefact goes (the true end reaches out to the cap).
  for (;;) {
    double weakest = std::numeric_limits<double>::infinity();
    std::vector<int> weakest_path;
    for (int v = 0; v < n; ++v) {
      if (removed[v] || degree(v) != 1) continue;
      std::vector<int> path{v};
      double length = 0;
      int previous = -1, current = v;
      while (true) {
        const int next = next_on_path(previous, current);
        if (next < 0) break;
        length += (skeleton.nodes.col(next) - skeleton.nodes.col(current)).norm();
        previous = current;
        current = next;
        if (degree(current) != 2) break;
        path.push_back(current);
      }
      if (degree(current) < 3) continue;
      std::vector<bool> on_spur(n, false);
      for (int p : path) on_spur[p] = true;
      double reach = std::numeric_limits<double>::infinity();
      for (int w = 0; w < n; ++w) {
        if (removed[w] || on_spur[w]) continue;
        reach = std::min(reach, (skeleton.nodes.col(w) - skeleton.nodes.col(v)).norm());
      }
      const double strength = std::min(length, reach);
      if (strength < min_spur && strength < weakest) {
        weakest = strength;
        weakest_path = path;
      }
    }
    if (weakest_path.empty()) break;
    for (int p : weakest_path) removed[p] = true;
  }
  std::vector<SkeletonRoute> routes;
  std::vector<std::vector<bool>> used(n);
  for (int v = 0; v < n; ++v) used[v].assign(adjacent[v].size(), false);
  auto mark = [&](int a, int b) {
    for (size_t i = 0; i < adjacent[a].size(); ++i) if (adjacent[a][i] == b) used[a][i] = true;
    for (size_t i = 0; i < adjacent[b].size(); ++i) if (adjacent[b][i] == a) used[b][i] = true;
  };
  auto walk = [&](int start, size_t first) {
    SkeletonRoute route;
    route.nodes = {start};
    route.start_is_end = degree(start) == 1;
    int previous = start, current = adjacent[start][first];
    mark(previous, current);
    while (true) {
      route.nodes.push_back(current);
      if (degree(current) != 2 || current == start) break;
      int next = -1;
      for (size_t i = 0; i < adjacent[current].size(); ++i) {
        const int w = adjacent[current][i];
        if (!removed[w] && w != previous && !used[current][i]) next = w;
      }
      if (next < 0) break;
      mark(current, next);
      previous = current;
      current = next;
    }
    route.finish_is_end = degree(route.nodes.back()) == 1;
    return route;
  };
  for (int pass = 0; pass < 2; ++pass) {  // pass 0: from ends and branch points; 1: cycles
    for (int v = 0; v < n; ++v) {
      if (removed[v] || (pass == 0 && degree(v) == 2)) continue;
      for (size_t i = 0; i < adjacent[v].size(); ++i) {
        if (!removed[adjacent[v][i]] && !used[v][i]) routes.push_back(walk(v, i));
      }
    }
  }
  return routes;
}

}  // namespace cablefit
