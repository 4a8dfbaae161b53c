// A network solved to a requested accuracy the way a single rod is (RodSimulator): SolveNetwork
// at uniformly refined levels, driven by the shared refinement loop (refinement.h), with the
// branches' centrelines Richardson-extrapolated and the same error estimate.
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/solver/refinement.h"

namespace cablefit {

struct NetworkSimulation {
  /// The finest level solved, as solved (loads, contacts, junctions, summary: the failing
  /// level's when one failed, except an optional finer level: see refinement_failure).
  NetworkSolution finest;
  /// Per branch: the extrapolated node centreline at the finest level's nodes (the finest
  /// level's own when fewer than two levels converged).
  std::vector<Polyline> centerlines;
  double estimated_error = 0.0;     // [m] see RichardsonLevels::EstimatedError
  std::vector<int> level_elements;  // elements per level solved
  std::vector<StaticsSummary> level_summaries;  // per level solved (iterations, seconds, ...)
  /// The solve on elements four times as long that the first level starts from.
  StaticsSummary coarse_start;
  int coarse_start_elements = 0;
  int newton_iterations = 0;        // over all levels
  bool converged = false;           // every level converged
  bool accuracy_met = false;
  /// Non-empty when a level beyond the plan's min_levels failed (why it failed): the result is
  /// that of the levels before it, with their estimate.
  std::string refinement_failure;
  double seconds = 0.0;
};

/// Solves `spec` at levels of `options.element_length` x 2^-level (options.refinement is
/// ignored) as `plan` says. Throws InvalidInput for an invalid spec.
NetworkSimulation SimulateNetwork(const NetworkSpec& spec, const RefinementPlan& plan,
                                  const NetworkOptions& options = {});

}  // namespace cablefit
