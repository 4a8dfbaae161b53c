// A cable drawn straight between two clamps has no slack: under gravity an inextensible cable
// cannot hang there and the solve fails. The failure must say why, for a single rod and for a
// network, and a cable with a little slack must still solve. With its axial stiffness EA the
// same cable stretches and hangs with a finite tension, that of an elastic string.
#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "network_test_util.h"

namespace cablefit {
namespace {

using testing::Clamp;
using testing::StraightRoute;
using testing::TestMaterial;

RodSpec StraightRod(double length) {
  RodSpec s;
  s.name = "taut";
  s.length = length;
  s.material = TestMaterial(0.05, 0.1, 0.008);
  s.supports = {Clamp(0.0, Vec3::Zero(), Vec3::UnitX()), Clamp(length, Vec3(0.8, 0, 0), Vec3::UnitX())};
  return s;
}

TEST(TautStretch, SingleRodFailureNamesTheTautStretch) {
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(StraightRod(0.8));
  ASSERT_FALSE(r.converged);
  EXPECT_NE(r.solution.summary.message.find("taut"), std::string::npos) << r.solution.summary.message;
  EXPECT_NE(r.solution.summary.message.find("0.8 m apart"), std::string::npos) << r.solution.summary.message;
}

// A one-branch network drawn straight between two clamps 0.8 m apart.
NetworkSolution SolveStraightNetwork(const MaterialSpec& material) {
  NetworkSpec spec;
  BranchSpec b;
  b.name = "taut";
  b.length = 0.8;
  b.material = material;
  b.route = StraightRoute(Vec3::Zero(), Vec3(0.8, 0, 0));
  b.supports = {Clamp(0.0, Vec3::Zero(), Vec3::UnitX()), Clamp(0.8, Vec3(0.8, 0, 0), Vec3::UnitX())};
  spec.branches = {b};
  NetworkOptions opt;
  opt.element_length = 0.01;
  return SolveNetwork(spec, opt);
}

TEST(TautStretch, NetworkFailureNamesTheTautStretch) {
  const NetworkSolution sol = SolveStraightNetwork(TestMaterial(0.05, 0.1, 0.008));
  ASSERT_FALSE(sol.converged());
  EXPECT_NE(sol.summary.message.find("taut"), std::string::npos) << sol.summary.message;
}

TEST(TautStretch, ALittleSlackStillHangs) {
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(StraightRod(0.8 * (1 + 1e-3)));
  EXPECT_TRUE(r.converged) << r.solution.summary.BriefReport();
  EXPECT_LT(r.solution.centerline.points.row(2).minCoeff(), -0.001);  // it sags
}

// A taut elastic string of span L, weight w per length and axial stiffness EA: its stretch
// T L / EA is the parabola's extra length 8 d^2 / (3 L) at sag d = w L^2 / (8 T), so
// T^3 = w^2 L^2 EA / 24 (Irvine, "Cable Structures", 1981, ch. 2, for small sag). A flexible
// cable (bending length sqrt(EI / T) of a few mm on a 0.8 m span) follows it within the bending
// boundary layers at the clamps.
TEST(TautStretch, WithAxialStiffnessATautSpanHangsWithTheElasticStringsTension) {
  for (const double ea : {1e3, 1e4, 1e5}) {
    RodSpec spec = StraightRod(0.8);
    spec.material = TestMaterial(1e-4, 0.1, 0.008);
    spec.material.axial_stiffness = ea;
    RodSimulator sim;
    const SimulationResult r = sim.Simulate(spec);
    ASSERT_TRUE(r.converged) << "EA " << ea << ": " << r.solution.summary.BriefReport();
    const double w = 0.1 * 9.81, L = 0.8;
    const double tension = std::cbrt(w * w * L * L * ea / 24.0);
    const double horizontal = std::abs(r.solution.reactions[1].force.x());
    EXPECT_NEAR(horizontal / tension, 1.0, 0.05) << "EA " << ea << " N";
    const double sag = -r.solution.centerline.points.row(2).minCoeff();
    EXPECT_NEAR(sag / (w * L * L / (8 * tension)), 1.0, 0.08) << "EA " << ea << " N";
    EXPECT_TRUE(r.solution.summary.stable);
  }
}

// With slack the tension is orders below EA, so the stretch changes the shape by a tiny amount:
// the extensible cable agrees with the inextensible one to within T / EA of the span.
TEST(TautStretch, AxialStiffnessBarelyMovesACableWithSlack) {
  RodSpec spec = StraightRod(0.9);
  RodSimulator sim;
  const SimulationResult rigid = sim.Simulate(spec);
  spec.material.axial_stiffness = 1e6;
  const SimulationResult elastic = sim.Simulate(spec);
  ASSERT_TRUE(rigid.converged && elastic.converged);
  const double difference =
      (rigid.solution.centerline.points - elastic.solution.centerline.points).colwise().norm().maxCoeff();
  EXPECT_LT(difference, 1e-5);
  EXPECT_GT(difference, 0.0);
}

TEST(TautStretch, NetworkWithAxialStiffnessHangsToo) {
  MaterialSpec material = TestMaterial(1e-4, 0.1, 0.008);
  material.axial_stiffness = 1e4;
  const NetworkSolution sol = SolveStraightNetwork(material);
  EXPECT_TRUE(sol.converged()) << sol.summary.message;
}

}  // namespace
}  // namespace cablefit
