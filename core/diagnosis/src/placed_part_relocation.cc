#include "placed_part_relocation.h"

#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"
#include "effect_combination.h"
#include "place_scan.h"

namespace cablefit {
namespace {

// How many other places a placed part is refitted from.
constexpr int kOtherPlaces = 2;

// One placed part of one pair to check.
struct Check {
  size_t pair = 0;
  int placed = 0;  // the part moved
  std::vector<Eigen::VectorXd> starts;
  int solves = 0;
};

}  // namespace

void RelocatePlacedParts(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                         const std::vector<RodSimulator>& coarse,
                         const std::vector<EffectModel>& singles, PairSearch* search,
                         const PairSearchOptions& options) {
  std::vector<size_t> order;
  for (size_t k = 0; k < search->fits.size(); ++k) {
    const EffectModel& m = search->models[k];
    bool placed = false;
    for (int part : m.parts)
      placed = placed || !singles[static_cast<size_t>(part)].scan_places.empty();
    if (search->fits[k].ok && placed) order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t p, size_t q) { return search->fits[p].cost < search->fits[q].cost; });
  order.resize(std::min(order.size(), static_cast<size_t>(options.relocated_pairs)));
  std::vector<Check> checks;
  for (size_t k : order)
    for (int placed = 0; placed < 2; ++placed)
      if (!singles[static_cast<size_t>(search->models[k].parts[static_cast<size_t>(placed)])]
               .scan_places.empty())
        checks.push_back({k, placed, {}, 0});
  // 1. Each check's scan, from the other part alone at its pair values on the coarse level,
  //    solved from the pair's own shape (the nominal's equilibrium may be far from it).
  ParallelFor(static_cast<int>(checks.size()), options.threads, [&](int i) {
    Check& c = checks[static_cast<size_t>(i)];
    const EffectModel& m = search->models[c.pair];
    const Fit& f = search->fits[c.pair];
    const int fitted = 1 - c.placed;
    const EffectModel& other = singles[static_cast<size_t>(m.parts[static_cast<size_t>(fitted)])];
    const Eigen::VectorXd x_other = PartParameters(m, singles, fitted, f.x);
    const Eigen::VectorXd x_placed = PartParameters(m, singles, c.placed, f.x);
    RodSimulator sim(coarse[static_cast<size_t>(f.branch)].options());
    ++c.solves;
    try {
      if (!sim.SimulateNear(other.apply(x_other), f.solution.centerline).converged) return;
    } catch (const InvalidInput&) {
      return;
    }
    const FitPoint point = EvaluateFitPoint(ctx, std::move(sim), other, x_other);
    c.solves += point.forward_solves;
    // Not where the part is (the pair's fit is there already), nor where the same effect's
    // other copy is.
    std::vector<PlaceExclusion> exclusions = {{x_placed[0], 0.1 * ctx.length}};
    if (m.parts[0] == m.parts[1]) exclusions.push_back({x_other[0], 0.15 * ctx.length});
    c.starts =
        ScanPlaces(ctx, m, singles, fitted, x_other, point, kOtherPlaces, exclusions, &c.solves);
  });
  // 2. The pair refitted from every place found, on the fine level.
  struct Refit {
    size_t pair = 0;
    Eigen::VectorXd x;
    Fit fit;
  };
  std::vector<Refit> refits;
  for (Check& c : checks) {
    search->forward_solves += c.solves;
    for (Eigen::VectorXd& x : c.starts) refits.push_back({c.pair, std::move(x), {}});
  }
  ParallelFor(static_cast<int>(refits.size()), options.threads, [&](int i) {
    Refit& r = refits[static_cast<size_t>(i)];
    EffectModel m = search->models[r.pair];
    m.starts = {r.x};
    const int branch = search->fits[r.pair].branch;
    r.fit = FitEffect(ctx, {bases[static_cast<size_t>(branch)]}, m,
                      {options.max_iterations, 1, /*polish=*/true, /*patient_start=*/true});
    r.fit.branch = branch;
  });
  // In a fixed order, so that the result does not depend on the threads.
  for (Refit& r : refits) search->KeepIfBetter(static_cast<std::size_t>(r.pair), std::move(r.fit));
}

}  // namespace cablefit
