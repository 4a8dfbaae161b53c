// Checks of a NetworkSpec that a single rod does not need: junction degrees, one connected
// tree, and whether every branch can reach its supports.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "cablefit/core/base/distinct_numbers.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/network/network_model.h"
#include "network_parts.h"

namespace cablefit {
namespace {

std::string Num(double v) { return MessageNumber(v); }

int Find(std::vector<int>& root, int i) {
  while (root[i] != i) i = root[i] = root[root[i]];
  return i;
}

// A support or a junction as a point of the network, for path lengths between supports.
struct NetworkPoint {
  int branch = -1;
  double s = 0.0;
  std::string label;
};

std::string SupportLabel(const NetworkSpec& spec, int b, const SupportSpec& sp) {
  return BranchLabel(spec, b) + " " + ToString(sp.kind) + " at s=" + Num(sp.s);
}

// Every pair of position supports must be reachable: their distance at most the cable between.
// Extensible branches (EA > 0) a little shorter than a span are stretched across it (solved,
// with the tension that takes), up to kMaxAxialStrain when every branch is extensible.
void CheckReach(const NetworkSpec& spec) {
  const bool extensible =
      std::all_of(spec.branches.begin(), spec.branches.end(),
                  [](const BranchSpec& b) { return b.material.axial_stiffness > 0; });
  const double stretch = extensible ? kMaxAxialStrain : 1e-9;
  const int nb = static_cast<int>(spec.branches.size());
  const int nj = static_cast<int>(spec.junctions.size());
  std::vector<NetworkPoint> points(nj);  // junctions first
  std::vector<std::vector<std::pair<int, double>>> adj(nj);
  std::vector<int> fixed;
  for (int b = 0; b < nb; ++b) {
    const BranchSpec& br = spec.branches[b];
    std::vector<std::pair<double, int>> along;  // (s, point)
    if (br.start_junction >= 0) along.emplace_back(0.0, br.start_junction);
    if (br.end_junction >= 0) along.emplace_back(br.length, br.end_junction);
    for (const SupportSpec& sp : br.supports) {
      points.push_back({b, sp.s, SupportLabel(spec, b, sp)});
      adj.emplace_back();
      along.emplace_back(sp.s, static_cast<int>(points.size()) - 1);
      if (!sp.sliding) fixed.push_back(static_cast<int>(points.size()) - 1);
    }
    std::sort(along.begin(), along.end());
    for (size_t k = 0; k + 1 < along.size(); ++k) {
      const double d = along[k + 1].first - along[k].first;
      adj[along[k].second].emplace_back(along[k + 1].second, d);
      adj[along[k + 1].second].emplace_back(along[k].second, d);
    }
  }
  auto position = [&](int p) {
    const NetworkPoint& pt = points[p];
    for (const SupportSpec& sp : spec.branches[pt.branch].supports)
      if (sp.s == pt.s) return sp.position;
    return Vec3(Vec3::Zero());
  };
  const double total = TotalLength(spec);
  for (size_t a = 0; a < fixed.size(); ++a) {
    // Path lengths from this support through the tree (a tree: the first visit is the path).
    std::vector<double> dist(points.size(), -1.0);
    std::vector<int> stack = {fixed[a]};
    dist[fixed[a]] = 0.0;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      for (const auto& [q, d] : adj[p])
        if (dist[q] < 0) {
          dist[q] = dist[p] + d;
          stack.push_back(q);
        }
    }
    for (size_t k = a + 1; k < fixed.size(); ++k) {
      const int p = fixed[a], q = fixed[k];
      if (points[p].branch == points[q].branch) continue;  // checked per branch
      const double gap = (position(p) - position(q)).norm();
      if (dist[q] >= 0 && gap > dist[q] * (1 + stretch) + 1e-12 * total) {
        const auto [gap_text, dist_text] = DistinctNumbers(gap, dist[q]);
        throw InvalidInput(points[p].label + " and " + points[q].label + " are " + gap_text +
                           " m apart but only " + dist_text +
                           " m of cable joins them: a branch between them is too short");
      }
    }
  }
}

}  // namespace

std::string BranchLabel(const NetworkSpec& spec, int b) {
  const std::string& name = spec.branches[b].name;
  return "branch '" + (name.empty() ? std::to_string(b) : name) + "'";
}

std::string JunctionLabel(const NetworkSpec& spec, int j) {
  const std::string& name = spec.junctions[j].name;
  return "junction '" + (name.empty() ? std::to_string(j) : name) + "'";
}

double TotalLength(const NetworkSpec& spec) {
  double total = 0.0;
  for (const BranchSpec& b : spec.branches) total += b.length;
  return total;
}

RodSpec BranchRodSpec(const NetworkSpec& spec, int b) {
  const BranchSpec& br = spec.branches[b];
  RodSpec rs;
  rs.name = br.name;
  rs.length = br.length;
  rs.material = br.material;
  rs.sleeves = br.sleeves;
  rs.gravity = spec.gravity;
  rs.supports = br.supports;
  rs.natural_curvature = br.natural_curvature;
  rs.point_loads = br.point_loads;
  return rs;
}

void ValidateNetworkSpec(const NetworkSpec& spec) {
  const int nb = static_cast<int>(spec.branches.size());
  const int nj = static_cast<int>(spec.junctions.size());
  if (nb == 0) throw InvalidInput("the network has no branch");
  if (!spec.gravity.allFinite()) throw InvalidInput("gravity is not finite");
  std::vector<int> degree(nj, 0);
  std::vector<int> first_branch(nj, -1);
  for (int b = 0; b < nb; ++b) {
    const BranchSpec& br = spec.branches[b];
    try {
      ValidateRodSpec(BranchRodSpec(spec, b), false);
    } catch (const InvalidInput& e) {
      throw InvalidInput(BranchLabel(spec, b) + ": " + e.what());
    }
    if (br.route.size() < 2) throw InvalidInput(BranchLabel(spec, b) + " has no drawn route");
    if (!br.route.points.allFinite())
      throw InvalidInput(BranchLabel(spec, b) + ": drawn route is not finite");
    for (int j : {br.start_junction, br.end_junction}) {
      if (j < -1 || j >= nj)
        throw InvalidInput(BranchLabel(spec, b) + " refers to junction " + std::to_string(j) +
                           " but there are " + std::to_string(nj));
      if (j < 0) continue;
      ++degree[j];
      if (first_branch[j] < 0) first_branch[j] = b;
    }
    if (br.start_junction >= 0 && br.start_junction == br.end_junction)
      throw InvalidInput(BranchLabel(spec, b) + " starts and ends at " +
                         JunctionLabel(spec, br.start_junction) + ": a closed loop");
    const double tol = 1e-9 * br.length;
    for (const SupportSpec& sp : br.supports)
      if ((br.start_junction >= 0 && sp.s <= tol) || (br.end_junction >= 0 && sp.s >= br.length - tol))
        throw InvalidInput(BranchLabel(spec, b) + ": a " + ToString(sp.kind) +
                           " at its junction end; support the junction a little way along a branch");
  }
  for (int j = 0; j < nj; ++j) {
    const JunctionSpec& jn = spec.junctions[j];
    if (!std::isfinite(jn.compliance) || jn.compliance < 0)
      throw InvalidInput(JunctionLabel(spec, j) + ": compliance must be a finite number >= 0");
    if (!std::isfinite(jn.mass) || jn.mass < 0)
      throw InvalidInput(JunctionLabel(spec, j) + ": mass must be a finite number >= 0");
    if (degree[j] == 0) throw InvalidInput(JunctionLabel(spec, j) + " joins no branch");
    if (degree[j] == 1)
      throw InvalidInput(JunctionLabel(spec, j) + " joins only " + BranchLabel(spec, first_branch[j]) +
                         ": a junction needs two or more branches");
  }
  // One tree: branches and junctions as graph nodes, attachments as edges.
  std::vector<int> root(nb + nj);
  std::iota(root.begin(), root.end(), 0);
  for (int b = 0; b < nb; ++b)
    for (int j : {spec.branches[b].start_junction, spec.branches[b].end_junction}) {
      if (j < 0) continue;
      const int rb = Find(root, b), rj = Find(root, nb + j);
      if (rb == rj)
        throw InvalidInput(BranchLabel(spec, b) + " closes a loop through " + JunctionLabel(spec, j) +
                           ": networks must be trees");
      root[rb] = rj;
    }
  for (int b = 1; b < nb; ++b)
    if (Find(root, b) != Find(root, 0))
      throw InvalidInput(BranchLabel(spec, b) + " is not connected to " + BranchLabel(spec, 0) +
                         ": the network falls into disconnected pieces");
  bool fixed = false;
  for (const BranchSpec& br : spec.branches)
    for (const SupportSpec& sp : br.supports) fixed |= !sp.sliding;
  if (!fixed)
    throw InvalidInput("no support fixes the network in space (every support slides or there is none)");
  for (size_t k = 0; k < spec.obstacles.size(); ++k) {
    const TriangleMesh& m = spec.obstacles[k].mesh;
    if (!m.vertices.allFinite())
      throw InvalidInput("obstacle '" + spec.obstacles[k].name + "' has non-finite vertices");
    if (m.faces.size() > 0 && (m.faces.minCoeff() < 0 || m.faces.maxCoeff() >= m.vertices.cols()))
      throw InvalidInput("obstacle '" + spec.obstacles[k].name + "' has faces with invalid vertex indices");
  }
  CheckReach(spec);
}

}  // namespace cablefit
