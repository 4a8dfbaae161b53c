// Which pair of effects explains a recording that no single effect does. Every pair the
// catalogue allows is screened by a few Levenberg-Marquardt iterations of the joint fit, started
// from the two single fits (each has absorbed some of the other cause, but they lie in the right
// basin), from one single fit with the other effect at its neutral start (what a forward
// selection step would start from) and, for a contact, from the places where it removes most of
// the other single fit's residual to first order, that fit refitted alongside (place_scan.h);
// the most promising pairs are then fitted to their optimum.
// A forward selection from the best single fit alone misses a pair whose causes that fit has
// mixed up, and its fits over every start of the added effect cost more than screening all pairs.
// The selection (model_selection) then weighs the pairs against the single effects: a pair must
// win its place by the information criterion (each effect paying the same margin), and its fit
// must hold in the accurate solve, so one cause stays one effect.
#pragma once

#include <vector>

#include "cablefit/core/rod/rod_spec.h"
#include "effect_fit.h"
#include "shape_effects.h"

namespace cablefit {

struct PairSearchOptions {
  int max_iterations = 30;    // Levenberg-Marquardt iterations of a pair carried to its optimum
  int screen_iterations = 6;  // ... of every pair's screening
  int start_iterations = 4;   // ... of each start before the screening keeps the best three
  int refits = 8;             // how many of the best screened pairs are carried to the optimum
  int deep_refits = 3;        // how many of the best pairs DeepenPairSearch fits again
  int backward_checks = 2;    // how many of the best pairs CheckPartsAlone takes apart
  /// How many of the best pairs with a placed part RelocatePlacedParts checks.
  int relocated_pairs = 4;
  /// SharePartsOfTheBest refits a pair sharing a part with the best one when its cost is within
  /// this factor of the best's.
  double shared_part_range = 100.0;
  int threads = 1;            // the pairs run in parallel (same result on any count)
};

struct PairSearch {
  std::vector<EffectModel> models;  // combinations (parts index the single models)
  std::vector<Fit> fits;            // one per model
  int forward_solves = 0;
  int lm_iterations = 0;

  /// A refit of model `k`: its cost counted, and kept when better than the fit there (which
  /// then carries the cost of both).
  void KeepIfBetter(std::size_t k, Fit refit);
};

/// The pairs worth weighing, each fitted jointly to its optimum. `singles` and `single_fits` are
/// the single effects and their fits (`none` among them); `bases` the nominal's equilibria they
/// started from, `coarse` the same on the coarse level (the screening's forward model).
PairSearch SearchEffectPairs(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                             const std::vector<RodSimulator>& coarse,
                             const RodSpec& nominal, const std::vector<EffectModel>& singles,
                             const std::vector<Fit>& single_fits, const PairSearchOptions& options);

/// Where even the best pair leaves more than the noise, its screening may have left the true
/// pair in a wrong basin (the few iterations per start rank basins only roughly): the
/// `deep_refits` best pairs of `search` are fitted again, every start carried further and more
/// of them kept, on the fine level. A fit is replaced where the new one is better.
void DeepenPairSearch(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                      const std::vector<RodSimulator>& coarse, PairSearch* search,
                      const PairSearchOptions& options);

/// A pair that shares a part (the same single effect at the same place) with the best pair of
/// `search` and fits within `shared_part_range` of it is fitted again with that part started
/// where the best pair has it: a point-like part (a contact's place, a curvature span's ends)
/// has local optima, and a rival pair stuck in one of them loses to the best pair by a margin
/// its other part does not deserve (seen: a contact 12 mm off left a clamp compliance 34x worse
/// than the clamp mis-set it actually was). Replaced where the new fit is better.
void SharePartsOfTheBest(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                         const std::vector<EffectModel>& singles, PairSearch* search,
                         const PairSearchOptions& options);

/// The backward check: each part of the `backward_checks` best pairs of `search` is fitted alone, started
/// from its parameters in the pair. A pair whose second part does (almost) nothing has found a
/// better optimum of its first part than that single fit did (the single's starts can all lie
/// in a wrong basin); the single fit is then replaced, so that the selection weighs the pair
/// against the single effect at its best, and a second effect must earn its place.
void CheckPartsAlone(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                     const std::vector<EffectModel>& singles, PairSearch* search,
                     std::vector<Fit>* single_fits, const PairSearchOptions& options);

}  // namespace cablefit
