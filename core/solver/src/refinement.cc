#include "cablefit/core/solver/refinement.h"

#include <limits>

namespace cablefit {

RefinedSolution SolveRefined(const RefinementPlan& plan,
                             const std::function<LevelSolution(int level)>& solve_level) {
  RefinedSolution out;
  out.converged = true;
  double estimate = std::numeric_limits<double>::infinity();
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
  }
  out.estimated_error = out.converged ? estimate : std::numeric_limits<double>::infinity();
  out.accuracy_met = out.converged && out.estimated_error <= plan.accuracy;
  return out;
}

}  // namespace cablefit
