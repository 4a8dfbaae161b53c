#include "cablefit/app/bench/bench_harness.h"

#include <cmath>

#include "cablefit/app/relax/relax_cable.h"

namespace cablefit::addin {
namespace {

// The material relax gives a bundle it knows only the diameter of (EA included: its supports
// are then compliant rows, as in a relax).
MaterialSpec Bundle(double diameter) { return DefaultBundleMaterial(diameter, 0.0); }

// A straight branch from a to b drawn drooping by 1.5 % of each clip interval between its clips
// (clips at interval ends except at junction ends); returns the route and sets the clips.
BranchSpec Branch(const std::string& name, const Vec3& a, const Vec3& b, double diameter,
                  int clips, bool clamp_start, bool clamp_end) {
  BranchSpec br;
  br.name = name;
  br.material = Bundle(diameter);
  const double chord = (b - a).norm();
  const int intervals = clips + 1;
  const int per = 24;
  Polyline route;
  route.points.resize(3, intervals * per + 1);
  for (int i = 0; i <= intervals * per; ++i) {
    const double u = static_cast<double>(i) / (intervals * per);
    const double local = std::fmod(u * intervals, 1.0);
    const double droop = 0.015 * chord / intervals * std::sin(M_PI * local);
    route.points.col(i) = a + u * (b - a) - droop * Vec3::UnitZ();
  }
  route.ParameteriseByChords();
  br.route = route;
  br.length = route.s[route.s.size() - 1];
  auto support_at = [&](int i, SupportKind kind) {
    SupportSpec sp;
    sp.kind = kind;
    sp.s = route.s[i];
    sp.position = route.points.col(i);
    const int j = std::min(i + 1, static_cast<int>(route.points.cols()) - 1);
    sp.tangent = route.points.col(j) - route.points.col(j == i ? i - 1 : i);
    sp.normal = Vec3::UnitZ();
    return sp;
  };
  if (clamp_start) br.supports.push_back(support_at(0, SupportKind::kClamp));
  for (int k = 1; k <= clips; ++k) br.supports.push_back(support_at(k * per, SupportKind::kClip));
  if (clamp_end) br.supports.push_back(support_at(intervals * per, SupportKind::kClamp));
  return br;
}

int ClipsAlong(const Vec3& a, const Vec3& b, double clip_spacing) {
  return std::max(1, static_cast<int>(std::lround((b - a).norm() / clip_spacing)));
}

// Park-Miller minimal standard generator: fully specified, so the harness is the same on every
// platform and standard library (std:: distributions are not).
struct Lcg {
  unsigned long long state = 20261203;
  int Next(int n) {
    state = state * 48271 % 2147483647;
    return static_cast<int>(state % static_cast<unsigned long long>(n));
  }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Next(1000001) / 1000000.0; }
};

}  // namespace

TriangleMesh FlatPanel(const Vec3& lo, const Vec3& hi, int nx, int ny) {
  TriangleMesh m;
  m.vertices.resize(3, (nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.vertices.col(j * (nx + 1) + i) =
          Vec3(lo.x() + (hi.x() - lo.x()) * i / nx, lo.y() + (hi.y() - lo.y()) * j / ny, lo.z());
  m.faces.resize(3, 2 * nx * ny);
  int f = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      m.faces.col(f++) = Eigen::Vector3i(a, b, d);
      m.faces.col(f++) = Eigen::Vector3i(a, d, c);
    }
  return m;
}

double NetworkLength(const NetworkSpec& spec) {
  double total = 0.0;
  for (const BranchSpec& b : spec.branches) total += b.length;
  return total;
}

NetworkSpec SyntheticHarness(const SyntheticHarnessSize& size) {
  NetworkSpec spec;
  spec.name = "synthetic-harness";
  const int segments = size.trunk_segments;
  const double seg = 0.6;
  auto add_junction = [&](const std::string& name) {
    spec.junctions.push_back({name, 0.0, 0.005});
    return static_cast<int>(spec.junctions.size()) - 1;
  };
  std::vector<int> trunk_junction(segments + 1, -1);
  for (int i = 1; i < segments; ++i) trunk_junction[i] = add_junction("breakout " + std::to_string(i));
  for (int i = 0; i < segments; ++i) {
    BranchSpec t = Branch("trunk " + std::to_string(i), Vec3(seg * i, 0, 0), Vec3(seg * (i + 1), 0, 0),
                          0.010, ClipsAlong(Vec3(seg * i, 0, 0), Vec3(seg * (i + 1), 0, 0), size.clip_spacing), i == 0, i == segments - 1);
    t.start_junction = trunk_junction[i];
    t.end_junction = trunk_junction[i + 1];
    spec.branches.push_back(t);
  }
  for (int i = 1; i < segments; ++i) {
    const double side = i % 2 ? 1.0 : -1.0;
    const Vec3 root(seg * i, 0, 0);
    const Vec3 dir = Vec3(0.5, side * std::sqrt(3.0) / 2, 0);
    const Vec3 tip = root + 0.8 * dir;
    const bool splits = i % 2 == 1;  // every other side branch splits again
    BranchSpec s = Branch("side " + std::to_string(i), root, tip, 0.006,
                          ClipsAlong(root, tip, size.clip_spacing), false, !splits);
    s.start_junction = trunk_junction[i];
    if (splits) {
      const int j = add_junction("split " + std::to_string(i));
      s.end_junction = j;
      const int ways = i == 1 ? 3 : 2;
      for (int w = 0; w < ways; ++w) {
        const double angle = (ways == 3 ? (w - 1) * 0.6 : (w ? 0.5 : -0.5));
        const Vec3 d = Eigen::AngleAxisd(angle, Vec3::UnitZ()) * dir;
        BranchSpec leaf = Branch("side " + std::to_string(i) + "." + std::to_string(w), tip, tip + 0.4 * d,
                                 0.004, ClipsAlong(tip, tip + 0.4 * d, size.clip_spacing), false, true);
        leaf.start_junction = j;
        spec.branches.push_back(leaf);
      }
    }
    spec.branches.push_back(s);
  }
  return spec;
}

NetworkSpec KblSizedHarness(const KblSizedHarnessSize& size) {
  NetworkSpec spec;
  spec.name = "kbl-sized-harness";
  const int nodes = size.segments + 1;
  Lcg rng;
  std::vector<int> parent(nodes, -1), degree(nodes, 0);
  std::vector<Vec3> position(nodes, Vec3::Zero()), heading(nodes, Vec3::UnitX());
  for (int i = 1; i < nodes; ++i) {
    // Mostly a chain (KBL splits a bundle at every protection end and fixing: many splices),
    // else a branch off an earlier node with room for one (breakouts of 3-4 segments).
    int p = i - 1;
    if (rng.Next(100) >= size.chain_percent) {
      for (int tries = 0; tries < 8; ++tries) {
        const int q = rng.Next(i);
        if (degree[q] < 4) {
          p = q;
          break;
        }
      }
    }
    parent[i] = p;
    ++degree[p];
    ++degree[i];
    const double turn = rng.Uniform(-1.0, 1.0);  // [rad]
    Vec3 dir = Eigen::AngleAxisd(turn, Vec3::UnitZ()) * heading[p];
    dir.z() = rng.Uniform(-0.1, 0.1);
    heading[i] = dir.normalized();
    position[i] = position[p] + rng.Uniform(size.min_length, size.max_length) * heading[i];
  }
  std::vector<int> junction(nodes, -1);
  for (int n = 0; n < nodes; ++n) {
    if (degree[n] < 2) continue;
    spec.junctions.push_back({"node " + std::to_string(n), 0.0, 0.002});
    junction[n] = static_cast<int>(spec.junctions.size()) - 1;
  }
  const int fixing_every = std::max(1, size.segments / std::max(1, size.fixings));
  int fixings = 0;
  for (int i = 1; i < nodes; ++i) {
    const int p = parent[i];
    const bool fixed = fixings < size.fixings && i % fixing_every == 0;
    fixings += fixed;
    BranchSpec b = Branch("segment " + std::to_string(i), position[p], position[i],
                          rng.Uniform(0.003, 0.012), fixed ? 1 : 0, junction[p] < 0,
                          junction[i] < 0);
    b.start_junction = junction[p];
    b.end_junction = junction[i];
    b.length *= 1 + size.length_change;
    for (SupportSpec& sp : b.supports) sp.s *= 1 + size.length_change;
    spec.branches.push_back(b);
  }
  return spec;
}

}  // namespace cablefit::addin
