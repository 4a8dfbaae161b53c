// A pre-formed branch (BranchSpec::preformed: a coiled cable, a moulded hose) has its drawn
// route as rest shape: unloaded it stays exactly as drawn, under gravity it only sags from it;
// the same coil without the flag springs open towards its straight rest shape.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cablefit/core/network/network_simulation.h"
#include "network_test_util.h"

namespace cablefit {
namespace {

using testing::Clamp;
using testing::TestMaterial;

constexpr double kCoilRadius = 0.03, kPitch = 0.02, kTurns = 2.0;  // [m], [m per turn]

// A coil along +x (its axis level, so that gravity acts across it), from the origin.
Polyline Coil(int n = 721) {
  Polyline p;
  p.points.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * kTurns * i / (n - 1);
    p.points.col(i) = Vec3(kPitch * a / (2 * std::numbers::pi), kCoilRadius * std::sin(a),
                           kCoilRadius * (1 - std::cos(a)));
  }
  p.ParameteriseByChords();
  return p;
}

// The coil clamped at its start, its other end free.
NetworkSpec CoilSpec(bool preformed, const Vec3& gravity) {
  const Polyline route = Coil();
  const double length = route.s[route.size() - 1];
  BranchSpec b;
  b.name = "coil";
  b.length = length;
  b.material = TestMaterial(0.01, 0.05, 0.004);
  b.route = route;
  b.preformed = preformed;
  const Vec3 tangent = (route.points.col(1) - route.points.col(0)).normalized();
  b.supports = {Clamp(0.0, route.points.col(0), tangent, Vec3::UnitZ().cross(tangent).cross(tangent))};
  NetworkSpec spec;
  spec.gravity = gravity;
  spec.branches = {b};
  return spec;
}

// Largest distance of the solution's nodes from the drawn coil at the same arc length.
double Deviation(const NetworkSpec& spec, const NetworkSolution& sol) {
  const Polyline& drawn = spec.branches[0].route;
  const Polyline& solved = sol.branches[0];
  double worst = 0.0;
  for (int i = 0; i < solved.size(); ++i) {
    const double s = solved.s[i] - solved.s[0];
    int k = 0;
    while (k + 2 < drawn.size() && drawn.s[k + 1] < s) ++k;
    const double w = std::clamp((s - drawn.s[k]) / (drawn.s[k + 1] - drawn.s[k]), 0.0, 1.0);
    const Vec3 at = (1 - w) * drawn.points.col(k) + w * drawn.points.col(k + 1);
    worst = std::max(worst, (Vec3(solved.points.col(i)) - at).norm());
  }
  return worst;
}

NetworkSolution Solve(const NetworkSpec& spec, double element_length = 0.005) {
  NetworkOptions opt;
  opt.element_length = element_length;
  return SolveNetwork(spec, opt);
}

// Largest distance between two solutions' nodes (same discretisation).
double Apart(const NetworkSolution& a, const NetworkSolution& b) {
  return (a.branches[0].points - b.branches[0].points).colwise().norm().maxCoeff();
}

// The elements are the coil's chords: unloaded it comes back as drawn up to their
// discretisation, which shrinks with the element length (a clamp's frame holding the curve's
// own tangent, not the first chord's, is part of the rest shape: else 4.45 mm off here).
TEST(NetworkPreformed, AnUnloadedPreformedCoilStaysAsDrawnToTheDiscretisation) {
  const NetworkSpec spec = CoilSpec(/*preformed=*/true, Vec3::Zero());
  const NetworkSolution coarse = Solve(spec, 0.005), fine = Solve(spec, 0.00125);
  ASSERT_TRUE(coarse.converged()) << coarse.summary.BriefReport();
  ASSERT_TRUE(fine.converged()) << fine.summary.BriefReport();
  const double at_coarse = Deviation(spec, coarse), at_fine = Deviation(spec, fine);
  std::printf("unloaded preformed coil off its drawing: %.3f mm (5 mm elements), %.3f mm (1.25 mm)\n",
              1e3 * at_coarse, 1e3 * at_fine);
  EXPECT_LT(at_fine, 0.35 * at_coarse);
  EXPECT_LT(at_coarse, 0.01 * kCoilRadius);
  EXPECT_LT(at_fine, 0.001 * kCoilRadius);
}

TEST(NetworkPreformed, AnUnloadedDefaultCoilSpringsOpen) {
  const NetworkSpec spec = CoilSpec(/*preformed=*/false, Vec3::Zero());
  const NetworkSolution sol = Solve(spec);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  // Straight rest shape, nothing to hold it: it ends up far from the coil.
  EXPECT_GT(Deviation(spec, sol), 2 * kCoilRadius);
}

TEST(NetworkPreformed, APreformedCoilOnlySagsUnderGravityAndADefaultOneDoesNot) {
  const Vec3 g(0, 0, -9.81);
  const NetworkSolution unloaded = Solve(CoilSpec(true, Vec3::Zero()));
  const NetworkSpec preformed = CoilSpec(true, g);
  const NetworkSolution coil = Solve(preformed);
  ASSERT_TRUE(coil.converged()) << coil.summary.BriefReport();
  const NetworkSpec plain = CoilSpec(false, g);
  const NetworkSolution hanging = Solve(plain);
  ASSERT_TRUE(hanging.converged()) << hanging.summary.BriefReport();
  // Its sag: from the same coil unloaded on the same elements.
  const double sag = Apart(coil, unloaded), fall = Deviation(plain, hanging);
  std::printf("coil of %.0f mm: preformed sags %.2f mm, default deviates %.1f mm\n",
              1e3 * preformed.branches[0].length, 1e3 * sag, 1e3 * fall);
  EXPECT_GT(sag, 1e-4);  // its weight does bend it
  EXPECT_LT(sag, 0.5 * kCoilRadius);
  EXPECT_GT(fall, 4 * sag);
  // Still a coil: it winds round its axis as drawn (the angle about x, unwrapped, end to end).
  const Polyline& c = coil.branches[0];
  double turned = 0.0;
  for (int i = 1; i < c.size(); ++i) {
    const double a0 = std::atan2(c.points(1, i - 1), kCoilRadius - c.points(2, i - 1));
    const double a1 = std::atan2(c.points(1, i), kCoilRadius - c.points(2, i));
    turned += std::remainder(a1 - a0, 2 * std::numbers::pi);
  }
  EXPECT_NEAR(std::abs(turned) / (2 * std::numbers::pi), kTurns, 0.25);
}

}  // namespace
}  // namespace cablefit
