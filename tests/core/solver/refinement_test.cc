// The refinement loop's stopping rules (SolveRefined): it stops when the estimate meets the
// accuracy, and stops early when the levels left could not meet it at the rate the estimate
// is falling, but not while they still could.
#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/core/solver/refinement.h"

namespace cablefit {
namespace {

// A level whose single branch converges at first order only: node k of 4 * 2^level elements on
// [0, 1] m sits at (s, kError * h, 0), h the element length. The extrapolation removes no error
// here, so the estimate halves per level (Richardson's 4x or 16x are not reached).
constexpr double kError = 1e-3;  // [m per m of element length]

LevelSolution FirstOrderLevel(int level) {
  const int ne = 4 << level;
  const double h = 1.0 / ne;
  Polyline p;
  p.s.resize(ne + 1);
  p.points.resize(3, ne + 1);
  for (int k = 0; k <= ne; ++k) {
    p.s[k] = k * h;
    p.points.col(k) = Vec3(k * h, kError * h, 0.0);
  }
  LevelSolution out;
  out.branches = {p};
  out.summary.termination = TerminationType::kConverged;
  out.summary.iterations = 1;
  return out;
}

TEST(SolveRefined, StopsWhenTheLevelsLeftCannotMeetTheAccuracyAtTheRateTheEstimateFalls) {
  RefinementPlan plan;
  plan.min_levels = 2;
  plan.max_levels = 7;
  plan.stop_when_out_of_reach = true;
  plan.accuracy = 1e-8;  // the estimate halves per level: 7 levels end near 1e-6 m
  int solved = 0;
  const RefinedSolution out = SolveRefined(plan, [&](int level) {
    ++solved;
    return FirstOrderLevel(level);
  });
  EXPECT_TRUE(out.converged);
  EXPECT_TRUE(out.stopped_early);
  EXPECT_FALSE(out.accuracy_met);
  // The fourth level gives the first rate (2x); 2^3 more cannot take ~7e-6 m to 1e-8 m.
  EXPECT_EQ(solved, 4);
  EXPECT_EQ(out.levels.levels(), 4);
  EXPECT_GT(out.estimated_error, plan.accuracy * 8);
}

TEST(SolveRefined, GoesOnWhileTheLevelsLeftCanStillMeetTheAccuracy) {
  RefinementPlan plan;
  plan.min_levels = 2;
  plan.max_levels = 7;
  plan.stop_when_out_of_reach = true;
  plan.accuracy = 1e-6;  // met at the seventh level, at 2x per level
  const RefinedSolution out = SolveRefined(plan, FirstOrderLevel);
  EXPECT_FALSE(out.stopped_early);
  EXPECT_TRUE(out.accuracy_met);
  EXPECT_EQ(out.levels.levels(), 7);
  EXPECT_LE(out.estimated_error, plan.accuracy);
  EXPECT_GT(out.estimated_error, 0.25 * plan.accuracy);  // the estimate did fall at first order
}

TEST(SolveRefined, WithoutTheFlagEveryLevelIsSolved) {
  RefinementPlan plan;
  plan.min_levels = 2;
  plan.max_levels = 7;
  plan.accuracy = 1e-8;
  const RefinedSolution out = SolveRefined(plan, FirstOrderLevel);
  EXPECT_FALSE(out.stopped_early);
  EXPECT_EQ(out.levels.levels(), 7);
}

TEST(SolveRefined, AMetAccuracyStopsAtTheMinimumLevels) {
  RefinementPlan plan;
  plan.min_levels = 2;
  plan.max_levels = 7;
  plan.stop_when_out_of_reach = true;
  plan.accuracy = 1e-3;
  const RefinedSolution out = SolveRefined(plan, FirstOrderLevel);
  EXPECT_TRUE(out.accuracy_met);
  EXPECT_FALSE(out.stopped_early);
  EXPECT_EQ(out.levels.levels(), 2);
}

}  // namespace
}  // namespace cablefit
