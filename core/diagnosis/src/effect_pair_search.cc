#include "effect_pair_search.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "cablefit/core/base/parallel_for.h"
#include "effect_combination.h"

namespace cablefit {
namespace {

// The single models that take part in pairs: fitted, not the nominal, and not the twin of an
// earlier one (a twist preload at either clamp of a cable that only feels the twist between them
// is one effect: its pairs would be fitted twice).
std::vector<int> Members(const std::vector<EffectModel>& singles, const std::vector<Fit>& fits,
                         const RodSpec& nominal) {
  std::vector<int> members;
  for (size_t i = 0; i < singles.size(); ++i) {
    if (singles[i].effect == ShapeEffect::kNone || !fits[i].ok) continue;
    bool twin = false;
    for (int j : members) {
      const EffectModel& o = singles[static_cast<size_t>(j)];
      twin = twin || (o.effect == ShapeEffect::kTwistPreload && o.effect == singles[i].effect &&
                      !CanCombine(o, singles[i], nominal));
    }
    if (!twin) members.push_back(static_cast<int>(i));
  }
  return members;
}

Eigen::VectorXd Concat(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd x(a.size() + b.size());
  x << a, b;
  return x;
}

// Where a pair starts: from both single fits (each absorbed some of the other cause, so the sum
// overshoots, but it often lies in the right basin), and from every start of either effect with
// the other at its single fit: a single fit that absorbed the other cause can sit in the wrong
// basin of a non-convex effect (a curvature span's place and width, a contact's place, angles),
// or where its effect does nothing and has no gradient (a clamp compliance fitted to zero). The
// same effect twice (two curvature spans, two contacts) starts its second copy at the effect's
// starts away from the fitted first.
std::vector<Eigen::VectorXd> PairStarts(const EffectModel& ma, const Fit& fa, const EffectModel& mb,
                                        const Fit& fb, bool same_model, double length) {
  std::vector<Eigen::VectorXd> starts;
  if (same_model) {
    for (const Eigen::VectorXd& s : mb.starts)
      if (std::abs(s[0] - fa.x[0]) > 0.15 * length) starts.push_back(Concat(fa.x, s));
    return starts;
  }
  starts.push_back(Concat(fa.x, fb.x));
  for (const Eigen::VectorXd& s : mb.starts) starts.push_back(Concat(fa.x, s));
  for (const Eigen::VectorXd& s : ma.starts) starts.push_back(Concat(s, fb.x));
  return starts;
}

}  // namespace

PairSearch SearchEffectPairs(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                             const std::vector<RodSimulator>& coarse,
                             const RodSpec& nominal, const std::vector<EffectModel>& singles,
                             const std::vector<Fit>& single_fits,
                             const PairSearchOptions& options) {
  const std::vector<int> members = Members(singles, single_fits, nominal);
  PairSearch out;
  for (size_t i = 0; i < members.size(); ++i)
    for (size_t j = i; j < members.size(); ++j) {
      const int a = members[i], b = members[j];
      const EffectModel& ma = singles[static_cast<size_t>(a)];
      const EffectModel& mb = singles[static_cast<size_t>(b)];
      if (!CanCombine(ma, mb, nominal)) continue;
      const Fit& fa = single_fits[static_cast<size_t>(a)];
      const Fit& fb = single_fits[static_cast<size_t>(b)];
      // The better single fit's equilibrium is the pair's.
      const bool a_first = fa.cost <= fb.cost;
      const int first = a_first ? a : b, second = a_first ? b : a;
      EffectModel m = CombineEffects(singles, first, second);
      const Fit& f1 = a_first ? fa : fb;
      const Fit& f2 = a_first ? fb : fa;
      m.starts = PairStarts(singles[static_cast<size_t>(first)], f1,
                            singles[static_cast<size_t>(second)], f2, a == b, nominal.length);
      out.models.push_back(std::move(m));
    }
  // 1. Every pair screened on the coarse level: a few iterations from its starts, the pairs in
  //    parallel.
  const int n = static_cast<int>(out.models.size());
  out.fits.resize(static_cast<size_t>(n));
  auto branch_of = [&](const EffectModel& m) {
    return single_fits[static_cast<size_t>(m.parts[0])].branch;
  };
  ParallelFor(n, options.threads, [&](int k) {
    const EffectModel& m = out.models[static_cast<size_t>(k)];
    Fit& f = out.fits[static_cast<size_t>(k)];
    f = FitEffect(ctx, {coarse[static_cast<size_t>(branch_of(m))]}, m,
                  {options.screen_iterations, 1, /*polish=*/false, /*patient_start=*/false,
                   options.start_iterations});
    f.branch = branch_of(m);
  });
  // 2. The most promising ones to their optimum on the fine model, from where the screening
  //    left them.
  std::vector<int> order(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) order[static_cast<size_t>(k)] = k;
  std::stable_sort(order.begin(), order.end(), [&](int p, int q) {
    return out.fits[static_cast<size_t>(p)].cost < out.fits[static_cast<size_t>(q)].cost;
  });
  order.resize(std::min(order.size(), static_cast<size_t>(options.refits)));
  ParallelFor(static_cast<int>(order.size()), options.threads, [&](int r) {
    const size_t k = static_cast<size_t>(order[static_cast<size_t>(r)]);
    if (!out.fits[k].ok) return;
    EffectModel m = out.models[k];
    m.starts = {out.fits[k].x};
    // On the fine model, which the screening's coarse solves only approximate: its first solve
    // may need the continuation.
    Fit refit = FitEffect(ctx, {bases[static_cast<size_t>(out.fits[k].branch)]}, m,
                          {options.max_iterations, 1, /*polish=*/true, /*patient_start=*/true});
    refit.branch = out.fits[k].branch;
    refit.forward_solves += out.fits[k].forward_solves;
    refit.lm_iterations += out.fits[k].lm_iterations;
    out.fits[k] = std::move(refit);
  });
  for (const Fit& f : out.fits) {
    out.forward_solves += f.forward_solves;
    out.lm_iterations += f.lm_iterations;
  }
  // Only the pairs carried to their optimum are candidates: a screened fit is not a result.
  std::vector<EffectModel> models;
  std::vector<Fit> fits;
  std::sort(order.begin(), order.end());
  for (int k : order) {
    models.push_back(std::move(out.models[static_cast<size_t>(k)]));
    fits.push_back(std::move(out.fits[static_cast<size_t>(k)]));
  }
  out.models = std::move(models);
  out.fits = std::move(fits);
  return out;
}

}  // namespace cablefit
