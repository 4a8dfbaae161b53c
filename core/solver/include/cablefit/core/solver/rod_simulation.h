// Solving a set-up to a requested accuracy: the statics solver at a sequence of uniformly
// refined discretisations (each warm-started from the previous), Richardson extrapolation of
// the second-order error and its error estimate (richardson.h). A simulator keeps its levels so that a slightly changed set-up (what a fit
// does thousands of times) is re-solved warm at the same resolution.
#pragma once

#include <optional>
#include <vector>

#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/solver/centerline_sampling.h"
#include "cablefit/core/solver/rod_solution.h"
#include "cablefit/core/rod/rod_state.h"
#include "cablefit/core/solver/statics_solver.h"

namespace cablefit {

struct SimulationOptions {
  /// Requested accuracy of the centreline positions (estimated max error) [m].
  double accuracy = 1e-6;
  /// Element length of the coarsest level [m]; 0 = length / 24.
  double coarse_element_length = 0.0;
  /// At most this many levels (each doubles the elements).
  int max_levels = 7;
  /// At least this many levels (2 gives one extrapolation; 3 also an error estimate of it).
  int min_levels = 3;
  StaticsOptions statics;
  /// Newton options of Resimulate, when they differ from `statics`. A fit's re-solves take small
  /// parameter steps from an equilibrium: one that needs many iterations (or continuation) is a
  /// step too large, and failing it fast lets the fit take a smaller one instead.
  std::optional<StaticsOptions> resimulate_statics;

  bool IsValid(std::string* why) const;
};

struct SimulationResult {
  /// The finest level's full solution (frames, internal forces, summary) with its centreline
  /// and support reactions replaced by the extrapolated ones.
  RodSolution solution;
  /// [m] estimated max position error of solution.centerline, at its nodes and between them
  /// (as SampleCenterline reads it); infinite with one level or when a level failed.
  double estimated_error = 0.0;
  std::vector<int> level_elements;  // elements per level solved
  int newton_iterations = 0;        // over all levels
  double seconds = 0.0;
  bool converged = false;           // every level converged
  bool accuracy_met = false;
  double accuracy = 0.0;            ///< [m] the accuracy asked for (SimulationOptions::accuracy)
};

class RodSimulator {
 public:
  /// Invalid options are not an error here: like Ceres' Solve, every Simulate and Resimulate
  /// then returns at once with TerminationType::kInvalidOptions and the reason in the summary.
  explicit RodSimulator(SimulationOptions options = {});

  /// Cold solve: chooses the resolution for the requested accuracy. `initial` (may be null) is
  /// the shape to start from (any parameterisation; mapped onto [0, length]); without it a smooth
  /// curve through the supports is used. Throws InvalidInput for an invalid spec.
  SimulationResult Simulate(const RodSpec& spec, const Polyline* initial = nullptr);

  /// Cold solve from `initial` by Newton alone, without continuation: for a shape already near
  /// an equilibrium of `spec` (a solution of another discretisation), where a failure should
  /// come fast instead of after a path that may end on another equilibrium.
  SimulationResult SimulateNear(const RodSpec& spec, const Polyline& initial);

  /// Warm re-solve of a changed spec (same supports in number and order) at the levels of the
  /// last Simulate, each starting from its last solution.
  SimulationResult Resimulate(const RodSpec& spec);
  /// The same with the simulator's full Newton options (`statics`, continuation included) even
  /// where `resimulate_statics` is set: for a re-solve that must succeed if it can.
  SimulationResult ResimulatePatiently(const RodSpec& spec);

  bool has_solution() const { return !states_.empty(); }
  const SimulationOptions& options() const { return options_; }

 private:
  SimulationResult SimulateWith(const RodSpec& spec, const Polyline* initial,
                                const StaticsOptions& statics);
  SimulationResult ResimulateWith(const RodSpec& spec, const StaticsOptions& statics);
  SimulationResult Finish(std::vector<StaticsSummary> summaries, double seconds);
  bool RejectInvalidOptions(SimulationResult* result) const;

  SimulationOptions options_;
  std::vector<RodModel> models_;
  std::vector<RodState> states_;
  std::vector<int> span_elements_;
  double coarse_h_ = 0.0;
};

}  // namespace cablefit
