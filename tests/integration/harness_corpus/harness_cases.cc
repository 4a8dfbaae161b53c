#include "harness_cases.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/solver/centerline_sampling.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/formats/ply_reader.h"
#include "synthetic_tube_scan.h"

namespace cablefit::testing {
namespace {

using json::Json;

Json Vector(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

NetworkSolution Solve(const NetworkSpec& spec) {
  double total = 0.0;
  for (const BranchSpec& b : spec.branches) total += b.length;
  NetworkOptions opt;
  opt.element_length = total / 1200.0;
  return SolveNetwork(spec, opt);
}

// Unit direction leaving junction j along branch b's drawn route.
Vec3 Leaving(const BranchSpec& b, bool at_start) {
  const Polyline& r = b.route;
  const int n = r.size();
  return at_start ? Vec3((r.points.col(1) - r.points.col(0)).normalized())
                  : Vec3((r.points.col(n - 2) - r.points.col(n - 1)).normalized());
}

}  // namespace

const std::vector<std::string>& HarnessCorpusEffects() {
  static const std::vector<std::string> effects = {
      "junction_position", "junction_compliance", "clip_position",   "clip_orientation",
      "branch_stiffness",  "branch_density",      "branch_curvature", "support_contact"};
  return effects;
}

HiddenHarnessEffect HideHarnessEffect(const std::string& effect, const HarnessLayout& layout,
                                      std::mt19937& rng, NetworkSpec* truth) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const NetworkSpec& nominal = layout.spec;
  NetworkSpec& t = *truth;
  HiddenHarnessEffect h;
  h.effect = effect;
  auto pick = [&](int n) { return std::min(n - 1, static_cast<int>(u(rng) * n)); };
  const int nb = static_cast<int>(nominal.branches.size());
  if (effect == "junction_position") {
    h.junction = pick(static_cast<int>(nominal.junctions.size()));
    struct End {
      int branch;
      bool at_start;
    };
    std::vector<End> ends;
    for (int b = 0; b < nb; ++b) {
      if (nominal.branches[static_cast<size_t>(b)].start_junction == h.junction) ends.push_back({b, true});
      if (nominal.branches[static_cast<size_t>(b)].end_junction == h.junction) ends.push_back({b, false});
    }
    size_t a = 0, c = 1;
    double straightest = 2.0;
    for (size_t p = 0; p < ends.size(); ++p)
      for (size_t q = p + 1; q < ends.size(); ++q) {
        const double dot = Leaving(nominal.branches[static_cast<size_t>(ends[p].branch)], ends[p].at_start)
                               .dot(Leaving(nominal.branches[static_cast<size_t>(ends[q].branch)], ends[q].at_start));
        if (dot < straightest) {
          straightest = dot;
          a = p;
          c = q;
        }
      }
    // The branch that gets shorter must keep slack: a third of what it has at most.
    auto slack = [&](const End& e) {
      const BranchSpec& b = nominal.branches[static_cast<size_t>(e.branch)];
      return b.length - (b.route.points.rightCols<1>() - b.route.points.col(0)).norm();
    };
    const double sign = u(rng) < 0.5 ? -1.0 : 1.0;
    const double room = 0.33 * slack(sign > 0 ? ends[c] : ends[a]);
    const double d = sign * std::min(0.01 + 0.02 * u(rng), room);
    BranchSpec& ba = t.branches[static_cast<size_t>(ends[a].branch)];
    BranchSpec& bc = t.branches[static_cast<size_t>(ends[c].branch)];
    ba.length += d;
    if (ends[a].at_start) for (SupportSpec& sp : ba.supports) sp.s += d;
    bc.length -= d;
    if (ends[c].at_start) for (SupportSpec& sp : bc.supports) sp.s -= d;
    if (!ends[a].at_start && !ba.supports.empty() && ba.supports.back().s > ba.length - 1e-9) ba.supports.back().s = ba.length;
    if (!ends[c].at_start && !bc.supports.empty()) {
      for (SupportSpec& sp : bc.supports) sp.s = std::min(sp.s, bc.length);
    }
  } else if (effect == "junction_compliance") {
    h.junction = pick(static_cast<int>(nominal.junctions.size()));
    const NetworkSolution sol = Solve(nominal);
    double moment = 0.0;
    for (const Vec3& m : sol.junctions[static_cast<size_t>(h.junction)].moment) moment = std::max(moment, m.norm());
    t.junctions[static_cast<size_t>(h.junction)].compliance = (0.08 + 0.07 * u(rng)) / std::max(moment, 1e-4);
  } else if (effect == "clip_position" || effect == "clip_orientation") {
    std::vector<std::pair<int, int>> places;
    for (int b = 0; b < nb; ++b) {
      const BranchSpec& br = nominal.branches[static_cast<size_t>(b)];
      for (int k = 0; k < static_cast<int>(br.supports.size()); ++k) {
        const SupportSpec& sp = br.supports[static_cast<size_t>(k)];
        const bool inside = sp.s > 1e-9 && sp.s < br.length - 1e-9;
        if (effect == "clip_position" ? inside : sp.kind != SupportKind::kPin) places.emplace_back(b, k);
      }
    }
    if (places.empty()) {
      h.effect.clear();  // not on this layout
      return h;
    }
    const auto [b, k] = places[static_cast<size_t>(pick(static_cast<int>(places.size())))];
    h.branch = b;
    h.support = k;
    SupportSpec& sp = t.branches[static_cast<size_t>(b)].supports[static_cast<size_t>(k)];
    if (effect == "clip_position") {
      const double d = (u(rng) < 0.5 ? -1.0 : 1.0) * (0.006 + 0.008 * u(rng));
      h.interval = std::make_pair(std::min(sp.s, sp.s + d), std::max(sp.s, sp.s + d));
      sp.s += d;
    } else {
      const Frame f = Frame::FromTangentNormal(sp.tangent, sp.normal);
      const double a = 2 * M_PI * u(rng);
      const Eigen::AngleAxisd rot(0.1 + 0.1 * u(rng), std::cos(a) * f.d1 + std::sin(a) * f.d2);
      sp.tangent = rot * f.d3;
      sp.normal = rot * f.d1;
      h.interval = std::make_pair(sp.s, sp.s);
    }
  } else if (effect == "branch_stiffness" || effect == "branch_density") {
    h.branch = pick(nb);
    MaterialSpec& m = t.branches[static_cast<size_t>(h.branch)].material;
    const double f = effect == "branch_stiffness" ? 2.0 + u(rng) : 1.6 + 0.9 * u(rng);
    const double factor = u(rng) < 0.5 ? f : 1.0 / f;
    if (effect == "branch_stiffness") {
      m.bending_stiffness *= factor;
      m.torsional_stiffness *= factor;
    } else {
      m.linear_density *= factor;
    }
    h.interval = std::make_pair(0.0, nominal.branches[static_cast<size_t>(h.branch)].length);
  } else if (effect == "branch_curvature") {
    h.branch = pick(nb);
    const double L = nominal.branches[static_cast<size_t>(h.branch)].length;
    const double c = (0.3 + 0.4 * u(rng)) * L, w = (0.25 + 0.2 * u(rng)) * L;
    const double k = 4.0 + 4.0 * u(rng), a = 2 * M_PI * u(rng);
    NaturalCurvatureSpec nc;
    nc.s_start = std::max(0.0, c - w / 2);
    nc.s_end = std::min(L, c + w / 2);
    nc.ramp = 0.2 * w;
    nc.kappa = Vec3(k * std::cos(a), k * std::sin(a), 0.0);
    t.branches[static_cast<size_t>(h.branch)].natural_curvature.push_back(nc);
    h.interval = std::make_pair(nc.s_start, nc.s_end);
  } else if (effect == "support_contact") {
    h.branch = pick(nb);
    const BranchSpec& br = nominal.branches[static_cast<size_t>(h.branch)];
    const double s = (0.35 + 0.3 * u(rng)) * br.length;
    const NetworkSolution sol = Solve(nominal);
    const Polyline& c = sol.branches[static_cast<size_t>(h.branch)];
    Eigen::Index i = 1;
    while (i + 1 < c.size() && c.s[i] < s) ++i;
    const Vec3 tangent = (c.points.col(i) - c.points.col(i - 1)).normalized();
    Vec3 up = Vec3::UnitZ() - tangent.z() * tangent;
    up.normalize();
    const double weight = br.material.linear_density * 9.81 * br.length;
    t.branches[static_cast<size_t>(h.branch)].point_loads.push_back({s, (0.3 + 0.3 * u(rng)) * weight * up});
    h.interval = std::make_pair(s, s);
  }
  return h;
}

// The largest distance between the nominal and the truth, branch by branch at equal arc
// length fractions [m]; infinite when either cannot be solved.
double LargestShift(const NetworkSpec& nominal, const NetworkSpec& truth) {
  try {
    const NetworkSolution a = Solve(nominal), b = Solve(truth);
    if (!a.converged() || !b.converged()) return std::numeric_limits<double>::infinity();
    double largest = 0.0;
    for (size_t k = 0; k < a.branches.size(); ++k) {
      const double la = a.branches[k].s[a.branches[k].size() - 1];
      const double lb = b.branches[k].s[b.branches[k].size() - 1];
      for (int i = 0; i <= 200; ++i) {
        const double f = i / 200.0;
        const Vec3 d = PointAt(a.branches[k], f * la) - PointAt(b.branches[k], f * lb);
        largest = std::max(largest, d.norm());
      }
    }
    return largest;
  } catch (const InvalidInput&) {
    return std::numeric_limits<double>::infinity();
  }
}

PointCloud ScanHarness(const NetworkSpec& truth, const HarnessScanOptions& options, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointCloud cloud;
  NetworkSolution sol;
  try {
    sol = Solve(truth);
  } catch (const InvalidInput&) {
    return cloud;  // a hidden change the harness cannot take (a stretch made too short)
  }
  if (!sol.converged()) return cloud;
  double total = 0.0;
  for (const BranchSpec& b : truth.branches) total += b.length;
  std::vector<Eigen::Matrix3Xd> parts;
  Eigen::Index count = 0;
  for (size_t b = 0; b < truth.branches.size(); ++b) {
    const Polyline& c = sol.branches[b];
    const double L = c.s[c.size() - 1];
    const Polyline fine = SampleCenterline(c, UniformArcLengths(L, 2000));
    SyntheticScanSpec ss;
    ss.diameter = truth.branches[b].material.diameter;
    ss.coverage_deg = 160 + 100 * u(rng);
    ss.noise_sigma = options.noise_sigma;
    ss.points = std::max(200, static_cast<int>(options.points * L / total));
    ss.clamp_margin = 0.005;
    if (options.gap_fraction > 0) {
      const double g = options.gap_fraction * L, g0 = (0.2 + 0.5 * u(rng)) * L;
      ss.gaps = {Eigen::Vector2d(g0, g0 + g)};
    }
    ss.seed = static_cast<unsigned>(rng());
    parts.push_back(MakeSyntheticScan(fine, ss).cloud.points);
    count += parts.back().cols();
  }
  cloud.points.resize(3, count);
  Eigen::Index at = 0;
  for (const Eigen::Matrix3Xd& p : parts) {
    cloud.points.middleCols(at, p.cols()) = p;
    at += p.cols();
  }
  return cloud;
}

bool WriteHarnessCaseFolder(const std::filesystem::path& dir, const HarnessLayout& layout,
                            const NetworkSpec& truth, const std::vector<HiddenHarnessEffect>& hidden,
                            const HarnessScanOptions& scan, std::mt19937& rng, std::string* why) {
  const PointCloud cloud = ScanHarness(truth, scan, rng);
  if (cloud.size() == 0) {
    if (why) *why = "the hidden truth could not be solved";
    return false;
  }
  // A hidden effect that moves no part of the harness by ten noise sigmas is not in the scan:
  // nothing could name it, so it is no case (a clip shifted onto where the bundle lies anyway).
  if (!hidden.empty() && LargestShift(layout.spec, truth) < 10 * scan.noise_sigma) {
    if (why) *why = "the hidden effect does not show";
    return false;
  }
  std::filesystem::create_directories(dir / "routes");
  const NetworkSpec& n = layout.spec;
  Json branches = Json::array();
  for (const BranchSpec& b : n.branches) {
    WriteCenterlineCsv((dir / "routes" / (b.name + ".csv")).string(), b.route);
    Json supports = Json::array();
    for (const SupportSpec& sp : b.supports)
      supports.push_back({{"kind", ToString(sp.kind)}, {"s", sp.s}, {"position", Vector(sp.position)},
                          {"tangent", Vector(sp.tangent)}, {"normal", Vector(sp.normal)}});
    Json jb = {{"name", b.name},
               {"route", "routes/" + b.name + ".csv"},
               {"length", b.length},
               {"diameter", b.material.diameter},
               {"bending_stiffness", b.material.bending_stiffness},
               {"torsional_stiffness", b.material.torsional_stiffness},
               {"linear_density", b.material.linear_density},
               {"supports", supports}};
    if (b.start_junction >= 0) jb["start_junction"] = n.junctions[static_cast<size_t>(b.start_junction)].name;
    if (b.end_junction >= 0) jb["end_junction"] = n.junctions[static_cast<size_t>(b.end_junction)].name;
    branches.push_back(jb);
  }
  Json junctions = Json::array();
  for (const JunctionSpec& j : n.junctions)
    junctions.push_back({{"name", j.name}, {"compliance", j.compliance}, {"mass", j.mass}});
  Json solids = Json::array();
  for (const HarnessBox& box : layout.boxes)
    solids.push_back({{"name", box.name}, {"min", Vector(box.lo)}, {"max", Vector(box.hi)}});
  const Json case_json = {{"format", "harness-recording/1"},
                          {"name", dir.filename().string()},
                          {"gravity", Vector(n.gravity)},
                          {"junctions", junctions},
                          {"branches", branches},
                          {"solids", solids},
                          {"recordings", Json::array({{{"kind", "scan"}, {"file", "scan.ply"}}})}};
  json::WriteJsonFile((dir / "case.json").string(), case_json);
  WritePly((dir / "scan.ply").string(), cloud);
  Json h = Json::array();
  for (const HiddenHarnessEffect& e : hidden)
    h.push_back({{"effect", e.effect},
                 {"branch", e.branch >= 0 ? Json(n.branches[static_cast<size_t>(e.branch)].name) : Json(nullptr)},
                 {"junction", e.junction >= 0 ? Json(n.junctions[static_cast<size_t>(e.junction)].name) : Json(nullptr)},
                 {"support", e.support >= 0 ? Json(e.support) : Json(nullptr)},
                 {"interval", e.interval ? Json::array({e.interval->first, e.interval->second}) : Json(nullptr)}});
  json::WriteJsonFile((dir / "hidden.json").string(), {{"layout", layout.name}, {"effects", h}});
  return true;
}

}  // namespace cablefit::testing
