#include "effect_pair_search.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"
#include "effect_combination.h"
#include "place_scan.h"
#include "residual_bends.h"

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

// SharePartsOfTheBest: a rival that overtakes the best shares its part back, at most this many
// times (each pair is started from each best once).
constexpr int kSharedPartRounds = 3;

// How many of a residual's bends a placed effect starts at.
constexpr int kResidualBends = 2;

// A fine refit this many times worse than its coarse screening left the screening's branch.
constexpr double kBranchJump = 4.0;

// `sim` solved for `spec` from `shape`, a solution of the same spec on another level or of a
// nearby spec, by Newton alone: a path from there could only end on another equilibrium. False
// when it cannot be.
bool SolvedNear(RodSimulator* sim, const RodSpec& spec, const Polyline& shape) {
  try {
    return sim->SimulateNear(spec, shape).converged;
  } catch (const InvalidInput&) {
    return false;
  }
}

// `m` fitted from `x` on `base`'s fine model, its first solve started from `shape` (a fit's own
// equilibrium) instead of continued from the nominal's: a start far from the nominal (a strong
// anisotropy on a hanging drop) may otherwise come to rest on another equilibrium. Not ok when
// `shape` cannot be brought to `x`'s equilibrium; `solves` counts every forward solve.
Fit FitFromShape(const FitContext& ctx, const RodSimulator& base, EffectModel m,
                 const Eigen::VectorXd& x, const Polyline& shape, int max_iterations,
                 int* solves, int* iterations) {
  RodSimulator fine(base.options());
  ++*solves;
  if (!SolvedNear(&fine, m.apply(x), shape)) return {};
  m.starts = {x};
  Fit fit = FitEffect(ctx, {fine}, m, {max_iterations, 1, /*polish=*/true, /*patient_start=*/true});
  *solves += fit.forward_solves;
  *iterations += fit.lm_iterations;
  return fit;
}

// A fit point's cost (1/2 |offsets|^2 [m^2]), as a Fit's.
double PointCost(const FitPoint& p) { return 0.5 * p.offsets.squaredNorm(); }

bool HasResidualStarts(const EffectModel& pair, const std::vector<EffectModel>& singles) {
  for (int part : pair.parts)
    if (!singles[static_cast<size_t>(part)].residual_starts.empty()) return true;
  return false;
}

// A pair's start; `fitted_part` (0 or 1) when that part sits at its single fit and the other
// one is neutral: the start's solve, offsets and most of its Jacobian are the single fit's.
struct PairStart {
  Eigen::VectorXd x;
  int fitted_part = -1;
};

// Where a pair starts: from both single fits (each absorbed some of the other cause, so the sum
// overshoots, but it often lies in the right basin), and from every start of either effect with
// the other at its single fit: a single fit that absorbed the other cause can sit in the wrong
// basin of a non-convex effect (a curvature span's place and width, a contact's place, angles),
// or where its effect does nothing and has no gradient (a clamp compliance fitted to zero). A
// placed effect also starts where the other single fit's residual bends (residual_bends.h):
// the grid of places is the same on every layout, the residual's bends are where this
// recording's missing effect is. The same effect twice (two curvature spans, two contacts)
// starts its second copy at the effect's starts away from the fitted first. A contact also
// starts where the first-order scan of place_scan.h puts it (its bends miss it where the other
// fit took up its kink; its grid, at zero force beside a fit that absorbed part of it, moves
// little in a screening's few iterations); those starts are added once the single fits' coarse
// states are known.
std::vector<PairStart> PairStarts(const EffectModel& ma, const Fit& fa, const EffectModel& mb,
                                  const Fit& fb, bool same_model, const FitContext& ctx) {
  const double length = ctx.length;
  std::vector<PairStart> starts;
  auto with_a_fitted = [&](const Eigen::VectorXd& s) {
    starts.push_back({Concat(fa.x, s), mb.is_neutral(s) ? 0 : -1});
  };
  auto bent = [&](const EffectModel& m, const Fit& other) {
    if (!m.starts_at_bends || other.offsets.size() != 3 * ctx.s.size())
      return std::vector<Eigen::VectorXd>{};
    return m.starts_at_bends(FindResidualBends(other.offsets, ctx.s, length, kResidualBends));
  };
  if (same_model) {
    for (const Eigen::VectorXd& s : mb.starts)
      if (std::abs(s[0] - fa.x[0]) > 0.15 * length) with_a_fitted(s);
    for (const Eigen::VectorXd& s : bent(mb, fa))
      if (std::abs(s[0] - fa.x[0]) > 0.15 * length) with_a_fitted(s);
    return starts;
  }
  starts.push_back({Concat(fa.x, fb.x), -1});
  for (const Eigen::VectorXd& s : mb.starts) with_a_fitted(s);
  for (const Eigen::VectorXd& s : mb.residual_starts) with_a_fitted(s);
  for (const Eigen::VectorXd& s : bent(mb, fa)) with_a_fitted(s);
  for (const Eigen::VectorXd& s : ma.starts)
    starts.push_back({Concat(s, fb.x), ma.is_neutral(s) ? 1 : -1});
  for (const Eigen::VectorXd& s : bent(ma, fb))
    starts.push_back({Concat(s, fb.x), ma.is_neutral(s) ? 1 : -1});
  return starts;
}

// A single fit's state on the coarse level, from one of the nominal's equilibria.
struct PointKey {
  int single = 0;
  int branch = 0;
  bool operator<(const PointKey& o) const {
    return single != o.single ? single < o.single : branch < o.branch;
  }
};

// The start of pair `m` with part `fitted` at its single fit `point` and the other part
// neutral: the pair's offsets are the single's, the fitted part's Jacobian columns are the
// single's, the neutral part's non-amplitude columns are zero (where the effect has no strength
// its place does nothing); only its amplitude columns need differences.
LmStart KnownPairStart(const EffectModel& m, const std::vector<EffectModel>& singles, int fitted,
                       const FitPoint& point) {
  const int n = static_cast<int>(m.scale.size());
  LmStart st;
  st.residual = point.offsets;
  st.jacobian = Eigen::MatrixXd::Zero(point.offsets.size(), n);
  st.known_columns.assign(static_cast<size_t>(n), true);
  const int off = m.part_offsets[static_cast<size_t>(fitted)];
  st.jacobian.middleCols(off, point.jacobian.cols()) = point.jacobian;
  const int other = 1 - fitted;
  const EffectModel& mo = singles[static_cast<size_t>(m.parts[static_cast<size_t>(other)])];
  for (int i : mo.amplitudes)
    st.known_columns[static_cast<size_t>(m.part_offsets[static_cast<size_t>(other)] + i)] = false;
  return st;
}

// A pair's start whose entry in the start kinds is kWarmStart + part: solved from that part's
// single fit's coarse state, but with both parts away from it (a scanned place).
constexpr int kWarmStart = 2;

// How many places a scan starts a placed effect at.
constexpr int kScannedPlaces = 2;

// A scan of where a placed part of `pair` belongs, beside part `fitted` at its single fit.
struct ScanTask {
  int pair = 0;
  int fitted = 0;
  std::vector<PlaceExclusion> exclusions;  // the same effect's place, where fitted already
};

// Every pair with a part that has scan places, scanned beside its other part's single fit; the
// same effect twice is scanned once, away from its first copy (as PairStarts starts it).
std::vector<ScanTask> ScanTasks(const std::vector<EffectModel>& pairs,
                                const std::vector<EffectModel>& singles,
                                const std::vector<Fit>& single_fits, double length) {
  std::vector<ScanTask> tasks;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const EffectModel& m = pairs[k];
    for (int placed = 0; placed < 2; ++placed) {
      const int fitted = 1 - placed;
      const int single = m.parts[static_cast<size_t>(fitted)];
      if (singles[static_cast<size_t>(m.parts[static_cast<size_t>(placed)])].scan_places.empty())
        continue;
      ScanTask t{static_cast<int>(k), fitted, {}};
      if (m.parts[0] == m.parts[1]) {
        if (placed == 0) continue;
        t.exclusions.push_back({single_fits[static_cast<size_t>(single)].x[0], 0.15 * length});
      }
      tasks.push_back(t);
    }
  }
  return tasks;
}

}  // namespace

void PairSearch::KeepIfBetter(std::size_t k, Fit refit) {
  Fit& old = fits[k];
  forward_solves += refit.forward_solves;
  lm_iterations += refit.lm_iterations;
  if (!refit.ok || !(refit.cost < old.cost)) return;
  refit.forward_solves += old.forward_solves;
  refit.lm_iterations += old.lm_iterations;
  old = std::move(refit);
}

PairSearch SearchEffectPairs(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                             const std::vector<RodSimulator>& coarse,
                             const RodSpec& nominal, const std::vector<EffectModel>& singles,
                             const std::vector<Fit>& single_fits,
                             const PairSearchOptions& options) {
  const std::vector<int> members = Members(singles, single_fits, nominal);
  PairSearch out;
  std::vector<std::vector<int>> fitted_parts;  // per pair and start
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
      const std::vector<PairStart> starts =
          PairStarts(singles[static_cast<size_t>(first)], a_first ? fa : fb,
                     singles[static_cast<size_t>(second)], a_first ? fb : fa, a == b, ctx);
      fitted_parts.emplace_back();
      for (const PairStart& s : starts) {
        m.starts.push_back(s.x);
        fitted_parts.back().push_back(s.fitted_part);
      }
      out.models.push_back(std::move(m));
    }
  const int n = static_cast<int>(out.models.size());
  auto branch_of = [&](const EffectModel& m) {
    return single_fits[static_cast<size_t>(m.parts[0])].branch;
  };
  // 1. The single fits' states on the coarse level, on the branches of the pairs they start or
  //    scan from.
  std::map<PointKey, FitPoint> points;
  for (int k = 0; k < n; ++k)
    for (int fitted : fitted_parts[static_cast<size_t>(k)])
      if (fitted >= 0) {
        const EffectModel& m = out.models[static_cast<size_t>(k)];
        points[{m.parts[static_cast<size_t>(fitted)], branch_of(m)}];
      }
  const std::vector<ScanTask> scans = ScanTasks(out.models, singles, single_fits, ctx.length);
  for (const ScanTask& t : scans) {
    const EffectModel& m = out.models[static_cast<size_t>(t.pair)];
    points[{m.parts[static_cast<size_t>(t.fitted)], branch_of(m)}];
  }
  std::vector<std::pair<const PointKey, FitPoint>*> todo;
  for (auto& entry : points) todo.push_back(&entry);
  ParallelFor(static_cast<int>(todo.size()), options.threads, [&](int t) {
    const PointKey& key = todo[static_cast<size_t>(t)]->first;
    const EffectModel& model = singles[static_cast<size_t>(key.single)];
    const Fit& single = single_fits[static_cast<size_t>(key.single)];
    const RodSimulator& base = coarse[static_cast<size_t>(key.branch)];
    FitPoint& point = todo[static_cast<size_t>(t)]->second;
    point = EvaluateFitPoint(ctx, base, model, single.x);
    // Continued from the nominal's equilibrium, the coarse model may come to rest on another one
    // at a strong single fit (an anisotropic drop that turns over): every pair started beside
    // that fit would start from the wrong shape. Started from the fine fit's own shape, it is
    // evaluated where the fit is. (A point that could not be solved at all is left out as
    // before: its pairs start from their other starts.)
    if (!point.ok || PointCost(point) <= kBranchJump * single.cost) return;
    RodSimulator from_shape(base.options());
    int solves = point.forward_solves + 1;
    if (!SolvedNear(&from_shape, model.apply(single.x), single.solution.centerline)) {
      point.forward_solves = solves;
      return;
    }
    FitPoint again = EvaluateFitPoint(ctx, std::move(from_shape), model, single.x);
    solves += again.forward_solves;
    if (again.ok && PointCost(again) < PointCost(point)) point = std::move(again);
    point.forward_solves = solves;
  });
  for (const auto& [key, point] : points) out.forward_solves += point.forward_solves;
  // 1b. A placed effect joining a fit also starts where, to first order, it removes most of
  //     what that fit leaves (place_scan.h), warm at the fit's coarse state.
  std::vector<std::vector<Eigen::VectorXd>> scanned(scans.size());
  std::vector<int> scan_solves(scans.size(), 0);
  ParallelFor(static_cast<int>(scans.size()), options.threads, [&](int i) {
    const ScanTask& t = scans[static_cast<size_t>(i)];
    const EffectModel& m = out.models[static_cast<size_t>(t.pair)];
    const int single = m.parts[static_cast<size_t>(t.fitted)];
    const FitPoint& point = points.at({single, branch_of(m)});
    scanned[static_cast<size_t>(i)] =
        ScanPlaces(ctx, m, singles, t.fitted, single_fits[static_cast<size_t>(single)].x, point,
                   kScannedPlaces, t.exclusions, &scan_solves[static_cast<size_t>(i)]);
  });
  for (size_t i = 0; i < scans.size(); ++i) {
    out.forward_solves += scan_solves[i];
    EffectModel& m = out.models[static_cast<size_t>(scans[i].pair)];
    for (Eigen::VectorXd& x : scanned[i]) {
      m.starts.push_back(std::move(x));
      fitted_parts[static_cast<size_t>(scans[i].pair)].push_back(kWarmStart + scans[i].fitted);
    }
  }
  // 2. Every pair screened on the coarse level: a few iterations from its starts, the pairs in
  //    parallel; a start beside a single fit begins where that fit's state is.
  out.fits.resize(static_cast<size_t>(n));
  ParallelFor(n, options.threads, [&](int k) {
    const EffectModel& m = out.models[static_cast<size_t>(k)];
    const std::vector<int>& fitted = fitted_parts[static_cast<size_t>(k)];
    FitOptions screen{options.screen_iterations, 1, /*polish=*/false, /*patient_start=*/false,
                      options.start_iterations};
    screen.known_start = [&](int s, RodSimulator* sim) -> std::optional<LmStart> {
      const int kind = fitted[static_cast<size_t>(s)];
      if (kind < 0) return std::nullopt;
      const int part = kind >= kWarmStart ? kind - kWarmStart : kind;
      const FitPoint& point = points.at({m.parts[static_cast<size_t>(part)], branch_of(m)});
      if (!point.ok) return std::nullopt;
      *sim = point.sim;
      if (kind >= kWarmStart) return std::nullopt;  // only solved from there
      return KnownPairStart(m, singles, part, point);
    };
    Fit& f = out.fits[static_cast<size_t>(k)];
    f = FitEffect(ctx, {coarse[static_cast<size_t>(branch_of(m))]}, m, screen);
    f.branch = branch_of(m);
  });
  // 3. The most promising ones to their optimum on the fine model, from where the screening
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
    // A fine fit far worse than its screening went to another branch on the way (a loop that
    // flips as a twist comes in): it is fitted again from the screening's own shape.
    int solves = out.fits[k].forward_solves + refit.forward_solves;
    int iterations = out.fits[k].lm_iterations + refit.lm_iterations;
    if (!refit.ok || refit.cost > kBranchJump * out.fits[k].cost) {
      Fit again = FitFromShape(ctx, bases[static_cast<size_t>(refit.branch)], m, out.fits[k].x,
                               out.fits[k].solution.centerline, options.max_iterations, &solves,
                               &iterations);
      again.branch = refit.branch;
      if (again.ok && again.cost < refit.cost) refit = std::move(again);
    }
    // A placed effect added to another one's fit (a contact) has local optima the coarse
    // screening ranks in the wrong order: its second basin is carried on too.
    if (HasResidualStarts(m, singles) && !out.fits[k].other_basins.empty()) {
      m.starts = {out.fits[k].other_basins.front()};
      Fit second = FitEffect(ctx, {bases[static_cast<size_t>(out.fits[k].branch)]}, m,
                             {options.max_iterations, 1, /*polish=*/true, /*patient_start=*/true});
      solves += second.forward_solves;
      iterations += second.lm_iterations;
      second.branch = out.fits[k].branch;
      if (second.ok && (!refit.ok || second.cost < refit.cost)) refit = std::move(second);
    }
    refit.forward_solves = solves;
    refit.lm_iterations = iterations;
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

void DeepenPairSearch(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                      const std::vector<RodSimulator>& coarse, PairSearch* search,
                      const PairSearchOptions& options) {
  std::vector<int> order(search->fits.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(), [&](int p, int q) {
    return search->fits[static_cast<size_t>(p)].cost < search->fits[static_cast<size_t>(q)].cost;
  });
  order.resize(std::min(order.size(), static_cast<size_t>(options.deep_refits)));
  std::vector<Fit> deep(order.size());
  ParallelFor(static_cast<int>(order.size()), options.threads, [&](int r) {
    const size_t k = static_cast<size_t>(order[static_cast<size_t>(r)]);
    const size_t branch = static_cast<size_t>(search->fits[k].branch);
    const std::vector<RodSimulator> screen = {coarse[branch]};
    FitOptions fo{options.max_iterations, 1, /*polish=*/true, /*patient_start=*/false,
                  2 * options.screen_iterations};
    fo.kept_starts = 6;
    fo.screen_bases = &screen;
    Fit& f = deep[static_cast<size_t>(r)];
    f = FitEffect(ctx, {bases[branch]}, search->models[k], fo);
    f.branch = static_cast<int>(branch);
  });
  for (size_t r = 0; r < order.size(); ++r) {
    Fit& old = search->fits[static_cast<size_t>(order[r])];
    search->forward_solves += deep[r].forward_solves;
    search->lm_iterations += deep[r].lm_iterations;
    if (deep[r].ok && deep[r].cost < old.cost) {
      deep[r].forward_solves += old.forward_solves;
      deep[r].lm_iterations += old.lm_iterations;
      old = std::move(deep[r]);
    }
  }
}

namespace {

size_t BestFit(const std::vector<Fit>& fits) {
  size_t best = fits.size();
  for (size_t k = 0; k < fits.size(); ++k)
    if (fits[k].ok && (best == fits.size() || fits[k].cost < fits[best].cost)) best = k;
  return best;
}

// `m`'s parameters `x` with the part it shares with `bm` set to where `bx` has it; nullopt when
// they share none (the same effect twice is not a part to share: its copies are not
// interchangeable).
std::optional<Eigen::VectorXd> WithSharedPart(const EffectModel& m, const Eigen::VectorXd& x,
                                              const EffectModel& bm, const Eigen::VectorXd& bx,
                                              const std::vector<EffectModel>& singles) {
  if (bm.parts[0] == bm.parts[1] || m.parts[0] == m.parts[1]) return std::nullopt;
  for (int part = 0; part < 2; ++part)
    for (int bpart = 0; bpart < 2; ++bpart)
      if (m.parts[static_cast<size_t>(part)] == bm.parts[static_cast<size_t>(bpart)]) {
        Eigen::VectorXd y = x;
        const Eigen::VectorXd from = PartParameters(bm, singles, bpart, bx);
        y.segment(m.part_offsets[static_cast<size_t>(part)], from.size()) = from;
        return y;
      }
  return std::nullopt;
}

}  // namespace

void SharePartsOfTheBest(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                         const std::vector<EffectModel>& singles, PairSearch* search,
                         const PairSearchOptions& options) {
  // A rival that overtakes the best shares its part back: rounds until the best stays.
  std::vector<std::pair<size_t, size_t>> tried;  // (pair, the best it was started from)
  for (int round = 0; round < kSharedPartRounds; ++round) {
    const size_t best = BestFit(search->fits);
    if (best == search->fits.size()) return;
    const EffectModel& bm = search->models[best];
    const Fit& bf = search->fits[best];
    struct Reseed {
      size_t pair = 0;
      Fit fit;
    };
    std::vector<Reseed> reseeds;
    const Polyline& best_shape = bf.solution.centerline;  // the best is not refitted below
    for (size_t k = 0; k < search->fits.size(); ++k) {
      const Fit& f = search->fits[k];
      if (k == best || !f.ok || f.cost > options.shared_part_range * bf.cost) continue;
      if (std::find(tried.begin(), tried.end(), std::make_pair(k, best)) != tried.end()) continue;
      const std::optional<Eigen::VectorXd> x =
          WithSharedPart(search->models[k], f.x, bm, bf.x, singles);
      if (!x) continue;
      tried.emplace_back(k, best);
      Reseed r;
      r.pair = k;
      r.fit.x = *x;
      reseeds.push_back(std::move(r));
    }
    if (reseeds.empty()) return;
    ParallelFor(static_cast<int>(reseeds.size()), options.threads, [&](int i) {
      Reseed& r = reseeds[static_cast<size_t>(i)];
      EffectModel m = search->models[r.pair];
      const Eigen::VectorXd x = r.fit.x;
      m.starts = {x};
      const Fit& old = search->fits[r.pair];
      const size_t base = static_cast<size_t>(old.branch);
      r.fit = FitEffect(ctx, {bases[base]}, m,
                        {options.max_iterations, 1, /*polish=*/true, /*patient_start=*/true});
      // A reseed far worse than the pair was, from a start that shares the best pair's part, came
      // to rest on another equilibrium on its way from the nominal: it starts again from the
      // best pair's shape, the one it was meant to reach.
      if (!r.fit.ok || r.fit.cost > kBranchJump * old.cost) {
        int solves = r.fit.forward_solves, iterations = r.fit.lm_iterations;
        Fit again = FitFromShape(ctx, bases[base], m, x, best_shape, options.max_iterations,
                                 &solves, &iterations);
        if (again.ok && (!r.fit.ok || again.cost < r.fit.cost)) r.fit = std::move(again);
        r.fit.forward_solves = solves;
        r.fit.lm_iterations = iterations;
      }
      r.fit.branch = old.branch;
    });
    for (Reseed& r : reseeds) search->KeepIfBetter(static_cast<std::size_t>(r.pair), std::move(r.fit));
    if (BestFit(search->fits) == best) return;
  }
}

void CheckPartsAlone(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                     const std::vector<EffectModel>& singles, PairSearch* pairs,
                     std::vector<Fit>* single_fits, const PairSearchOptions& options) {
  const PairSearch& search = *pairs;
  std::vector<int> order;
  for (size_t k = 0; k < search.fits.size(); ++k)
    if (search.fits[k].ok) order.push_back(static_cast<int>(k));
  std::stable_sort(order.begin(), order.end(), [&](int p, int q) {
    return search.fits[static_cast<size_t>(p)].cost < search.fits[static_cast<size_t>(q)].cost;
  });
  order.resize(std::min(order.size(), static_cast<size_t>(options.backward_checks)));
  struct Check {
    int single = 0;
    Fit fit;
  };
  std::vector<Check> checks;
  for (int k : order)
    for (int part = 0; part < 2; ++part) {
      const EffectModel& pair = search.models[static_cast<size_t>(k)];
      Check c;
      c.single = pair.parts[static_cast<size_t>(part)];
      c.fit.x = PartParameters(pair, singles, part, search.fits[static_cast<size_t>(k)].x);
      c.fit.branch = search.fits[static_cast<size_t>(k)].branch;
      checks.push_back(std::move(c));
    }
  ParallelFor(static_cast<int>(checks.size()), options.threads, [&](int i) {
    Check& c = checks[static_cast<size_t>(i)];
    EffectModel m = singles[static_cast<size_t>(c.single)];
    m.starts = {c.fit.x};
    const int branch = c.fit.branch;
    c.fit = FitEffect(ctx, {bases[static_cast<size_t>(branch)]}, m,
                      {options.max_iterations, 1, /*polish=*/true, /*patient_start=*/true});
    c.fit.branch = branch;
  });
  // In a fixed order, so that the same single checked from two pairs keeps the same winner.
  for (Check& c : checks) {
    pairs->forward_solves += c.fit.forward_solves;
    pairs->lm_iterations += c.fit.lm_iterations;
    Fit& old = (*single_fits)[static_cast<size_t>(c.single)];
    if (c.fit.ok && c.fit.cost < old.cost) old = std::move(c.fit);
  }
}

}  // namespace cablefit
