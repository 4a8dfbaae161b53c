// The drawn shape of a network as frames: what the breakout angles are measured from and what
// the solver starts from.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "cablefit/core/rod/initial_shape.h"
#include "network_parts.h"
#include "cablefit/core/base/internal/quaternion.h"

namespace cablefit {
namespace {

// Rotates `d1` to stay perpendicular to the new tangent by the smallest rotation (parallel
// transport from tangent t0 to t1).
Vec3 Transport(const Vec3& d1, const Vec3& t0, const Vec3& t1) {
  const Vec3 axis = t0.cross(t1);
  const double s = axis.norm(), c = t0.dot(t1);
  if (s < 1e-14) return d1;
  const Vec3 k = axis / s;
  const double angle = std::atan2(s, c);
  const Vec3 v = d1 * std::cos(angle) + k.cross(d1) * std::sin(angle) + k * k.dot(d1) * (1 - std::cos(angle));
  return (v - v.dot(t1) * t1).normalized();
}

// Signed angle about t that turns a onto b (both perpendicular to t).
double AngleAbout(const Vec3& t, const Vec3& a, const Vec3& b) {
  return std::atan2(t.dot(a.cross(b)), a.dot(b));
}

// Twist offsets along a branch so its drawn frames agree with the normals of its clamps: the
// first clamp's mismatch everywhere, each further clamp's spread linearly from the previous one
// (the drawing carries no twist, so none is invented beyond what the clamps impose).
std::vector<double> ClampTwist(const BranchSpec& br, const std::vector<double>& mid_s,
                               const std::vector<Vec3>& t, const std::vector<Vec3>& d1) {
  std::vector<std::pair<double, double>> fix;  // (s, angle)
  for (const SupportSpec& sp : br.supports) {
    if (sp.kind != SupportKind::kClamp) continue;
    size_t k = 0;
    while (k + 1 < mid_s.size() && std::abs(mid_s[k + 1] - sp.s) < std::abs(mid_s[k] - sp.s)) ++k;
    const Vec3 n = sp.normal - sp.normal.dot(t[k]) * t[k];
    if (n.norm() < 1e-9 * sp.normal.norm()) continue;
    double angle = AngleAbout(t[k], d1[k], n.normalized());
    if (!fix.empty())  // unwrap relative to the previous clamp
      angle = fix.back().second + std::remainder(angle - fix.back().second, 2 * M_PI);
    fix.emplace_back(sp.s, angle);
  }
  std::vector<double> twist(mid_s.size(), 0.0);
  if (fix.empty()) return twist;
  for (size_t k = 0; k < mid_s.size(); ++k) {
    const double s = mid_s[k];
    if (s <= fix.front().first) {
      twist[k] = fix.front().second;
    } else if (s >= fix.back().first) {
      twist[k] = fix.back().second;
    } else {
      size_t i = 0;
      while (fix[i + 1].first < s) ++i;
      const double w = (s - fix[i].first) / (fix[i + 1].first - fix[i].first);
      twist[k] = (1 - w) * fix[i].second + w * fix[i + 1].second;
    }
  }
  return twist;
}

}  // namespace

std::vector<Eigen::Vector4d> DrawnFrames(const NetworkModel& net,
                                         const std::vector<Polyline>* routes,
                                         const std::vector<Eigen::Matrix3Xd>* normals) {
  const RodModel& m = net.rod;
  std::vector<Eigen::Vector4d> q(m.items.size(), Eigen::Vector4d(1, 0, 0, 0));
  for (size_t b = 0; b < net.branches.size(); ++b) {
    const BranchSpec& br = net.spec.branches[b];
    const internal::BranchLayout& lay = net.branches[b];
    const Polyline route = ReparameteriseToLength(routes ? (*routes)[b] : br.route, br.length);
    const size_t ne = lay.elements.size();
    // A start from a coarser solution (a level's, on longer elements) is followed as a smooth
    // curve; its own chords would kink at every coarse node.
    const bool from_coarser = routes && static_cast<size_t>(route.size()) < ne + 1;
    auto at = [&](double s) { return from_coarser ? SmoothPointAt(route, s) : PointAt(route, s); };
    std::vector<Vec3> t(ne), d1(ne);
    std::vector<double> mid_s(ne);
    for (size_t k = 0; k < ne; ++k) {
      const Vec3 chord = at(lay.node_s[k + 1]) - at(lay.node_s[k]);
      t[k] = chord.norm() > 0 ? Vec3(chord.normalized()) : (k > 0 ? t[k - 1] : Vec3::UnitX());
      d1[k] = k == 0 ? Vec3(t[k].unitOrthogonal()) : Transport(d1[k - 1], t[k - 1], t[k]);
      mid_s[k] = 0.5 * (lay.node_s[k] + lay.node_s[k + 1]);
    }
    std::vector<double> twist = ClampTwist(br, mid_s, t, d1);
    const Eigen::Matrix3Xd* given = nullptr;  // 3 x (start's elements)
    if (routes && normals && normals->size() == net.branches.size() &&
        (*normals)[b].cols() == (*routes)[b].size() - 1 && (*normals)[b].cols() > 0)
      given = &(*normals)[b];
    if (given) {
      // The start's normals, linear in s between its element midpoints, turned onto each
      // element's tangent: the twist angle from the transported d1 (unwrapped along the branch).
      const Polyline& from = (*routes)[b];
      const double scale = br.length / std::max(1e-300, from.s[from.size() - 1] - from.s[0]);
      const int nf = static_cast<int>(given->cols());
      int j = 0;
      for (size_t k = 0; k < ne; ++k) {
        auto mid = [&](int i) { return 0.5 * (from.s[i] + from.s[i + 1] - 2 * from.s[0]) * scale; };
        while (j + 1 < nf && mid(j + 1) < mid_s[k]) ++j;
        Vec3 n = given->col(j);
        if (j + 1 < nf && mid_s[k] > mid(j)) {
          const double w = std::clamp((mid_s[k] - mid(j)) / std::max(1e-300, mid(j + 1) - mid(j)), 0.0, 1.0);
          n = (1 - w) * given->col(j) + w * given->col(j + 1);
        }
        n -= n.dot(t[k]) * t[k];
        if (n.norm() < 1e-6) continue;  // keep the drawn twist here
        double angle = AngleAbout(t[k], d1[k], n.normalized());
        if (k > 0) angle = twist[k - 1] + std::remainder(angle - twist[k - 1], 2 * M_PI);
        twist[k] = angle;
      }
    }
    for (size_t k = 0; k < ne; ++k) {
      const Vec3 n = Eigen::AngleAxisd(twist[k], t[k]) * d1[k];
      Eigen::Matrix3d r;
      r.col(0) = n;
      r.col(1) = t[k].cross(n);
      r.col(2) = t[k];
      q[m.element_item[lay.elements[k]]] = internal::quat::FromMatrix(r);
    }
  }
  // Support frames follow their neighbouring element; a breakout its first branch's end.
  for (size_t i = 0; i < m.items.size(); ++i) {
    const RodItem& it = m.items[i];
    if (it.is_element || it.junction >= 0) continue;
    const int b = net.support_branch[it.support];
    const internal::BranchLayout& lay = net.branches[b];
    const double s = it.s;
    size_t k = 0;
    while (k + 1 < lay.elements.size() && lay.node_s[k + 1] <= s) ++k;
    q[i] = q[m.element_item[lay.elements[k]]];
  }
  for (const internal::JunctionLayout& jl : net.junctions) {
    if (jl.item < 0) continue;
    const internal::BranchLayout& lay = net.branches[jl.branches[0]];
    const int element = jl.branch_end[0] == 0 ? lay.elements.front() : lay.elements.back();
    q[jl.item] = q[m.element_item[element]];
  }
  return q;
}

}  // namespace cablefit
