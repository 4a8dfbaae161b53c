// The tolerance envelope of a cable solved alone: fixings shifted along the cable against the
// cantilever's closed form and against set-ups solved independently, and the corners chosen by
// sensitivity against every corner of the box.
#include "cablefit/app/tolerance/relax_tolerance.h"

#include <cmath>

#include <gtest/gtest.h>

#include "cablefit/core/solver/centerline_sampling.h"
#include "test_support.h"

namespace cablefit::addin {
namespace {

constexpr double kG = 9.81;

// A drawn route: V-shaped loops between the given support points (span i `spans[i - 1]` long,
// or the last one given), then straight on for `overhang` along +x.
Polyline LoopedRoute(const std::vector<double>& xs, const std::vector<double>& spans,
                     double overhang) {
  std::vector<Vec3> pts = {Vec3(xs[0], 0, 0)};
  for (size_t i = 1; i < xs.size(); ++i) {
    const double span = spans[std::min(i - 1, spans.size() - 1)];
    const double half = 0.5 * (xs[i] - xs[i - 1]);
    const double h = std::sqrt(0.25 * span * span - half * half);
    pts.push_back(Vec3(xs[i - 1] + half, 0, -h));
    pts.push_back(Vec3(xs[i], 0, 0));
  }
  if (overhang > 0) pts.push_back(Vec3(xs.back() + overhang, 0, 0));
  Polyline p;
  p.points.resize(3, static_cast<Eigen::Index>(pts.size()));
  p.s.resize(static_cast<Eigen::Index>(pts.size()));
  double s = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (i > 0) s += (pts[i] - pts[i - 1]).norm();
    p.points.col(static_cast<Eigen::Index>(i)) = pts[i];
    p.s[static_cast<Eigen::Index>(i)] = s;
  }
  return p;
}

SupportSpec Support(SupportKind kind, double s, double x) {
  SupportSpec sp;
  sp.kind = kind;
  sp.s = s;
  sp.position = Vec3(x, 0, 0);
  sp.tangent = Vec3::UnitX();
  sp.normal = Vec3::UnitZ();
  return sp;
}

CableRelaxation Relaxed(const RodSpec& spec, const Polyline& route,
                        const SimulationOptions& options) {
  CableRelaxation r;
  r.setup.name = spec.name;
  r.setup.spec = spec;
  r.setup.route = route;
  r.result = RodSimulator(options).Simulate(spec, &route);
  return r;
}

// Largest distance of `varied`'s points to the polyline `nominal`, sampled every 0.2 mm (brute
// force: an independent measure of the excursion).
double Farthest(const Polyline& nominal, const Polyline& varied) {
  const double length = nominal.s[nominal.size() - 1];
  const Polyline n = SampleCenterline(
      nominal, UniformArcLengths(length, static_cast<int>(length / 2e-4) + 1));
  double far = 0.0;
  for (Eigen::Index j = 0; j < varied.points.cols(); ++j)
    far = std::max(far, (n.points.colwise() - varied.points.col(j)).colwise().norm().minCoeff());
  return far;
}

TEST(RelaxTolerance, AShiftedClipLeavesTheOverhangOfTheCantileverClosedForm) {
  // Clamp at x = 0, a slack loop of 0.3 m to a clip at x = 0.25 m, a 0.3 m overhang beyond it:
  // a cantilever clamped at the clip. The fixing taped 10 mm further along the cable leaves
  // 0.29 m hanging out, 10 mm nearer 0.31 m: tip sag w l^4 / (8 EI).
  RodSpec spec;
  spec.name = "overhang";
  spec.length = 0.6;
  spec.material = {.bending_stiffness = 1.0, .torsional_stiffness = 0.8, .linear_density = 0.1,
                   .diameter = 0.008};
  spec.supports = {Support(SupportKind::kClamp, 0.0, 0.0), Support(SupportKind::kClip, 0.3, 0.25)};
  const Polyline route = LoopedRoute({0.0, 0.25}, {0.3}, 0.3);
  SimulationOptions options;
  options.accuracy = 1e-6;
  const CableRelaxation nominal = Relaxed(spec, route, options);
  ASSERT_TRUE(nominal.ok()) << nominal.result.solution.summary.message;
  ToleranceConfig tc;
  tc.clip_position = 0.01;
  std::vector<std::string> problems;
  const CableTolerance t = SingleCableTolerance(nominal, tc, options, &problems);
  EXPECT_TRUE(problems.empty());
  ASSERT_EQ(t.clip_s.size(), 1u);
  EXPECT_DOUBLE_EQ(t.clip_s[0], 0.3);
  EXPECT_DOUBLE_EQ(t.clip_range[0][0], -0.01);
  EXPECT_DOUBLE_EQ(t.clip_range[0][1], 0.01);
  EXPECT_EQ(t.quantities, 1);
  EXPECT_TRUE(t.all_corners);
  ASSERT_EQ(t.corners.size(), 2u);
  const double w = 0.1 * kG;
  for (const ToleranceCase& c : t.corners) {
    ASSERT_TRUE(c.converged);
    ASSERT_EQ(c.clip_shift.size(), 1u);
    EXPECT_NEAR(std::abs(c.clip_shift[0]), 0.01, 1e-15);
    const double l = 0.3 - c.clip_shift[0];
    const Vec3 tip = c.centreline.points.rightCols<1>();
    const double sag = w * std::pow(l, 4) / 8.0;  // EI = 1
    EXPECT_NEAR(-tip.z(), sag, 0.01 * sag) << c.clip_shift[0];
    EXPECT_NEAR(tip.x(), 0.25 + l, 1e-5) << c.clip_shift[0];
    // The same set-up solved on its own, the clip's place changed by hand.
    RodSpec shifted = spec;
    shifted.supports[1].s += c.clip_shift[0];
    const SimulationResult alone = RodSimulator(options).Simulate(shifted, &route);
    ASSERT_TRUE(alone.converged);
    const Polyline mine = SampleCenterline(alone.solution.centerline, c.centreline.s);
    EXPECT_LT((mine.points - c.centreline.points).colwise().norm().maxCoeff(), 1e-6);
    EXPECT_NEAR(c.excursion, Farthest(nominal.result.solution.centerline, c.centreline), 2e-6);
    // The loop takes up the shift: it moves by millimetres, far more than the tip.
    EXPECT_GT(c.excursion, 5 * std::abs(sag - w * std::pow(0.3, 4) / 8.0));
  }
  EXPECT_TRUE(t.interior_within);
}

// As a harness drawing has it: a clamp, 200 mm of cable drawn straight (taut: it stretches) to
// a clip, a 250 mm loop to a second clip 200 mm on, 150 mm hanging beyond it.
CableRelaxation TautThenLooped(const SimulationOptions& options) {
  RodSpec spec;
  spec.name = "taut";
  spec.length = 0.6;
  spec.material = {.bending_stiffness = 0.05, .torsional_stiffness = 0.04, .linear_density = 0.1,
                   .diameter = 0.008, .axial_stiffness = 1e5};
  spec.supports = {Support(SupportKind::kClamp, 0.0, 0.0), Support(SupportKind::kClip, 0.2, 0.2),
                   Support(SupportKind::kClip, 0.45, 0.4)};
  const Polyline looped = LoopedRoute({0.2, 0.4}, {0.25}, 0.15);
  Polyline route;  // the straight stretch from the clamp, then the loop
  route.points.resize(3, looped.size() + 1);
  route.points.col(0) = Vec3::Zero();
  route.points.rightCols(looped.size()) = looped.points;
  route.ParameteriseByChords(0.0);
  return Relaxed(spec, route, options);
}

TEST(RelaxTolerance, AFixingAtTheEndOfATautStretchMovesOnlyAwayFromIt) {
  SimulationOptions options;
  options.accuracy = 1e-5;
  const CableRelaxation nominal = TautThenLooped(options);
  ASSERT_TRUE(nominal.ok()) << nominal.result.solution.summary.message;
  ToleranceConfig tc;
  tc.clip_position = 0.01;
  std::vector<std::string> problems;
  const CableTolerance t = SingleCableTolerance(nominal, tc, options, &problems);
  // The first clip cannot move towards the clamp (no slack): only on, by the 10 mm asked; the
  // second by 10 mm either way (the loop's 50 mm of slack, a quarter each, is more).
  ASSERT_EQ(t.clip_range.size(), 2u);
  EXPECT_NEAR(t.clip_range[0][0], 0.0, 1e-9);
  EXPECT_NEAR(t.clip_range[0][1], 0.01, 1e-12);
  EXPECT_NEAR(t.clip_range[1][0], -0.01, 1e-12);
  EXPECT_NEAR(t.clip_range[1][1], 0.01, 1e-12);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("shifted by -0.0/+10.0 mm only: the cable before it is nearly taut"),
            std::string::npos)
      << problems[0];
  // Every corner is a harness that can be built, and is solved.
  ASSERT_EQ(t.corners.size(), 4u);
  for (const ToleranceCase& c : t.corners) {
    EXPECT_TRUE(c.buildable);
    EXPECT_TRUE(c.converged) << c.why;
  }
}

TEST(RelaxTolerance, ALengthThatMakesAStretchTooShortCannotBeBuiltAndSaysSo) {
  SimulationOptions options;
  options.accuracy = 1e-5;
  const CableRelaxation nominal = TautThenLooped(options);
  ASSERT_TRUE(nominal.ok());
  ToleranceConfig tc;
  // 15 % shorter: 170 mm of cable from the clamp to the clip 200 mm away, a stretch of 18 %,
  // beyond what a bundle's EA makes up for (a few per cent is stretched across, taut).
  tc.length = 0.15;
  std::vector<std::string> problems;
  const CableTolerance t = SingleCableTolerance(nominal, tc, options, &problems);
  ASSERT_EQ(t.corners.size(), 2u);
  for (const ToleranceCase& c : t.corners) {
    EXPECT_EQ(c.buildable, c.length > 0);
    EXPECT_EQ(c.converged, c.length > 0) << c.why;
    if (!c.buildable) {
      EXPECT_NE(c.why.find("of cable lies between them"), std::string::npos) << c.why;
    }
  }
  FileTolerance ft;
  ft.cables = {t};
  const std::string line = ToleranceLines(ft)[0];
  EXPECT_NE(line.find("cannot be built (first: supports 0 and 1"), std::string::npos) << line;
  EXPECT_EQ(line.find("NOT SOLVED"), std::string::npos) << line;
}

TEST(RelaxTolerance, CornersChosenBySensitivityReachTheEnvelopeOfEveryCorner) {
  // Clamped at both ends, five clips between, six slack loops: length, EI and five fixings
  // varied = 7 quantities, beyond the exhaustive limit.
  const std::vector<double> xs = {0.0, 0.18, 0.36, 0.54, 0.72, 0.90, 1.08};
  RodSpec spec;
  spec.name = "clipped";
  spec.length = 1.2;
  spec.material = {.bending_stiffness = 0.02, .torsional_stiffness = 0.015, .linear_density = 0.1,
                   .diameter = 0.008};
  for (size_t i = 0; i < xs.size(); ++i)
    spec.supports.push_back(Support(i == 0 || i + 1 == xs.size() ? SupportKind::kClamp
                                                                 : SupportKind::kClip,
                                    0.2 * static_cast<double>(i), xs[i]));
  const Polyline route = LoopedRoute(xs, {0.2}, 0.0);
  SimulationOptions options;
  options.accuracy = 1e-5;
  const CableRelaxation nominal = Relaxed(spec, route, options);
  ASSERT_TRUE(nominal.ok()) << nominal.result.solution.summary.message;
  ToleranceConfig tc;
  tc.length = 0.02;
  tc.bending_stiffness = 0.3;
  tc.clip_position = 0.004;  // every span keeps slack at every corner
  std::vector<std::string> problems;
  const CableTolerance t = SingleCableTolerance(nominal, tc, options, &problems);
  ASSERT_EQ(t.quantities, 7);
  EXPECT_FALSE(t.all_corners);
  EXPECT_EQ(t.sensitivity_solves, 14);
  EXPECT_LE(t.corners.size(), static_cast<size_t>(kChosenCorners));
  ASSERT_GE(t.worst_corner, 0);
  const double chosen = t.corners[static_cast<size_t>(t.worst_corner)].excursion;
  // Every one of the 128 corners solved independently.
  double every = 0.0;
  for (int m = 0; m < 128; ++m) {
    auto sign = [m](int q) { return (m >> q) & 1 ? 1.0 : -1.0; };
    RodSpec v = VariedSpec(spec, sign(0) * 0.02, sign(1) * 0.3, 0.0);
    for (int c = 0; c < 5; ++c) v.supports[static_cast<size_t>(c + 1)].s += sign(c + 2) * 0.004;
    const SimulationResult r =
        RodSimulator(options).Simulate(v, &nominal.result.solution.centerline);
    ASSERT_TRUE(r.converged) << m;
    const Polyline shape = SampleCenterline(r.solution.centerline,
                                            UniformArcLengths(v.length, 201));
    every = std::max(every, Farthest(nominal.result.solution.centerline, shape));
  }
  std::printf("envelope: chosen %zu corners %.4f mm, all 128 corners %.4f mm\n", t.corners.size(),
              1e3 * chosen, 1e3 * every);
  EXPECT_GT(chosen, 0.97 * every);
  EXPECT_LT(chosen, every + 1e-5);
  EXPECT_TRUE(t.interior_within);
  // The same on three threads, to the bit.
  const CableTolerance t3 = SingleCableTolerance(nominal, tc, options, &problems, 3);
  ASSERT_EQ(t3.corners.size(), t.corners.size());
  for (size_t i = 0; i < t.corners.size(); ++i) {
    EXPECT_EQ(t3.corners[i].excursion, t.corners[i].excursion) << i;
    EXPECT_EQ(t3.corners[i].clip_shift, t.corners[i].clip_shift) << i;
  }
}

}  // namespace
}  // namespace cablefit::addin
