// Fitting one effect model to the thinned recording: Levenberg-Marquardt on the offsets of the
// seen points from the simulated curve, warm-starting every forward solve from the last,
// multi-start where the problem is not convex, from every equilibrium of the nominal.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "levenberg_marquardt.h"
#include "shape_effects.h"

namespace cablefit {

/// The points the fits compare against and how the simulated curve is sampled.
struct FitContext {
  Eigen::Matrix3Xd points;  // 3 x n [m] thinned observation points
  Eigen::VectorXd s;        // n [m] their arc lengths
  double length = 0.0;      // [m] the cable's
  double window = 0.0;      // [m] how far along the curve a point's closest point is searched
  int curve_samples = 0;    // the simulated curve is resampled uniformly at this many points
};

/// The context for `points` at arc lengths `s` on a cable of `length`.
FitContext MakeFitContext(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& s,
                          double length);

struct Fit {
  Eigen::VectorXd x;        // the model's fit parameters
  double cost = INFINITY;   // 1/2 |offsets|^2 [m^2]
  Eigen::VectorXd offsets;  // 3n [m] offsets of the thinned points from the fitted curve
  RodSolution solution;     // the fitted solve (centreline: warm start of the final solve)
  int branch = 0;           // which equilibrium of the nominal the fit started from
  bool converged = false;   // the best run's Levenberg-Marquardt stopped on a minimum
  bool ok = false;          // false: no start could be solved
  int forward_solves = 0;   // over every start and run of the fit
  int lm_iterations = 0;
  /// Where the other distinct basins a screened fit kept ended, best first: a screening ranks
  /// basins only roughly, and a later fit may carry one of them on too.
  std::vector<Eigen::VectorXd> other_basins;
};

/// The fits' cost (1/2 |offsets|^2 [m^2]) of `spec` solved warm from `sim` (patiently);
/// INFINITY when it cannot be solved. `offsets` and `solution` (may be null) receive the rest.
double EvaluateFitCost(const FitContext& ctx, RodSimulator sim, const RodSpec& spec,
                       Eigen::VectorXd* offsets = nullptr, RodSolution* solution = nullptr);

/// The thinned points' offsets (3n [m]) from `spec` solved warm from `sim` by Newton alone, no
/// continuation (a small change of the spec `sim` is at); false when that solve fails.
bool FitOffsets(const FitContext& ctx, RodSimulator* sim, const RodSpec& spec,
                Eigen::VectorXd* offsets);

struct FitOptions {
  int max_iterations = 30;  // Levenberg-Marquardt iterations per start
  int threads = 1;          // the starts run in parallel, with the same result as on one
  /// A best run stopped by its iteration limit is carried on (a fit compared with others must
  /// reach its optimum); false where the fit only ranks candidates for a later fit.
  bool polish = true;
  /// Each start's first solve may use the solver's continuation: needed where a start is far
  /// from the equilibria it is solved from (a single effect from the nominal). False where the
  /// starts come from fits that were solved already: a start that a plain Newton solve cannot
  /// reach is then dropped at once instead of being continued for seconds.
  bool patient_start = true;
  /// With more than two starts, each start runs this many iterations first and only the
  /// `kept_starts` best distinct ones are carried on.
  int start_iterations = 4;
  int kept_starts = 3;
  /// Where the starts are screened (one simulator per base, same order), when not the bases
  /// themselves: the coarse level ranks starts at a third of the cost, and the kept ones are
  /// carried on from where it left them on the bases.
  const std::vector<RodSimulator>* screen_bases = nullptr;
  /// Starts whose state is known already (a pair started with one effect at its single fit and
  /// the other at zero strength: the single fit's solve, offsets and Jacobian are the pair's).
  /// Given a start's index and its run's simulator, it sets the simulator warm at the start and
  /// returns the start's offsets and known Jacobian columns; nullopt: the start runs cold.
  std::function<std::optional<LmStart>(int start, RodSimulator* sim)> known_start = nullptr;
};

/// A model's state at x: solved warm from `sim` (without continuation), the thinned points'
/// offsets from it and their Jacobian by forward differences.
struct FitPoint {
  RodSimulator sim;          // warm at x
  Eigen::VectorXd offsets;   // 3n [m]
  Eigen::MatrixXd jacobian;  // 3n x x.size() [m per parameter unit]
  int forward_solves = 0;
  bool ok = false;           // false: x or a difference could not be solved
};

/// `model` at `x` from `sim`.
FitPoint EvaluateFitPoint(const FitContext& ctx, RodSimulator sim,
                                         const EffectModel& model, const Eigen::VectorXd& x);

/// The best fit of `model`, started from every simulator in `bases` (one per equilibrium of the
/// nominal, each warm).
Fit FitEffect(const FitContext& ctx, const std::vector<RodSimulator>& bases,
              const EffectModel& model, const FitOptions& options);

}  // namespace cablefit
