// Branched harnesses on a bench for the harness diagnosis tests and corpus: a Y breakout, a
// trunk with three breakouts and clips, an X (a trunk into three branches, one clipped), and a
// Y whose branch lies on a support plate. Each
// drawn a little slack between its clamps (so that it hangs), its sizes and materials varied
// by a seed.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cablefit/core/network/network_spec.h"

namespace cablefit::testing {

/// A branch drawn from `a` to `b` through its chord's midpoint lowered by `sag` [m], `slack`
/// longer than that drawing, its ends free (the caller attaches them).
inline BranchSpec DrawnBranch(const std::string& name, const Vec3& a, const Vec3& b, double sag,
                              double slack, const MaterialSpec& m) {
  BranchSpec br;
  br.name = name;
  br.material = m;
  const int n = 17;
  br.route.points.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1);
    br.route.points.col(i) = (1 - t) * a + t * b - Vec3(0, 0, 4 * sag * t * (1 - t));
  }
  br.route.ParameteriseByChords();
  br.length = br.route.s[n - 1] * (1 + slack);
  return br;
}

/// A clamp (or clip) at arc length s of `br` holding it along its drawn route there.
inline SupportSpec HoldAt(const BranchSpec& br, double s, SupportKind kind = SupportKind::kClamp) {
  const Polyline& r = br.route;
  const double f = s / br.length * r.s[r.size() - 1];
  Eigen::Index i = 1;
  while (i + 1 < r.size() && r.s[i] < f) ++i;
  const double w = (f - r.s[i - 1]) / (r.s[i] - r.s[i - 1]);
  SupportSpec sp;
  sp.kind = kind;
  sp.s = s;
  sp.position = (1 - w) * r.points.col(i - 1) + w * r.points.col(i);
  sp.tangent = (r.points.col(i) - r.points.col(i - 1)).normalized();
  Vec3 up = Vec3::UnitZ() - sp.tangent.z() * sp.tangent;
  sp.normal = up.norm() > 1e-6 ? Vec3(up.normalized()) : sp.tangent.unitOrthogonal();
  return sp;
}

inline MaterialSpec BundleMaterial(double ei, double density, double diameter) {
  MaterialSpec m;
  m.bending_stiffness = ei;
  m.torsional_stiffness = ei / 1.3;
  m.linear_density = density;
  m.diameter = diameter;
  return m;
}

/// A solid box [lo, hi] beside the harness (a support plate).
struct HarnessBox {
  std::string name;
  Vec3 lo, hi;
};

struct HarnessLayout {
  std::string name;
  NetworkSpec spec;
  std::vector<HarnessBox> boxes;  // also in spec.obstacles, in this order
};

/// The four bench layouts, sizes and materials drawn from `rng` (variation of about +-20 %).
inline std::vector<HarnessLayout> HarnessLayouts(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.8, 1.2);
  const Vec3 origin(0, 0, 0.6);
  auto bundle = [&](double scale) {
    return BundleMaterial(0.02 * scale * u(rng), 0.08 * scale * u(rng), 0.006 + 0.004 * scale);
  };
  std::vector<HarnessLayout> out;
  {  // Y: a trunk from a clamp to a breakout, two branches on to their clamps.
    NetworkSpec s;
    s.name = "y";
    const double l = 0.35 * u(rng);
    const Vec3 j = origin + Vec3(l, 0.0, -0.03);
    BranchSpec trunk = DrawnBranch("trunk", origin, j, 0.01, 0.02, bundle(1.5));
    trunk.supports.push_back(HoldAt(trunk, 0.0));
    trunk.end_junction = 0;
    BranchSpec a = DrawnBranch("branch_a", j, j + Vec3(0.35 * u(rng), 0.2 * u(rng), 0.04), 0.02, 0.03, bundle(1.0));
    a.supports.push_back(HoldAt(a, a.length));
    a.start_junction = 0;
    BranchSpec b = DrawnBranch("branch_b", j, j + Vec3(0.4 * u(rng), -0.22 * u(rng), -0.02), 0.02, 0.03, bundle(0.8));
    b.supports.push_back(HoldAt(b, b.length));
    b.start_junction = 0;
    s.branches = {trunk, a, b};
    s.junctions = {{"breakout", 0.0, 0.005}};
    out.push_back({"y", s, {}});
  }
  {  // A trunk clamped at both ends with three breakouts and a clip between each pair.
    NetworkSpec s;
    s.name = "trunk3";
    const double step = 0.3 * u(rng);
    Vec3 at = origin;
    for (int k = 0; k < 4; ++k) {
      const Vec3 next = origin + Vec3(step * (k + 1), 0.0, -0.01 * k);
      BranchSpec t = DrawnBranch("trunk_" + std::to_string(k), at, next, 0.01, 0.02, bundle(1.6));
      if (k == 0) t.supports.push_back(HoldAt(t, 0.0));
      if (k == 1 || k == 2) t.supports.push_back(HoldAt(t, 0.5 * t.length, SupportKind::kClip));
      if (k == 3) t.supports.push_back(HoldAt(t, t.length));
      if (k > 0) t.start_junction = k - 1;
      if (k < 3) t.end_junction = k;
      s.branches.push_back(t);
      at = next;
    }
    for (int k = 0; k < 3; ++k) {
      const Vec3 j = origin + Vec3(step * (k + 1), 0.0, -0.01 * k);
      const double side = k % 2 ? -1.0 : 1.0;
      BranchSpec b = DrawnBranch("breakout_" + std::to_string(k), j,
                                 j + Vec3(0.05 * u(rng), side * 0.25 * u(rng), -0.05), 0.02, 0.03, bundle(0.8));
      b.supports.push_back(HoldAt(b, b.length));
      b.start_junction = k;
      s.branches.push_back(b);
      s.junctions.push_back({"junction_" + std::to_string(k), 0.0, 0.004});
    }
    out.push_back({"trunk3", s, {}});
  }
  {  // X: a trunk into a breakout of three branches, one of them held by a clip on its way.
    NetworkSpec s;
    s.name = "x";
    const Vec3 j = origin + Vec3(0.3 * u(rng), 0.02, -0.02);
    BranchSpec trunk = DrawnBranch("trunk", origin, j, 0.01, 0.02, bundle(1.6));
    trunk.supports.push_back(HoldAt(trunk, 0.0));
    trunk.end_junction = 0;
    s.branches.push_back(trunk);
    const Vec3 ends[3] = {j + Vec3(0.3 * u(rng), 0.25 * u(rng), 0.03), j + Vec3(0.4 * u(rng), 0.0, -0.04),
                          j + Vec3(0.25 * u(rng), -0.3 * u(rng), 0.0)};
    for (int k = 0; k < 3; ++k) {
      BranchSpec b = DrawnBranch("leg_" + std::to_string(k), j, ends[k], 0.02, 0.03, bundle(0.9));
      if (k == 1) b.supports.push_back(HoldAt(b, 0.5 * b.length, SupportKind::kClip));
      b.supports.push_back(HoldAt(b, b.length));
      b.start_junction = 0;
      s.branches.push_back(b);
    }
    s.junctions = {{"breakout", 0.0, 0.006}};
    out.push_back({"x", s, {}});
  }
  {  // A Y whose longer branch sags onto a plate under it.
    NetworkSpec s = out.front().spec;
    s.name = "plate";
    BranchSpec& b = s.branches[2];
    const Vec3 a0 = b.route.points.col(0), a1 = b.route.points.rightCols<1>();
    b.length = b.route.s[b.route.size() - 1] * 1.04;  // more slack: it reaches the plate
    b.supports.back().s = b.length;
    const Vec3 mid = 0.5 * (a0 + a1);
    const double top = mid.z() - 0.035;
    const double w = 0.12;
    const HarnessBox plate{"plate", Vec3(mid.x() - w, mid.y() - w, top - 0.01), Vec3(mid.x() + w, mid.y() + w, top)};
    s.obstacles.push_back({plate.name, BoxMesh(plate.lo, plate.hi)});
    out.push_back({"plate", s, {plate}});
  }
  return out;
}

}  // namespace cablefit::testing
