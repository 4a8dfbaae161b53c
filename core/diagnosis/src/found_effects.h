// The chosen model read as the pieces of physics it names: each effect described where it acts,
// with the part of the baseline mismatch it removes (diagnosis.json's `effects`).
#pragma once

#include <vector>

#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "effect_fit.h"
#include "shape_effects.h"
#include "shape_final_solve.h"
#include "shape_recording.h"

namespace cablefit {

/// The effects of `models[chosen]` fitted at `x` (none: empty; a single effect: one; a pair:
/// two), dominant first. `final_solves` holds the nominal and the chosen model at full accuracy;
/// a pair's parts are solved once more each, alone (the other left out), for their shares and
/// where they act.
/// `mismatch` is where the nominal differs most from the recording (a single effect that acts on
/// the whole cable is reported there).
std::vector<FoundEffect> DescribeFoundEffects(const PreparedRecording& recording,
                                              const FitContext& ctx,
                                              const std::vector<EffectModel>& models,
                                              std::size_t chosen, const Eigen::VectorXd& x,
                                              const FinalSolves& final_solves,
                                              std::pair<double, double> mismatch);

}  // namespace cablefit
