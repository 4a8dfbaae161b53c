#include "cablefit/core/solver/rod_simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/solver/refinement.h"

namespace cablefit {
namespace {

using Clock = std::chrono::steady_clock;

// The coarsest level has at least this many elements per span: one element would give the
// extrapolation's interpolated correction no neighbour to interpolate from.
constexpr int kMinCoarseSpanElements = 2;
// Coarsest element length without an explicit one: a fraction of the length that resolves a
// cable's sag and its bending length near clamps on typical set-ups (finer levels follow).
constexpr double kCoarseElementsPerLength = 24.0;

std::vector<int> SpanCounts(const RodSpec& spec, double h0) {
  const std::vector<double> bp = SpanBreakpoints(spec);
  std::vector<int> counts;
  for (size_t k = 0; k + 1 < bp.size(); ++k)
    counts.push_back(std::max(kMinCoarseSpanElements,
                              static_cast<int>(std::ceil((bp[k + 1] - bp[k]) / h0 - 1e-9))));
  return counts;
}

Polyline NodeCenterline(const RodModel& model, const RodState& state) {
  Polyline p;
  p.s = model.node_s;
  p.points = state.NodePositions(model);
  return p;
}

}  // namespace

bool SimulationOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(accuracy > 0)) return fail("accuracy must be > 0");
  if (coarse_element_length < 0) return fail("coarse_element_length must be >= 0");
  if (min_levels < 1 || max_levels < min_levels) return fail("need 1 <= min_levels <= max_levels");
  if (resimulate_statics && !resimulate_statics->IsValid(why)) return false;
  return statics.IsValid(why);
}

RodSimulator::RodSimulator(SimulationOptions options) : options_(std::move(options)) {}

bool RodSimulator::RejectInvalidOptions(SimulationResult* result) const {
  std::string why;
  if (options_.IsValid(&why)) return false;
  *result = SimulationResult{};
  result->solution.summary.termination = TerminationType::kInvalidOptions;
  result->solution.summary.message = "invalid simulation options: " + why;
  result->estimated_error = std::numeric_limits<double>::infinity();
  return true;
}

SimulationResult RodSimulator::Simulate(const RodSpec& spec, const Polyline* initial) {
  return SimulateWith(spec, initial, options_.statics);
}

SimulationResult RodSimulator::SimulateNear(const RodSpec& spec, const Polyline& initial) {
  StaticsOptions direct = options_.statics;
  direct.max_continuation_steps = 0;
  return SimulateWith(spec, &initial, direct);
}

SimulationResult RodSimulator::SimulateWith(const RodSpec& spec, const Polyline* initial,
                                            const StaticsOptions& statics) {
  const auto t0 = Clock::now();
  SimulationResult rejected;
  if (RejectInvalidOptions(&rejected)) return rejected;
  ValidateRodSpec(spec);
  models_.clear();
  states_.clear();
  const double h0 = options_.coarse_element_length > 0 ? options_.coarse_element_length
                                                        : spec.length / kCoarseElementsPerLength;
  coarse_h_ = h0;
  span_elements_ = SpanCounts(spec, h0);
  const Polyline curve = initial ? ReparameteriseToLength(*initial, spec.length)
                                 : DefaultInitialCurve(spec);
  RefinementPlan plan;
  plan.accuracy = options_.accuracy;
  plan.min_levels = options_.min_levels;
  plan.max_levels = options_.max_levels;
  const RefinedSolution refined = SolveRefined(plan, [&](int level) {
    Discretisation disc;
    disc.elements_per_span = span_elements_;
    disc.refinement = level;
    models_.push_back(CompileRodModel(spec, disc));
    const RodModel& model = models_.back();
    RodState state = level == 0 ? MakeInitialState(model, curve)
                                : TransferState(models_[level - 1], states_[level - 1], model);
    LevelSolution solved;
    solved.summary = SolveStatics(model, &state, statics);
    solved.branches = {NodeCenterline(model, state)};
    states_.push_back(std::move(state));
    return solved;
  });
  return Finish(refined.summaries, std::chrono::duration<double>(Clock::now() - t0).count());
}

SimulationResult RodSimulator::Resimulate(const RodSpec& spec) {
  return ResimulateWith(spec, options_.resimulate_statics.value_or(options_.statics));
}

SimulationResult RodSimulator::ResimulatePatiently(const RodSpec& spec) {
  return ResimulateWith(spec, options_.statics);
}

SimulationResult RodSimulator::ResimulateWith(const RodSpec& spec, const StaticsOptions& statics) {
  CABLEFIT_REQUIRE(!states_.empty(), "Resimulate needs a previous Simulate");
  const auto t0 = Clock::now();
  SimulationResult rejected;
  if (RejectInvalidOptions(&rejected)) return rejected;
  ValidateRodSpec(spec);
  std::vector<StaticsSummary> summaries;
  // A failed re-solve leaves the simulator where it was: the next one (a fit's smaller step)
  // starts from the last equilibrium, not from the failed solve's far-off iterate.
  std::vector<RodModel> last_models = models_;
  std::vector<RodState> last_states = states_;
  const std::vector<int> last_spans = span_elements_;
  // A changed layout (a point load moved, a support added) gets new spans of the same size.
  if (SpanBreakpoints(spec).size() != span_elements_.size() + 1 ||
      spec.length != models_[0].length)
    span_elements_ = SpanCounts(spec, coarse_h_);
  for (size_t level = 0; level < models_.size(); ++level) {
    Discretisation disc;
    disc.elements_per_span = span_elements_;
    disc.refinement = static_cast<int>(level);
    RodModel model = CompileRodModel(spec, disc);
    RodState state = TransferState(models_[level], states_[level], model);
    StaticsSummary sum = SolveStatics(model, &state, statics);
    models_[level] = std::move(model);
    states_[level] = std::move(state);
    summaries.push_back(sum);
    if (!sum.converged()) break;
  }
  SimulationResult result =
      Finish(summaries, std::chrono::duration<double>(Clock::now() - t0).count());
  if (!result.converged) {
    models_ = std::move(last_models);
    states_ = std::move(last_states);
    span_elements_ = last_spans;
  }
  return result;
}

SimulationResult RodSimulator::Finish(std::vector<StaticsSummary> summaries, double seconds) {
  SimulationResult r;
  r.accuracy = options_.accuracy;
  r.seconds = seconds;
  r.converged = !summaries.empty() && std::all_of(summaries.begin(), summaries.end(),
                                                  [](const StaticsSummary& s) { return s.converged(); });
  for (const auto& s : summaries) r.newton_iterations += s.iterations;
  const int nl = static_cast<int>(summaries.size());
  for (int l = 0; l < nl; ++l) r.level_elements.push_back(models_[l].num_elements);
  const int fin = nl - 1;
  r.solution = ExtractSolution(models_[fin], states_[fin], summaries[fin]);
  r.solution.summary.iterations = r.newton_iterations;
  r.solution.summary.seconds = seconds;
  r.estimated_error = std::numeric_limits<double>::infinity();
  if (r.converged && nl >= 2) {
    RichardsonLevels levels;
    for (int l = 0; l < nl; ++l) levels.Add({NodeCenterline(models_[l], states_[l])});
    r.solution.centerline = levels.Extrapolated().front();
    r.estimated_error = levels.EstimatedError().total();
    const RodSolution coarse = ExtractSolution(models_[fin - 1], states_[fin - 1], summaries[fin - 1]);
    for (size_t k = 0; k < r.solution.reactions.size(); ++k) {
      auto& a = r.solution.reactions[k];
      const auto& b = coarse.reactions[k];
      a.force = ExtrapolateRichardson(a.force, b.force);
      a.moment = ExtrapolateRichardson(a.moment, b.moment);
    }
  }
  r.accuracy_met = r.converged && r.estimated_error <= options_.accuracy;
  return r;
}

}  // namespace cablefit
