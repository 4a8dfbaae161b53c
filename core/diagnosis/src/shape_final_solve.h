// Last stage of the shape diagnosis: the nominal and the chosen model solved at full accuracy,
// and the deviations of the recording from both. A fit that does not hold in the accurate solve
// is set aside and the next candidate taken.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cablefit/core/rod/rod_spec.h"
#include "cablefit/core/solver/rod_solution.h"
#include "effect_fit.h"
#include "shape_recording.h"

namespace cablefit {

struct FinalSolves {
  std::size_t chosen = 0;       // index of the model that held
  std::vector<bool> rejected;   // per fit: set aside because it did not hold
  RodSpec fitted_spec;
  RodSolution nominal, fitted;  // full accuracy
  std::vector<DiagnosisNote> notes;
};

/// `choose(rejected)` gives the best-ranked fit not rejected; `none_index` is the nominal's.
FinalSolves SolveFinal(const RodSpec& nominal, const PreparedRecording& recording,
                       const FitContext& ctx, const std::vector<EffectModel>& models,
                       const std::vector<Fit>& fits, std::size_t none_index,
                       const std::function<std::size_t(const std::vector<bool>&)>& choose);

/// Distances of every recorded point from a curve, and their max and rms [m].
struct CurveDeviation {
  Eigen::VectorXd s;         // n [m] arc length of each point on the curve
  Eigen::VectorXd distance;  // n [m]
  double max = 0.0, rms = 0.0;
};
CurveDeviation MeasureDeviation(const PreparedRecording& recording, const FitContext& ctx,
                                const Polyline& centerline);

/// Max and rms length of 3-vectors stacked in `offsets` [m].
void OffsetStatistics(const Eigen::VectorXd& offsets, double* max, double* rms);

/// The span where the deviation exceeds half its maximum (seen points only).
std::pair<double, double> MismatchInterval(const Eigen::VectorXd& s, const Eigen::VectorXd& dev);

}  // namespace cablefit
