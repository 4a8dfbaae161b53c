#include "harness_effects.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace cablefit::internal {
namespace {

// The end of branch b attached to junction j, and the unit tangent there pointing away from
// the junction into the branch, on the solved shape.
struct JunctionEnd {
  int branch = -1;
  bool at_start = true;
  Vec3 away = Vec3::UnitX();
};

std::vector<JunctionEnd> EndsAt(const NetworkSpec& spec, const NetworkSolution& sol, int j) {
  std::vector<JunctionEnd> ends;
  for (size_t b = 0; b < spec.branches.size(); ++b) {
    const Polyline& c = sol.branches[b];
    if (c.size() < 2) continue;
    if (spec.branches[b].start_junction == j)
      ends.push_back({static_cast<int>(b), true, (c.points.col(1) - c.points.col(0)).normalized()});
    if (spec.branches[b].end_junction == j) {
      const int n = c.size();
      ends.push_back({static_cast<int>(b), false, (c.points.col(n - 2) - c.points.col(n - 1)).normalized()});
    }
  }
  return ends;
}

// Moves everything placed along branch `b` by `ds` [m] of arc length (supports, loads, spans):
// what is fixed in space or on the bundle stays where it is when the branch's start moves.
void ShiftAlong(BranchSpec* b, double ds) {
  for (SupportSpec& sp : b->supports) sp.s += ds;
  for (PointLoadSpec& pl : b->point_loads) pl.s += ds;
  for (NaturalCurvatureSpec& nc : b->natural_curvature) {
    nc.s_start += ds;
    nc.s_end += ds;
  }
  for (SleeveSpec& sl : b->sleeves) {
    sl.s_begin += ds;
    sl.s_end += ds;
  }
}

// Tangent of the solved branch at arc length s (unit).
Vec3 TangentAt(const Polyline& c, double s) {
  Eigen::Index i = 1;
  while (i + 1 < c.size() && c.s[i] < s) ++i;
  return (c.points.col(i) - c.points.col(i - 1)).normalized();
}

// Two unit vectors across `t`, the first as near "up" (against gravity) as `t` allows.
std::pair<Vec3, Vec3> Across(const Vec3& t, const Vec3& gravity) {
  Vec3 up = gravity.norm() > 0 ? Vec3(-gravity.normalized()) : Vec3::UnitZ();
  up -= up.dot(t) * t;
  if (up.norm() < 1e-6) up = t.unitOrthogonal();
  up.normalize();
  return {up, t.cross(up)};
}

std::string Name(const NetworkSpec& spec, int branch) {
  const std::string& n = spec.branches[static_cast<size_t>(branch)].name;
  return n.empty() ? "branch " + std::to_string(branch) : n;
}

HarnessEffectModel JunctionPosition(const NetworkSpec& nominal, const NetworkSolution& sol, int j) {
  HarnessEffectModel m;
  const std::vector<JunctionEnd> ends = EndsAt(nominal, sol, j);
  if (ends.size() < 2) return m;
  // The trunk: the two ends that leave the junction most nearly opposite each other.
  size_t a = 0, b = 1;
  double straightest = 2.0;
  for (size_t p = 0; p < ends.size(); ++p)
    for (size_t q = p + 1; q < ends.size(); ++q) {
      const double c = ends[p].away.dot(ends[q].away);
      if (c < straightest) {
        straightest = c;
        a = p;
        b = q;
      }
    }
  const JunctionEnd ea = ends[a], eb = ends[b];
  if (ea.branch == eb.branch) return m;
  const double la = nominal.branches[static_cast<size_t>(ea.branch)].length;
  const double lb = nominal.branches[static_cast<size_t>(eb.branch)].length;
  m.effect = HarnessEffect::kJunctionPosition;
  m.junction = j;
  m.branch = -1;
  m.x0 = Eigen::VectorXd::Zero(1);  // d [m]: the junction moved this far into branch b's side
  m.scale = Eigen::VectorXd::Constant(1, 0.02 * std::min(la, lb));
  m.amplitudes = {0};
  // Moving the junction by d towards b: a gains d, b loses d; a branch whose start is at the
  // junction keeps everything it carries where it is by shifting it along.
  auto limited = [=](double d) { return std::clamp(d, -0.8 * la, 0.8 * lb); };
  m.change = [=](const Eigen::VectorXd& x, NetworkSpec* s) {
    const double d = limited(x[0]);
    BranchSpec& ba = s->branches[static_cast<size_t>(ea.branch)];
    BranchSpec& bb = s->branches[static_cast<size_t>(eb.branch)];
    ba.length += d;
    if (ea.at_start) ShiftAlong(&ba, d);
    bb.length -= d;
    if (eb.at_start) ShiftAlong(&bb, -d);
    if (!ea.at_start && !ba.supports.empty() && ba.supports.back().s > ba.length) ba.supports.back().s = ba.length;
    if (!eb.at_start && !bb.supports.empty() && bb.supports.back().s > bb.length) bb.supports.back().s = bb.length;
  };
  const std::string name_a = Name(nominal, ea.branch), name_b = Name(nominal, eb.branch);
  const std::string junction = nominal.junctions[static_cast<size_t>(j)].name;
  m.describe = [=](const Eigen::VectorXd& x) {
    HarnessFoundEffect f;
    f.effect = HarnessEffect::kJunctionPosition;
    f.junction = j;
    const double d = limited(x[0]);
    // Stated on the branch it moved into, from the junction's nominal place.
    f.branch = d >= 0 ? eb.branch : ea.branch;
    const bool start = d >= 0 ? eb.at_start : ea.at_start;
    const double l = d >= 0 ? lb : la;
    const double moved = std::abs(d);
    f.interval = start ? std::make_pair(0.0, moved) : std::make_pair(l - moved, l);
    f.parameters["shift"] = d;
    f.parameters["shift_along_trunk"] = moved;
    f.units = {{"shift", "m"}, {"shift_along_trunk", "m"}};
    return f;
  };
  m.label = "junction_position at " + junction + " (" + name_a + " / " + name_b + ")";
  return m;
}

HarnessEffectModel JunctionCompliance(const NetworkSpec& nominal, const NetworkSolution& sol, int j) {
  HarnessEffectModel m;
  m.effect = HarnessEffect::kJunctionCompliance;
  m.junction = j;
  // c = c0 x (x >= 0): x = 1 turns the branches by ~0.05 rad under the nominal junction moments.
  double moment = 0.0;
  if (static_cast<size_t>(j) < sol.junctions.size())
    for (const Vec3& mo : sol.junctions[static_cast<size_t>(j)].moment) moment = std::max(moment, mo.norm());
  const double c0 = 0.05 / std::max(moment, 1e-4);
  m.x0 = Eigen::VectorXd::Zero(1);
  m.scale = Eigen::VectorXd::Constant(1, 1.0);
  m.amplitudes = {0};
  m.change = [=](const Eigen::VectorXd& x, NetworkSpec* s) {
    s->junctions[static_cast<size_t>(j)].compliance += c0 * std::max(x[0], 0.0);
  };
  m.describe = [=](const Eigen::VectorXd& x) {
    HarnessFoundEffect f;
    f.effect = HarnessEffect::kJunctionCompliance;
    f.junction = j;
    f.parameters["compliance"] = c0 * std::max(x[0], 0.0);
    f.units = {{"compliance", "rad/(N m)"}};
    return f;
  };
  m.label = "junction_compliance at " + nominal.junctions[static_cast<size_t>(j)].name;
  return m;
}

HarnessEffectModel ClipPosition(const NetworkSpec& nominal, int b, int k) {
  HarnessEffectModel m;
  const BranchSpec& br = nominal.branches[static_cast<size_t>(b)];
  const double s0 = br.supports[static_cast<size_t>(k)].s;
  // Between its neighbours (or the ends): the clip cannot pass another support.
  const double lo = k > 0 ? br.supports[static_cast<size_t>(k - 1)].s : 0.0;
  const double hi = k + 1 < static_cast<int>(br.supports.size()) ? br.supports[static_cast<size_t>(k + 1)].s : br.length;
  m.effect = HarnessEffect::kClipPosition;
  m.branch = b;
  m.support = k;
  m.x0 = Eigen::VectorXd::Zero(1);  // ds [m]
  m.scale = Eigen::VectorXd::Constant(1, 0.01 * br.length);
  m.amplitudes = {0};
  auto at = [=](double ds) { return std::clamp(s0 + ds, lo + 0.2 * (s0 - lo), hi - 0.2 * (hi - s0)); };
  m.change = [=](const Eigen::VectorXd& x, NetworkSpec* s) {
    s->branches[static_cast<size_t>(b)].supports[static_cast<size_t>(k)].s = at(x[0]);
  };
  m.describe = [=](const Eigen::VectorXd& x) {
    HarnessFoundEffect f;
    f.effect = HarnessEffect::kClipPosition;
    f.branch = b;
    f.support = k;
    const double s = at(x[0]);
    f.interval = std::make_pair(std::min(s, s0), std::max(s, s0));
    f.parameters["shift"] = s - s0;
    f.parameters["s"] = s;
    f.units = {{"shift", "m"}, {"s", "m"}};
    return f;
  };
  m.label = "clip_position at " + Name(nominal, b) + " support " + std::to_string(k);
  return m;
}

HarnessEffectModel ClipOrientation(const NetworkSpec& nominal, int b, int k) {
  HarnessEffectModel m;
  const SupportSpec& sp = nominal.branches[static_cast<size_t>(b)].supports[static_cast<size_t>(k)];
  const Frame frame = Frame::FromTangentNormal(sp.tangent, sp.normal);
  m.effect = HarnessEffect::kClipOrientation;
  m.branch = b;
  m.support = k;
  m.x0 = Eigen::VectorXd::Zero(2);  // rotation about d1, about d2 [rad]
  m.scale = Eigen::VectorXd::Constant(2, 0.05);
  m.amplitudes = {0, 1};
  auto rotation = [=](const Eigen::VectorXd& x) {
    const Vec3 axis = x[0] * frame.d1 + x[1] * frame.d2;
    const double angle = axis.norm();
    return angle > 0 ? Eigen::AngleAxisd(angle, axis / angle).toRotationMatrix() : Mat3::Identity();
  };
  m.change = [=](const Eigen::VectorXd& x, NetworkSpec* s) {
    SupportSpec& t = s->branches[static_cast<size_t>(b)].supports[static_cast<size_t>(k)];
    const Mat3 r = rotation(x);
    t.tangent = r * frame.d3;
    t.normal = r * frame.d1;
  };
  const double s_at = sp.s;
  m.describe = [=](const Eigen::VectorXd& x) {
    HarnessFoundEffect f;
    f.effect = HarnessEffect::kClipOrientation;
    f.branch = b;
    f.support = k;
    f.interval = std::make_pair(s_at, s_at);
    f.parameters["angle"] = std::hypot(x[0], x[1]);
    f.parameters["axis_angle"] = std::atan2(x[1], x[0]);
    f.units = {{"angle", "rad"}, {"axis_angle", "rad"}};
    return f;
  };
  m.label = "clip_orientation at " + Name(nominal, b) + " support " + std::to_string(k);
  return m;
}

// Stiffness or density of one branch scaled by exp(x).
HarnessEffectModel BranchScale(const NetworkSpec& nominal, int b, HarnessEffect effect) {
  HarnessEffectModel m;
  m.effect = effect;
  m.branch = b;
  m.x0 = Eigen::VectorXd::Zero(1);
  m.scale = Eigen::VectorXd::Constant(1, 0.3);
  m.amplitudes = {0};
  const bool stiffness = effect == HarnessEffect::kBranchStiffness;
  m.change = [=](const Eigen::VectorXd& x, NetworkSpec* s) {
    MaterialSpec& mat = s->branches[static_cast<size_t>(b)].material;
    const double f = std::exp(std::clamp(x[0], -4.0, 4.0));
    if (stiffness) {
      mat.bending_stiffness *= f;
      mat.torsional_stiffness *= f;
    } else {
      mat.linear_density *= f;
    }
  };
  const double length = nominal.branches[static_cast<size_t>(b)].length;
  m.describe = [=](const Eigen::VectorXd& x) {
    HarnessFoundEffect f;
    f.effect = effect;
    f.branch = b;
    f.interval = std::make_pair(0.0, length);
    f.parameters["factor"] = std::exp(std::clamp(x[0], -4.0, 4.0));
    f.units = {{"factor", "-"}};
    return f;
  };
  m.label = std::string(ToString(effect)) + " at " + Name(nominal, b);
  return m;
}

// The span [centre - w/2, centre + w/2] of a curvature set, kept on the branch and at least a
// hundredth of it wide.
std::pair<double, double> Span(double centre, double width, double length) {
  const double w = std::max(std::abs(width), 0.01 * length);
  const double c = std::clamp(centre, 0.0, length);
  return {std::max(0.0, c - 0.5 * w), std::min(length, c + 0.5 * w)};
}

HarnessEffectModel BranchCurvature(const NetworkSpec& nominal, int b, double where) {
  HarnessEffectModel m;
  const double L = nominal.branches[static_cast<size_t>(b)].length;
  m.effect = HarnessEffect::kBranchCurvature;
  m.branch = b;
  m.x0.resize(4);
  m.x0 << std::clamp(where, 0.0, L), L / 3, 0.0, 0.0;  // centre, width [m], kappa1, kappa2 [1/m]
  m.scale.resize(4);
  m.scale << 0.02 * L, 0.02 * L, 1.0, 1.0;
  m.amplitudes = {2, 3};
  m.change = [=](const Eigen::VectorXd& x, NetworkSpec* s) {
    NaturalCurvatureSpec nc;
    std::tie(nc.s_start, nc.s_end) = Span(x[0], x[1], L);
    nc.ramp = 0.2 * (nc.s_end - nc.s_start);
    nc.kappa = Vec3(x[2], x[3], 0.0);
    s->branches[static_cast<size_t>(b)].natural_curvature.push_back(nc);
  };
  m.describe = [=](const Eigen::VectorXd& x) {
    HarnessFoundEffect f;
    f.effect = HarnessEffect::kBranchCurvature;
    f.branch = b;
    f.interval = Span(x[0], x[1], L);
    const double kappa = std::hypot(x[2], x[3]);
    f.parameters["curvature"] = kappa;
    f.parameters["direction"] = std::atan2(x[3], x[2]);
    f.parameters["total_bend_angle"] = kappa * (f.interval->second - f.interval->first);
    f.units = {{"curvature", "1/m"}, {"direction", "rad"}, {"total_bend_angle", "rad"}};
    return f;
  };
  m.label = "branch_curvature at " + Name(nominal, b);
  return m;
}

HarnessEffectModel SupportContact(const NetworkSpec& nominal, const NetworkSolution& sol, int b,
                                  double where) {
  HarnessEffectModel m;
  const BranchSpec& br = nominal.branches[static_cast<size_t>(b)];
  const double L = br.length;
  const double weight = br.material.linear_density * nominal.gravity.norm() * L;
  m.effect = HarnessEffect::kSupportContact;
  m.branch = b;
  m.x0.resize(3);
  m.x0 << std::clamp(where, 0.0, L), 0.0, 0.0;  // s [m], push across the cable [N] (up, side)
  m.scale.resize(3);
  m.scale << 0.02 * L, 0.05 * std::max(weight, 1e-3), 0.05 * std::max(weight, 1e-3);
  m.amplitudes = {1, 2};
  const Polyline shape = sol.branches[static_cast<size_t>(b)];
  const Vec3 gravity = nominal.gravity;
  auto push = [=](const Eigen::VectorXd& x) {
    const auto [up, side] = Across(TangentAt(shape, std::clamp(x[0], 0.0, L)), gravity);
    return Vec3(x[1] * up + x[2] * side);
  };
  m.change = [=](const Eigen::VectorXd& x, NetworkSpec* s) {
    s->branches[static_cast<size_t>(b)].point_loads.push_back({std::clamp(x[0], 0.0, L), push(x)});
  };
  m.describe = [=](const Eigen::VectorXd& x) {
    HarnessFoundEffect f;
    f.effect = HarnessEffect::kSupportContact;
    f.branch = b;
    const double s = std::clamp(x[0], 0.0, L);
    f.interval = std::make_pair(s, s);
    const Vec3 force = push(x);
    f.parameters["s"] = s;
    f.parameters["force"] = force.norm();
    f.parameters["force_x"] = force.x();
    f.parameters["force_y"] = force.y();
    f.parameters["force_z"] = force.z();
    f.units = {{"s", "m"}, {"force", "N"}, {"force_x", "N"}, {"force_y", "N"}, {"force_z", "N"}};
    return f;
  };
  m.label = "support_contact at " + Name(nominal, b);
  return m;
}

}  // namespace


std::vector<HarnessEffectModel> BuildHarnessEffectModels(const NetworkSpec& nominal,
                                                         const NetworkSolution& solution,
                                                         const MismatchHints& hints) {
  std::vector<HarnessEffectModel> out;
  for (size_t j = 0; j < nominal.junctions.size(); ++j) {
    HarnessEffectModel p = JunctionPosition(nominal, solution, static_cast<int>(j));
    if (p.effect != HarnessEffect::kNone) out.push_back(p);
    out.push_back(JunctionCompliance(nominal, solution, static_cast<int>(j)));
  }
  for (size_t b = 0; b < nominal.branches.size(); ++b) {
    const BranchSpec& br = nominal.branches[b];
    const int bi = static_cast<int>(b);
    for (size_t k = 0; k < br.supports.size(); ++k) {
      const SupportSpec& sp = br.supports[k];
      const bool inside = sp.s > 1e-9 && sp.s < br.length - 1e-9;
      if (inside) out.push_back(ClipPosition(nominal, bi, static_cast<int>(k)));
      if (sp.kind != SupportKind::kPin) out.push_back(ClipOrientation(nominal, bi, static_cast<int>(k)));
    }
    out.push_back(BranchScale(nominal, bi, HarnessEffect::kBranchStiffness));
    out.push_back(BranchScale(nominal, bi, HarnessEffect::kBranchDensity));
    const double where = b < hints.max_s.size() ? hints.max_s[b] : 0.5 * br.length;
    out.push_back(BranchCurvature(nominal, bi, where));
    out.push_back(SupportContact(nominal, solution, bi, where));
  }
  return out;
}

HarnessEffectModel CombineHarnessModels(const HarnessEffectModel& a, const HarnessEffectModel& b) {
  HarnessEffectModel m;
  m.effect = a.effect;
  const int na = static_cast<int>(a.x0.size()), nb = static_cast<int>(b.x0.size());
  m.x0.resize(na + nb);
  m.x0 << a.x0, b.x0;
  m.scale.resize(na + nb);
  m.scale << a.scale, b.scale;
  m.amplitudes = a.amplitudes;
  for (int i : b.amplitudes) m.amplitudes.push_back(na + i);
  m.change = [a, b, na, nb](const Eigen::VectorXd& x, NetworkSpec* s) {
    a.change(x.head(na), s);
    b.change(x.segment(na, nb), s);
  };
  m.label = a.label + " + " + b.label;
  m.parts = {a, b};
  m.offsets = {0, na};
  return m;
}

std::vector<HarnessFoundEffect> DescribeEffects(const HarnessEffectModel& model,
                                                const Eigen::VectorXd& x) {
  if (model.parts.empty()) return {model.describe(x)};
  std::vector<HarnessFoundEffect> out;
  for (size_t k = 0; k < model.parts.size(); ++k) {
    const HarnessEffectModel& p = model.parts[k];
    out.push_back(p.describe(x.segment(model.offsets[k], p.x0.size())));
  }
  return out;
}

}  // namespace cablefit::internal
