#include "concealed_cases.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/scan_centerline_extractor.h"
#include "synthetic_tube_scan.h"

namespace cablefit::testing {

std::vector<Layout> CorpusLayouts() {
  return {
      {"sag", 0.75, 0.0, 0.0, Vec3(1, 0, 0), Vec3(1, 0, 0)},
      {"bend3d", 0.6, 0.15, 0.6, Vec3(1, 0.3, 0.1), Vec3(0.2, 1, -0.2)},
      {"drop", 0.5, 0.5, 0.2, Vec3(1, 0, 0), Vec3(0.3, 0, -1)},
      {"loop", 0.3, 0.05, 0.0, Vec3(1, 0, 0.3), Vec3(-1, 0, 0.3)},
  };
}

std::vector<Layout> NewLayouts() {
  return {
      // The far clamp well below the first, the cable leaving downwards and arriving steeply.
      {"steep", 0.35, 0.8, 0.3, Vec3(1, 0, -0.4), Vec3(0.2, 0.1, -1)},
      // Parallel clamps set side by side: the cable makes an S in plan as it sags.
      {"s_clips", 0.6, 0.1, 0.6, Vec3(1, 0, 0), Vec3(1, 0, 0)},
      // A long, limp span: weight far above stiffness.
      {"long_sag", 0.85, 0.05, 0.0, Vec3(1, 0, 0.2), Vec3(1, 0, -0.2), 40.0, 90.0},
      // Out of plane, rising to the far clamp, which is set a half-turn and more off the cable's
      // own twist.
      {"twisted3d", 0.5, -0.2, -0.9, Vec3(0.8, -0.2, 0.4), Vec3(-0.3, -1, 0.3), 2.0, 35.0, 1.9},
  };
}

const Layout* FindLayout(const std::string& name) {
  static const std::vector<Layout> all = [] {
    std::vector<Layout> a = CorpusLayouts();
    for (const Layout& l : NewLayouts()) a.push_back(l);
    return a;
  }();
  for (const Layout& l : all)
    if (name == l.name) return &l;
  return nullptr;
}

ScanQuality SparseNoisyScan() { return {0.5, 0.1, 2.0}; }

RodSpec MakeNominal(const Layout& lay, std::mt19937& rng, double gravity_number) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RodSpec s;
  s.length = 0.45 + 0.3 * u(rng);
  s.material.bending_stiffness = 0.005 + 0.012 * u(rng);
  s.material.torsional_stiffness = 0.8 * s.material.bending_stiffness;
  s.material.diameter = 0.005 + 0.004 * u(rng);
  // Gravity number w L^3 / EI between 2 (stiff, little sag) and 35 (visibly sagging, not a
  // string).
  const double drawn = lay.min_gravity + (lay.max_gravity - lay.min_gravity) * u(rng);
  const double gn = gravity_number > 0 ? gravity_number : drawn;
  s.material.linear_density = gn * s.material.bending_stiffness / (9.81 * std::pow(s.length, 3));
  SupportSpec a, b;
  a.position = Vec3(0, 0, 0.5);
  a.tangent = lay.t0;
  a.normal = lay.t0.unitOrthogonal();
  b.s = s.length;
  const double d = lay.span * s.length;
  b.position =
      a.position + Vec3(d * std::cos(lay.yaw), d * std::sin(lay.yaw), -lay.drop * s.length);
  b.tangent = lay.t1;
  b.normal = lay.t1.unitOrthogonal();
  s.supports = {a, b};
  // The far clamp is set as on a bench, within ~10 deg of the cable's torque-free twist (the far
  // clamp released about its axis), like the public recordings.
  RodSpec released = s;
  released.supports[1].kind = SupportKind::kClip;
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(released);
  if (r.converged) {
    const Frame& f = r.solution.frames.back();
    const Vec3 t = lay.t1.normalized();
    const Vec3 d1 = Eigen::Quaterniond::FromTwoVectors(f.d3, t) * f.d1;
    std::normal_distribution<double> twist(0.0, 0.17);
    s.supports[1].normal = Eigen::AngleAxisd(twist(rng) + lay.far_twist, t) * d1;
  }
  return s;
}

Vec3 NormalPush(const RodSpec& nominal, double sc, double magnitude, double angle) {
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(nominal);
  const Polyline& c = r.solution.centerline;
  Eigen::Index i = 1;
  while (i + 1 < c.s.size() && c.s[i] < sc) ++i;
  const Vec3 t = (c.points.col(i) - c.points.col(i - 1)).normalized();
  Vec3 up = Vec3::UnitZ() - t.z() * t;
  up = up.norm() > 0.1 ? Vec3(up.normalized()) : t.unitOrthogonal();
  const Vec3 side = t.cross(up);
  return magnitude * (std::cos(angle) * up + std::sin(angle) * side);
}

std::optional<int> HideEffect(const std::string& effect, const RodSpec& nominal, bool subtle,
                              std::mt19937& rng, RodSpec* truth, Placement place) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double f = subtle ? 0.5 : 1.0;
  RodSpec& t = *truth;
  const double L = nominal.length;
  // The random draws are made whatever the placement, so that a placement changes nothing else.
  auto clamp_of = [&](bool either) { return place.clamp >= 0 ? place.clamp : (either ? 0 : 1); };
  if (effect == "intrinsic_curvature") {
    const double w = (0.08 + 0.2 * u(rng)) * L, drawn = (0.25 + 0.5 * u(rng)) * L;
    const double c = place.where >= 0 ? place.where * L : drawn;
    const double a = 2 * M_PI * u(rng), k = f * (2.0 + 2.0 * u(rng));
    t.natural_curvature.push_back({std::max(0.0, c - w / 2), std::min(L, c + w / 2), 0.2 * w,
                                   Vec3(k * std::cos(a), k * std::sin(a), 0)});
  } else if (effect == "clamp_orientation") {
    const int k = clamp_of(u(rng) < 0.5);
    SupportSpec& sp = t.supports[static_cast<size_t>(k)];
    const Frame fr = Frame::FromTangentNormal(sp.tangent, sp.normal);
    const double a = 2 * M_PI * u(rng);
    const Eigen::AngleAxisd rot(f * (0.08 + 0.12 * u(rng)),
                                std::cos(a) * fr.d1 + std::sin(a) * fr.d2);
    sp.tangent = rot * fr.d3;
    sp.normal = rot * fr.d1;
    return k;
  } else if (effect == "weight_stiffness_ratio") {
    const double r =
        u(rng) < 0.5 ? 1.0 + f * (0.3 + 0.6 * u(rng)) : 1.0 / (1.0 + f * (0.3 + 0.6 * u(rng)));
    t.material.linear_density *= r;
  } else if (effect == "anisotropic_bending") {
    t.material.bending_ratio = 1.0 + f * (0.5 + 0.8 * u(rng));
    t.material.principal_angle = M_PI * u(rng);
  } else if (effect == "support_contact") {
    const double w = nominal.material.linear_density * 9.81 * L;
    const double a = 2 * M_PI * u(rng), drawn = (0.3 + 0.4 * u(rng)) * L;
    const double sc = place.where >= 0 ? place.where * L : drawn;
    // Normal to the cable as it hangs with what was hidden before (a support pushes on the real
    // cable, not on the drawing).
    t.point_loads.push_back({sc, NormalPush(t, sc, f * (0.034 + 0.056 * u(rng)) * w, a)});
  } else if (effect == "clamp_compliance") {
    const int k = clamp_of(u(rng) < 0.5);
    RodSimulator sim;
    const SimulationResult r = sim.Simulate(nominal);
    const double m = r.solution.reactions[static_cast<size_t>(k)].moment.norm();
    const double theta = f * (0.05 + 0.07 * u(rng));
    t.supports[static_cast<size_t>(k)].compliance = Mat3::Identity() * (theta / std::max(m, 1e-6));
    return k;
  } else if (effect == "twist_preload") {
    const int k = clamp_of(u(rng) < 0.5);
    SupportSpec& sp = t.supports[static_cast<size_t>(k)];
    const double a = (u(rng) < 0.5 ? -1.0 : 1.0) * f * (0.5 + 0.6 * u(rng));
    sp.normal = Eigen::AngleAxisd(a, sp.tangent.normalized()) * sp.normal;
    return k;
  }
  return std::nullopt;
}

std::optional<std::pair<double, double>> HiddenSpan(const std::string& effect,
                                                    const RodSpec& truth) {
  if (effect == "intrinsic_curvature" && !truth.natural_curvature.empty())
    return std::make_pair(truth.natural_curvature.back().s_start,
                          truth.natural_curvature.back().s_end);
  if (effect == "support_contact" && !truth.point_loads.empty())
    return std::make_pair(truth.point_loads.back().s, truth.point_loads.back().s);
  return std::nullopt;
}

std::optional<std::pair<double, double>> ContributionSpan(const RodSpec& with,
                                                          const RodSpec& without) {
  RodSimulator a, b;
  const SimulationResult ra = a.Simulate(with), rb = b.Simulate(without);
  if (!ra.converged || !rb.converged) return std::nullopt;
  const Eigen::VectorXd s = UniformArcLengths(with.length, 400);
  const Polyline pa = SampleCenterline(ra.solution.centerline, s);
  const Polyline pb = SampleCenterline(rb.solution.centerline, s);
  const Eigen::VectorXd d = (pa.points - pb.points).colwise().norm().transpose();
  const double half = 0.5 * d.maxCoeff();
  Eigen::Index first = 0, last = d.size() - 1;
  while (first < last && d[first] < half) ++first;
  while (last > first && d[last] < half) --last;
  return std::make_pair(s[first], s[last]);
}

namespace {

// A frictionless support pushes normal to the cable as it finally hangs, its own push and every
// other hidden effect included, not as the cable hung before (the public reference cases do so
// to 0.1 degrees). Each push loses its component along the final tangent and keeps its
// magnitude, until the directions settle.
RodSpec WithContactsNormalToTheCable(RodSpec truth) {
  if (truth.point_loads.empty()) return truth;
  for (int it = 0; it < 8; ++it) {
    RodSimulator sim;
    const SimulationResult r = sim.Simulate(truth);
    if (!r.converged) return truth;
    const Polyline& c = r.solution.centerline;
    double change = 0.0;
    for (PointLoadSpec& pl : truth.point_loads) {
      Eigen::Index i = 1;
      while (i + 1 < c.s.size() && c.s[i] < pl.s) ++i;
      const Vec3 t = (c.points.col(i) - c.points.col(i - 1)).normalized();
      const double magnitude = pl.force.norm();
      if (!(magnitude > 0)) continue;
      const Vec3 normal = (pl.force - pl.force.dot(t) * t).normalized() * magnitude;
      change = std::max(change, (normal - pl.force).norm() / magnitude);
      pl.force = normal;
    }
    if (change < 1e-6) break;
  }
  return truth;
}

}  // namespace

ScannedTruth ScanTruth(const RodSpec& hidden, const RodSpec& told, std::mt19937& rng, bool run,
                       const ScanQuality& quality) {
  ScannedTruth out;
  RodSimulator sim;
  SimulationResult solved;
  const RodSpec truth = WithContactsNormalToTheCable(hidden);
  try {
    solved = sim.Simulate(truth);
  } catch (const std::exception& e) {
    out.failure = e.what();
    return out;
  }
  if (!solved.converged) {
    out.failure = solved.solution.summary.BriefReport();
    return out;
  }
  out.solved = true;
  const double L = truth.length;
  const Polyline curve = SampleCenterline(solved.solution.centerline, UniformArcLengths(L, 4000));
  SyntheticScanSpec ss;
  ss.diameter = truth.material.diameter;
  ss.coverage_deg = 140 + 120 * (rng() % 1000) / 1000.0;
  ss.noise_sigma = quality.noise_factor * (0.05e-3 + 0.1e-3 * (rng() % 1000) / 1000.0);
  ss.points = static_cast<int>(quality.point_factor * ((rng() % 2) ? 8000 : 15000));
  const double g0 = (0.2 + 0.5 * (rng() % 1000) / 1000.0) * L;
  ss.gaps = {
      Eigen::Vector2d(g0, g0 + (quality.gap_fraction > 0 ? quality.gap_fraction * L : 0.04))};
  ss.seed = static_cast<unsigned>(rng());
  if (!run) return out;
  const SyntheticScan scan = MakeSyntheticScan(curve, ss);
  ScanCenterlineOptions so;
  so.diameter = truth.material.diameter;
  const auto t0 = std::chrono::steady_clock::now();
  // The scan is traced along the set-up it was taken on when the diagnosis is told too few
  // clamps to guide it (as a measured centreline would need no guide).
  const ScanCenterline sc = ExtractScanCenterline(
      scan.cloud, so, ScanGuide::FromRodSpec(told.supports.size() > 1 ? told : truth));
  out.observation.points = sc.points;
  out.observation.s = sc.s;
  out.observation.noise_sigma = std::max(1e-5, sc.noise_sigma / 10.0);
  out.extraction_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.cloud = scan.cloud;
  return out;
}

std::optional<ScannedTruth> ScanOrReport(const char* layout, const std::string& label,
                                         const RodSpec& truth, const RodSpec& told,
                                         std::mt19937& rng, bool run, const ScanQuality& quality) {
  ScannedTruth scanned = ScanTruth(truth, told, rng, run, quality);
  if (scanned.solved) return scanned;
  std::printf("%-7s %-45s truth solve failed: %s\n", layout, label.c_str(),
              scanned.failure.c_str());
  return std::nullopt;
}

ShapeDiagnosis DiagnoseAsCommand(const RodSpec& told, const ScannedTruth& scanned,
                                 double* seconds) {
  const auto t0 = std::chrono::steady_clock::now();
  ShapeDiagnosisOptions options;
  options.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  ShapeDiagnosis d = DiagnoseShape(told, scanned.observation, options);
  *seconds = scanned.extraction_seconds +
             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return d;
}

}  // namespace cablefit::testing
