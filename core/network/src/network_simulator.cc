#include "cablefit/core/network/network_simulator.h"

#include <chrono>
#include <string>

namespace cablefit {

NetworkSimulation SimulateNetwork(const NetworkSpec& spec, const RefinementPlan& plan,
                                  const NetworkOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  NetworkSimulation out;
  NetworkSolution last_converged;
  const RefinedSolution refined = SolveRefined(plan, [&](int level) {
    NetworkOptions at = options;
    at.refinement = level;
    // A finer level starts from the coarser level's equilibrium: a few Newton steps instead of
    // a cold solve from the drawing (on a 27-branch harness 35-51 iterations per level).
    // Contact can defeat that start (nodes between the coarse ones cut into an edge the coarse
    // level rested on): then the level is solved cold, as it was before.
    if (level > 0 && out.finest.converged()) {
      at.initial_routes = out.finest.branches;
      at.initial_normals = out.finest.element_normals;
    }
    out.finest = SolveNetwork(spec, at);
    if (!out.finest.converged() && !at.initial_routes.empty()) {
      at.initial_routes.clear();
      at.initial_normals.clear();
      out.finest = SolveNetwork(spec, at);
    }
    out.level_elements.push_back(out.finest.num_elements);
    if (out.finest.converged()) last_converged = out.finest;
    return LevelSolution{out.finest.branches, out.finest.summary};
  });
  out.centerlines = refined.levels.levels() > 0 ? refined.levels.Extrapolated()
                                                : out.finest.branches;
  out.estimated_error = refined.estimated_error;
  out.newton_iterations = refined.newton_iterations;
  out.converged = refined.converged;
  out.accuracy_met = refined.accuracy_met;
  // Every level is a cold solve with its own contact set, and a finer one can fail where the
  // coarser ones held (a contact set cycling over a sharp edge). The levels the plan requires
  // converged, so their extrapolation and honest estimate stand; the failure is reported.
  const int kept = refined.levels.levels();
  if (!refined.converged && kept >= plan.min_levels && kept >= 1) {
    out.refinement_failure = out.finest.summary.message.empty()
                                 ? std::string(ToString(out.finest.summary.termination))
                                 : out.finest.summary.message;
    out.finest = std::move(last_converged);
    out.level_elements.pop_back();
    out.converged = true;
    out.estimated_error = refined.levels.EstimatedError().total();
    out.accuracy_met = out.estimated_error <= plan.accuracy;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace cablefit
