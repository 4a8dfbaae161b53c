// The refinement loop every simulation runs, single rod or network: solve level 0, 1, ...
// (each halving every element of the one before, warm-started from it by the caller) until the
// Richardson extrapolation's estimated error meets the requested accuracy. One place decides
// how many levels a set-up gets, so rods and networks are judged by the same estimate.
#pragma once

#include <functional>
#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/solver/richardson.h"
#include "cablefit/core/solver/statics_solver.h"

namespace cablefit {

/// What one level's solve hands the loop.
struct LevelSolution {
  std::vector<Polyline> branches;  // node centrelines, one per branch (s [m], 3 x n [m])
  StaticsSummary summary;
};

struct RefinementPlan {
  double accuracy = 1e-6;  // [m] requested estimated max position error
  int min_levels = 3;      // solved even when the estimate is met earlier
  int max_levels = 7;      // never more
  /// Stop before max_levels when the levels left cannot meet the accuracy (SolveRefined). Off
  /// for single rods (a finer level's failure is reported there, not skipped); on for the
  /// network groups of relax (PlanNetworkRelax), whose levels are the expensive part.
  bool stop_when_out_of_reach = false;
};

struct RefinedSolution {
  RichardsonLevels levels;                 // centrelines of every converged level
  std::vector<StaticsSummary> summaries;   // of every level solved; only the last can have failed
  bool converged = false;                  // every level solved converged
  /// [m] RichardsonLevels::EstimatedError of the converged levels (infinite with fewer than
  /// two, or when a level failed).
  double estimated_error = 0.0;
  bool accuracy_met = false;               // converged and estimated_error <= accuracy
  int newton_iterations = 0;               // over all levels
  /// Stopped before max_levels because the levels left could not meet the accuracy at the rate
  /// the estimate was falling (at best 16x per level, fourth order): accuracy_met is false.
  bool stopped_early = false;
};

/// Calls solve_level(0), solve_level(1), ... until a level fails, or `plan.min_levels` are solved
/// and the estimate meets `plan.accuracy`, or `plan.max_levels` are solved, or (after
/// `plan.min_levels`, with `plan.stop_when_out_of_reach`) the levels left could not bring the estimate down to `plan.accuracy` even
/// at the rate it last fell by (16x per level, fourth order, until two estimates from
/// extrapolations can be compared, from the fourth level on; never faster than that).
RefinedSolution SolveRefined(const RefinementPlan& plan,
                             const std::function<LevelSolution(int level)>& solve_level);

}  // namespace cablefit
