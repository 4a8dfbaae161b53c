#include "found_effects.h"

#include <algorithm>
#include <cmath>

#include "cablefit/core/solver/rod_simulation.h"
#include "curve_projection.h"
#include "effect_combination.h"

namespace cablefit {
namespace {

// Half the squared offsets of the thinned points from a centreline (the fits' cost) [m^2].
double ThinnedCost(const FitContext& ctx, const Polyline& centerline) {
  const Polyline curve =
      SampleCenterline(centerline, UniformArcLengths(ctx.length, ctx.curve_samples));
  return 0.5 * ProjectOntoCurve(curve, ctx.points, ctx.s, ctx.window).offset.squaredNorm();
}

// Where two centrelines differ most, at the recorded points' arc lengths (the span where the
// distance exceeds half its maximum).
std::pair<double, double> WhereTheyDiffer(const Polyline& a, const Polyline& b,
                                          const Eigen::VectorXd& s) {
  const Polyline pa = SampleCenterline(a, s), pb = SampleCenterline(b, s);
  const Eigen::VectorXd d = (pa.points - pb.points).colwise().norm().transpose();
  return MismatchInterval(s, d);
}

FoundEffect Describe(const EffectModel& model, const Eigen::VectorXd& x,
                     const EffectDescriptionContext& context) {
  EffectDescription d = model.describe(x, context);
  FoundEffect f;
  f.effect = model.effect;
  f.clamp = model.clamp;
  f.interval = d.interval;
  f.parameters = std::move(d.parameters);
  f.vectors = std::move(d.vectors);
  f.units = std::move(d.units);
  return f;
}

}  // namespace

std::vector<FoundEffect> DescribeFoundEffects(const PreparedRecording& recording,
                                              const FitContext& ctx,
                                              const std::vector<EffectModel>& models,
                                              std::size_t chosen, const Eigen::VectorXd& x,
                                              const FinalSolves& final_solves,
                                              std::pair<double, double> mismatch) {
  const EffectModel& model = models[chosen];
  if (model.effect == ShapeEffect::kNone) return {};
  const double c0 = ThinnedCost(ctx, final_solves.nominal.centerline);
  const double c_all = ThinnedCost(ctx, final_solves.fitted.centerline);
  auto fraction = [c0](double gain) { return c0 > 0 ? gain / c0 : 0.0; };
  EffectDescriptionContext context;
  context.solution = &final_solves.fitted;
  if (!model.is_combination()) {
    context.mismatch = mismatch;
    FoundEffect f = Describe(model, x, context);
    f.share = fraction(c0 - c_all);
    return {f};
  }
  // Each part alone (the other left out), solved from the joint fit's shape.
  const Polyline& shape = final_solves.fitted.centerline;
  const size_t n = model.parts.size();
  std::vector<double> alone_cost(n, INFINITY);
  std::vector<Polyline> without(n);
  for (size_t p = 0; p < n; ++p) {
    const RodSpec spec = WithoutPart(model, models, static_cast<int>(p)).apply(x);
    SimulationResult r = RodSimulator().Simulate(spec, &shape);
    if (!r.converged) r = RodSimulator().Simulate(spec, &recording.initial);
    if (!r.converged) continue;
    without[p] = r.solution.centerline;
    alone_cost[1 - p] = ThinnedCost(ctx, without[p]);  // two parts: leaving one out keeps the other
  }
  // What each part adds to the joint fit: the mismatch that comes back when it is left out. The
  // part the whole fit removes is shared in proportion (each part alone can even make the
  // mismatch worse when the other part compensates it, so gains alone would not add up).
  std::vector<double> adds(n, NAN);
  double sum = 0.0;
  for (size_t p = 0; p < n; ++p) {
    if (!std::isfinite(alone_cost[1 - p])) continue;
    adds[p] = std::max(0.0, alone_cost[1 - p] - c_all);
    sum += adds[p];
  }
  const double removed = fraction(c0 - c_all);
  std::vector<FoundEffect> found;
  for (size_t p = 0; p < n; ++p) {
    const EffectModel& part = models[static_cast<size_t>(model.parts[p])];
    context.mismatch = without[p].size() > 1
                           ? WhereTheyDiffer(shape, without[p], recording.s)
                           : mismatch;
    FoundEffect f = Describe(part, PartParameters(model, models, static_cast<int>(p), x), context);
    f.share = std::isfinite(adds[p]) ? removed * (sum > 0 ? adds[p] / sum : 1.0 / n) : NAN;
    found.push_back(std::move(f));
  }
  std::stable_sort(found.begin(), found.end(), [](const FoundEffect& a, const FoundEffect& b) {
    const double sa = std::isnan(a.share) ? -INFINITY : a.share;
    const double sb = std::isnan(b.share) ? -INFINITY : b.share;
    return sa > sb;
  });
  return found;
}

}  // namespace cablefit
