// A cable drawn straight between two clamps has no slack: under gravity an inextensible cable
// cannot hang there and the solve fails. The failure must say why, for a single rod and for a
// network, and a cable with a little slack must still solve.
#include <gtest/gtest.h>

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

TEST(TautStretch, NetworkFailureNamesTheTautStretch) {
  NetworkSpec spec;
  BranchSpec b;
  b.name = "taut";
  b.length = 0.8;
  b.material = TestMaterial(0.05, 0.1, 0.008);
  b.route = StraightRoute(Vec3::Zero(), Vec3(0.8, 0, 0));
  b.supports = {Clamp(0.0, Vec3::Zero(), Vec3::UnitX()), Clamp(0.8, Vec3(0.8, 0, 0), Vec3::UnitX())};
  spec.branches = {b};
  NetworkOptions opt;
  opt.element_length = 0.01;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  ASSERT_FALSE(sol.converged());
  EXPECT_NE(sol.summary.message.find("taut"), std::string::npos) << sol.summary.message;
}

TEST(TautStretch, ALittleSlackStillHangs) {
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(StraightRod(0.8 * (1 + 1e-3)));
  EXPECT_TRUE(r.converged) << r.solution.summary.BriefReport();
  EXPECT_LT(r.solution.centerline.points.row(2).minCoeff(), -0.001);  // it sags
}

}  // namespace
}  // namespace cablefit
