// How the statics solver and the simulator report each error tier: invalid options and a failed
// solve are a summary (like Ceres' Solve), a progress callback returning false cancels (one
// mechanism with the time limit), and calling out of order is caller misuse.
#include <gtest/gtest.h>

#include <string>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/core/solver/statics_solver.h"
#include "network_test_util.h"

namespace cablefit {
namespace {

// Hangs between two clamps closer than its length.
RodSpec SaggingRod() {
  RodSpec s;
  s.name = "sag";
  s.length = 1.0;
  s.material = testing::TestMaterial(0.05, 0.1, 0.008);
  s.supports = {testing::Clamp(0.0, Vec3::Zero(), Vec3::UnitX()),
                testing::Clamp(1.0, Vec3(0.6, 0, 0), -Vec3::UnitX())};
  return s;
}

TEST(StaticsErrorTiers, InvalidOptionsAreASummaryNotAnAbort) {
  const RodSpec spec = SaggingRod();
  const RodModel model = CompileRodModel(spec);
  RodState state = MakeInitialState(model, DefaultInitialCurve(spec));
  const RodState before = state;
  StaticsOptions options;
  options.max_iterations = 0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  for (const StaticsSummary& sum :
       {SolveStatics(model, &state, options), SolveStaticsDirect(model, &state, options)}) {
    EXPECT_EQ(sum.termination, TerminationType::kInvalidOptions);
    EXPECT_FALSE(sum.converged());
    EXPECT_NE(sum.message.find(why), std::string::npos) << sum.message;
    EXPECT_EQ(sum.iterations, 0);
  }
  EXPECT_TRUE(state.q == before.q);  // nothing was solved
}

TEST(StaticsErrorTiers, ASimulatorWithInvalidOptionsSolvesNothingAndSaysWhy) {
  SimulationOptions options;
  options.min_levels = 4;
  options.max_levels = 2;
  std::string why;
  ASSERT_FALSE(options.IsValid(&why));
  RodSimulator sim(options);  // constructing is fine: the solve reports it
  const SimulationResult r = sim.Simulate(SaggingRod());
  EXPECT_EQ(r.solution.summary.termination, TerminationType::kInvalidOptions);
  EXPECT_NE(r.solution.summary.message.find(why), std::string::npos) << r.solution.summary.message;
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.accuracy_met);
  EXPECT_TRUE(r.level_elements.empty());
  EXPECT_FALSE(sim.has_solution());

  // Invalid statics options inside valid simulation options are reported the same way.
  SimulationOptions inner;
  inner.statics.max_iterations = 0;
  const SimulationResult r2 = RodSimulator(inner).Simulate(SaggingRod());
  EXPECT_EQ(r2.solution.summary.termination, TerminationType::kInvalidOptions);
  EXPECT_FALSE(r2.converged);
}

TEST(StaticsErrorTiers, AProgressCallbackReturningFalseThrowsCancelled) {
  const RodSpec spec = SaggingRod();
  const RodModel model = CompileRodModel(spec);
  int calls = 0;
  StaticsOptions options;
  options.progress = [&calls](double, const std::string&) { return ++calls < 2; };
  options.max_iterations = 1;  // the direct solve cannot converge: continuation reports
  RodState state = MakeInitialState(model, DefaultInitialCurve(spec));
  const CancellationScope scope;
  EXPECT_THROW(SolveStatics(model, &state, options), Cancelled);
  EXPECT_EQ(calls, 2);
  EXPECT_TRUE(CancellationRequested());
}

TEST(StaticsErrorTiers, ResimulateBeforeSimulateIsCallerMisuse) {
  RodSimulator sim;
  EXPECT_THROW(sim.Resimulate(SaggingRod()), UsageError);
}

}  // namespace
}  // namespace cablefit
