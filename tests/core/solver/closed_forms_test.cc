// The rod core against closed forms: a weightless rod with uniform natural curvature forms the
// exact arc; clamped-clamped Euler buckling at 4 pi^2 EI / L^2 and Greenhill's twist buckling at
// M L / EI = 2.8606 pi (clamped ends, free axial sliding; Greenhill 1883, see Timoshenko & Gere
// "Theory of Elastic Stability" 2.19) found by the stability verdict; the pinned elastica's
// force-shortening law P(d) (Love, "Mathematical Theory of Elasticity" 263).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "cablefit/core/force/force_rig.h"
#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/core/solver/statics_solver.h"
#include "test_support.h"

namespace cablefit {
namespace {

RodSpec StraightRod(double ei, double gj) {
  RodSpec spec;
  spec.length = 1.0;
  spec.material.bending_stiffness = ei;
  spec.material.torsional_stiffness = gj;
  spec.gravity = Vec3::Zero();
  return spec;
}

TEST(ClosedFormTest, UniformNaturalCurvatureFormsTheExactArc) {
  RodSpec spec = StraightRod(1.0, 0.7);
  SupportSpec clamp;
  clamp.tangent = Vec3::UnitX();
  clamp.normal = Vec3::UnitZ();
  spec.supports = {clamp};
  const double kappa = 2.5;
  spec.natural_curvature.push_back({0.0, 1.0, 0.0, Vec3(kappa, 0, 0)});
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(spec);
  ASSERT_TRUE(r.converged);
  // u1 d1 x d3 = -u1 d2: the arc bends towards -d2 = +y (d2 = d3 x d1 = -y).
  const Vec3 centre = Vec3(0, 1.0 / kappa, 0);
  const auto& p = r.solution.centerline.points;
  double err = 0.0;
  for (int i = 0; i < p.cols(); ++i) err = std::max(err, std::abs((p.col(i) - centre).norm() - 1.0 / kappa));
  const Vec3 tip(std::sin(kappa) / kappa, (1 - std::cos(kappa)) / kappa, 0);
  std::printf("arc: max radius error %.2e m, tip error %.2e m\n", err, (p.col(p.cols() - 1) - tip).norm());
  EXPECT_LE(err, 1e-6);  // the simulator's requested accuracy
  EXPECT_LE((p.col(p.cols() - 1) - tip).norm(), 1e-6);
  EXPECT_LE(r.solution.elastic_energy, 1e-12);
}

// Straight clamped rod, far end a clamp sliding along x; `configure` adds the load.
bool StableStraight(const RodSpec& spec, int elements) {
  Discretisation d;
  d.elements_per_span = {elements};
  const RodModel model = CompileRodModel(spec, d);
  RodState st = MakeInitialState(model, DefaultInitialCurve(spec));
  StaticsOptions opt;
  opt.escape_unstable = false;  // the verdict of the straight state itself
  const StaticsSummary sum = SolveStatics(model, &st, opt);
  EXPECT_TRUE(sum.converged()) << sum.BriefReport();
  return sum.stable;
}

double Bisect(const std::function<bool(double)>& stable, double lo, double hi) {
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

RodSpec SlidingClampedRod(double ei, double gj, double twist) {
  RodSpec spec = StraightRod(ei, gj);
  SupportSpec a, b;
  a.tangent = b.tangent = Vec3::UnitX();
  a.normal = Vec3::UnitZ();
  b.normal = Vec3(0, -std::sin(twist), std::cos(twist));
  b.s = 1.0;
  b.position = Vec3(1, 0, 0);
  b.sliding = true;
  spec.supports = {a, b};
  return spec;
}

TEST(ClosedFormTest, ClampedClampedEulerLoadFromTheStabilityVerdict) {
  const double ei = 2.0;
  const double exact = 4 * M_PI * M_PI * ei;
  const double found = Bisect(
      [&](double p) {
        RodSpec spec = SlidingClampedRod(ei, 1.5, 0.0);
        spec.point_loads.push_back({1.0, Vec3(-p, 0, 0)});
        return StableStraight(spec, 200);
      },
      0.5 * exact, 1.5 * exact);
  std::printf("Euler clamped-clamped: %.6f vs 4 pi^2 EI/L^2 = %.6f (rel. %.1e)\n", found, exact,
              found / exact - 1);
  EXPECT_NEAR(found / exact, 1.0, 0.01);
}

TEST(ClosedFormTest, GreenhillTwistLoadFromTheStabilityVerdict) {
  const double ei = 1.0, gj = 10.0;  // critical twist angle 2.8606 pi EI / GJ ~ 0.9 rad
  const double angle = Bisect(
      [&](double phi) { return StableStraight(SlidingClampedRod(ei, gj, phi), 200); }, 0.3, 1.5);
  const double mlei = gj * angle / ei;  // M L / EI with M = GJ phi / L, L = 1
  std::printf("Greenhill: M L / EI = %.5f = %.5f pi (reference 2.8606 pi)\n", mlei, mlei / M_PI);
  EXPECT_NEAR(mlei / (2.8606 * M_PI), 1.0, 0.01);
}

TEST(ClosedFormTest, PinnedElasticaForceAgainstEndShortening) {
  const double ei = 0.01, L = 1.0;
  for (double d : {0.01, 0.05, 0.2}) {
    RodSpec spec = StraightRod(ei, 0.008);
    SupportSpec a, b;
    a.kind = b.kind = SupportKind::kPin;
    b.s = L;
    b.position = Vec3(L - d, 0, 0);
    spec.supports = {a, b};
    // A buckled first-mode start in the x-z plane selects the branch.
    Polyline start;
    const int n = 200;
    start.points.resize(3, n + 1);
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      start.points.col(i) = Vec3((L - d) * t, 0, std::sqrt(2 * d * L) / M_PI * std::sin(M_PI * t));
    }
    RodSimulator sim;
    const SimulationResult r = sim.Simulate(spec, &start);
    ASSERT_TRUE(r.converged);
    const double p = -r.solution.reactions[1].force[0];
    const double exact = PinnedElasticaForce(ei, L, d);
    std::printf("pinned elastica d/L=%.2f: P = %.8f N, closed form %.8f N (rel. %.1e)\n", d, p,
                exact, p / exact - 1);
    EXPECT_NEAR(p / exact, 1.0, 1e-4);
  }
}

}  // namespace
}  // namespace cablefit
