// Warm re-solves as a fit uses them: a budget of their own (fail fast on a step too large), a
// failed one leaves the simulator at its last equilibrium, and a patient one may still continue.
#include <gtest/gtest.h>

#include "cablefit/core/solver/rod_simulation.h"
#include "network_test_util.h"

namespace cablefit {
namespace {

RodSpec SaggingRod(double density) {
  RodSpec s;
  s.name = "sag";
  s.length = 1.0;
  s.material = testing::TestMaterial(0.05, density, 0.008);
  s.supports = {testing::Clamp(0.0, Vec3::Zero(), Vec3::UnitX()),
                testing::Clamp(1.0, Vec3(0.6, 0, 0), -Vec3::UnitX())};
  return s;
}

SimulationOptions TwoLevelsWithWarmBudget(int warm_iterations) {
  SimulationOptions o;
  o.min_levels = o.max_levels = 2;
  StaticsOptions warm = o.statics;
  warm.max_iterations = warm_iterations;
  warm.max_continuation_steps = 0;
  warm.ramp_loads = true;
  o.resimulate_statics = warm;
  return o;
}

double LargestGap(const Polyline& a, const Polyline& b) {
  const Eigen::VectorXd at = UniformArcLengths(1.0, 51);
  return (SampleCenterline(a, at).points - SampleCenterline(b, at).points).colwise().norm().maxCoeff();
}

TEST(WarmResimulate, AFailedReSolveLeavesTheLastEquilibrium) {
  RodSimulator sim(TwoLevelsWithWarmBudget(1));
  const SimulationResult first = sim.Simulate(SaggingRod(0.1));
  ASSERT_TRUE(first.converged);
  // Forty times heavier: one Newton iteration cannot get there.
  const SimulationResult failed = sim.Resimulate(SaggingRod(4.0));
  EXPECT_FALSE(failed.converged);
  // Back to the first set-up: already in equilibrium, so no iteration at all, and the same shape.
  const SimulationResult again = sim.Resimulate(SaggingRod(0.1));
  ASSERT_TRUE(again.converged) << again.solution.summary.message;
  EXPECT_EQ(again.newton_iterations, 0);
  EXPECT_LT(LargestGap(again.solution.centerline, first.solution.centerline), 1e-12);
}

TEST(WarmResimulate, APatientReSolveUsesTheFullOptions) {
  RodSimulator sim(TwoLevelsWithWarmBudget(1));
  ASSERT_TRUE(sim.Simulate(SaggingRod(0.1)).converged);
  const SimulationResult patient = sim.ResimulatePatiently(SaggingRod(4.0));
  ASSERT_TRUE(patient.converged) << patient.solution.summary.message;
  RodSimulator cold(TwoLevelsWithWarmBudget(1));
  const SimulationResult reference = cold.Simulate(SaggingRod(4.0));
  ASSERT_TRUE(reference.converged);
  EXPECT_LT(LargestGap(patient.solution.centerline, reference.solution.centerline), 1e-7);
}

TEST(WarmResimulate, AnInvalidWarmBudgetIsReportedLikeAnyInvalidOption) {
  SimulationOptions o = TwoLevelsWithWarmBudget(1);
  o.resimulate_statics->max_iterations = -1;
  std::string why;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_FALSE(why.empty());
}

// A solution of another discretisation is solved again by Newton alone, to the same shape.
TEST(SimulateNear, AnotherLevelsSolutionIsSolvedWithoutContinuation) {
  SimulationOptions coarse;
  coarse.min_levels = coarse.max_levels = 1;
  RodSimulator c(coarse);
  const SimulationResult from = c.Simulate(SaggingRod(1.0));
  ASSERT_TRUE(from.converged);
  RodSimulator near(TwoLevelsWithWarmBudget(8));
  const SimulationResult r = near.SimulateNear(SaggingRod(1.0), from.solution.centerline);
  ASSERT_TRUE(r.converged) << r.solution.summary.message;
  EXPECT_EQ(r.solution.summary.continuation_steps, 0);
  RodSimulator cold(TwoLevelsWithWarmBudget(8));
  const SimulationResult reference = cold.Simulate(SaggingRod(1.0));
  ASSERT_TRUE(reference.converged);
  EXPECT_LT(LargestGap(r.solution.centerline, reference.solution.centerline), 1e-9);
}

// Far from an equilibrium, with a Newton budget too small to get there directly, it fails
// without a path; Simulate from the same shape with the same budget gets there by one.
TEST(SimulateNear, FailsWhereOnlyAPathWouldGetThere) {
  SimulationOptions few = TwoLevelsWithWarmBudget(8);
  few.statics.max_iterations = 4;
  RodSimulator light(TwoLevelsWithWarmBudget(8));
  const SimulationResult shape = light.Simulate(SaggingRod(0.1));
  ASSERT_TRUE(shape.converged);
  RodSimulator near(few);
  const SimulationResult direct = near.SimulateNear(SaggingRod(4.0), shape.solution.centerline);
  EXPECT_FALSE(direct.converged);
  EXPECT_EQ(direct.solution.summary.continuation_steps, 0);
  RodSimulator path(few);
  const SimulationResult continued = path.Simulate(SaggingRod(4.0), &shape.solution.centerline);
  EXPECT_TRUE(continued.converged) << continued.solution.summary.message;
}

}  // namespace
}  // namespace cablefit
