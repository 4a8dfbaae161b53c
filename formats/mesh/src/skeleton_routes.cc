#include "skeleton_routes.h"

#include <algorithm>
#include <functional>
#include <map>
#include <utility>
#include <limits>
#include <numeric>

namespace cablefit {

std::vector<TriangleMesh> ConnectedComponents(const TriangleMesh& mesh) {
  // Faces are connected through shared edges, not vertices: nested closed shells whose caps
  // were fanned from the same axis point (a coax drawn as concentric tubes) share that one
  // vertex once welded, and are still separate surfaces.
  const int nf = static_cast<int>(mesh.faces.cols());
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int f) { return parent[f] == f ? f : parent[f] = find(parent[f]); };
  std::map<std::pair<int, int>, int> first_face_of_edge;
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces(k, f), b = mesh.faces((k + 1) % 3, f);
      const auto [it, inserted] = first_face_of_edge.emplace(std::make_pair(std::min(a, b), std::max(a, b)), f);
      if (!inserted) parent[find(f)] = find(it->second);
    }
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
