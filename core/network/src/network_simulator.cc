#include "cablefit/core/network/network_simulator.h"

#include <chrono>

namespace cablefit {

NetworkSimulation SimulateNetwork(const NetworkSpec& spec, const RefinementPlan& plan,
                                  const NetworkOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  NetworkSimulation out;
  const RefinedSolution refined = SolveRefined(plan, [&](int level) {
    NetworkOptions at = options;
    at.refinement = level;
    out.finest = SolveNetwork(spec, at);
    out.level_elements.push_back(out.finest.num_elements);
    return LevelSolution{out.finest.branches, out.finest.summary};
  });
  out.centerlines = refined.levels.levels() > 0 ? refined.levels.Extrapolated()
                                                : out.finest.branches;
  out.estimated_error = refined.estimated_error;
  out.newton_iterations = refined.newton_iterations;
  out.converged = refined.converged;
  out.accuracy_met = refined.accuracy_met;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace cablefit
