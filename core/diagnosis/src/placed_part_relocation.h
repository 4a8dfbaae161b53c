// A pair's placed part (a contact) moved to where its share of the residual says it belongs.
// The joint fit of a pair can settle with its placed part in a wrong basin: a contact that
// took up what the other part's single fit left where that fit was wrong (seen: a curvature span
// fitted 20 cm off, the contact put where the span belonged; the joint fit then moved the span
// right but kept the contact there). Its consistency is checked the way the pair search starts
// it (place_scan.h): the placed part left out, the other part at its pair values, every place
// along the cable is asked how much of that residual the effect there removes; where another
// place removes more than the fitted one, the pair is fitted again from there and kept when it
// ends better.
#pragma once

#include <vector>

#include "effect_fit.h"
#include "effect_pair_search.h"
#include "shape_effects.h"

namespace cablefit {

/// The `relocated_pairs` best pairs of `search` with a placed part (one with scan places), each
/// placed part checked and the pair refitted from the places that remove more of its share of
/// the residual. `coarse` scans, `bases` refit (one per equilibrium of the nominal). A fit is
/// replaced where the new one is better.
void RelocatePlacedParts(const FitContext& ctx, const std::vector<RodSimulator>& bases,
                         const std::vector<RodSimulator>& coarse,
                         const std::vector<EffectModel>& singles, PairSearch* search,
                         const PairSearchOptions& options);

}  // namespace cablefit
