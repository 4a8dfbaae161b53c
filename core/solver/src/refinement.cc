#include "cablefit/core/solver/refinement.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cablefit {
namespace {

// The fastest the estimate falls per halving of the elements: fourth order (2^4), what Richardson
// extrapolation of a second-order scheme gives where the solution is smooth.
constexpr double kBestRatePerLevel = 16.0;

}  // namespace

RefinedSolution SolveRefined(const RefinementPlan& plan,
                             const std::function<LevelSolution(int level)>& solve_level) {
  RefinedSolution out;
  out.converged = true;
  double estimate = std::numeric_limits<double>::infinity();
  double previous = std::numeric_limits<double>::infinity();  // the estimate from one level fewer
  for (int level = 0; level < plan.max_levels; ++level) {
    LevelSolution solved = solve_level(level);
    out.newton_iterations += solved.summary.iterations;
    out.summaries.push_back(solved.summary);
    if (!solved.summary.converged()) {
      out.converged = false;
      break;
    }
    out.levels.Add(std::move(solved.branches));
    estimate = out.levels.EstimatedError().total();
    if (level + 1 >= plan.min_levels && estimate <= plan.accuracy) break;
    // The levels left cannot meet the accuracy even at the rate the estimate fell by from the
    // previous level (at most kBestRatePerLevel, the fourth order the extrapolation gives on a
    // smooth shape; that rate until there is a previous rate to take): stop rather than pay for
    // levels that end unmet anyway. With two levels the estimate is the finer level's own
    // error, a different measure than the later ones, so the first rate comes from the fourth level.
    const int left = plan.max_levels - (level + 1);
    const double rate = level >= 3 && std::isfinite(previous) && estimate > 0
                            ? std::clamp(previous / estimate, 1.0, kBestRatePerLevel)
                            : kBestRatePerLevel;
    if (plan.stop_when_out_of_reach && level + 1 >= plan.min_levels && left > 0 &&
        estimate > plan.accuracy * std::pow(rate, left)) {
      out.stopped_early = true;
      break;
    }
    previous = estimate;
  }
  out.estimated_error = out.converged ? estimate : std::numeric_limits<double>::infinity();
  out.accuracy_met = out.converged && out.estimated_error <= plan.accuracy;
  return out;
}

}  // namespace cablefit
