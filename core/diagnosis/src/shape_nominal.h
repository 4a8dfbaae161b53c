// Second stage of the shape diagnosis: the nominal set-up solved for the fits, from the
// recorded shape and from the other starts that settle in another equilibrium.
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "cablefit/core/rod/rod_spec.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "shape_recording.h"

namespace cablefit {

struct NominalBranches {
  /// One warm simulator per distinct equilibrium; the first is the one the recorded shape
  /// leads to.
  std::vector<RodSimulator> bases;
  /// The same equilibria on the coarse level alone (no extrapolation): a screening's forward
  /// model, about three times cheaper a solve, for ranking candidates that the fine one settles
  /// (the fine simulator where the coarse level alone does not settle).
  std::vector<RodSimulator> coarse;
  std::vector<NominalStart> starts;     // how each was reached
  std::vector<double> reaction_moment;  // [N m] moment magnitude at every support (first)
};

/// The forward model of the fits: two levels with extrapolation.
SimulationOptions FitSimulationOptions(const RodSpec& nominal);
/// Its coarse level alone.
SimulationOptions ScreenSimulationOptions(const RodSpec& nominal);

/// Throws InvalidInput when the nominal set-up cannot be solved from the recorded shape.
NominalBranches SolveNominalBranches(const RodSpec& nominal, const PreparedRecording& recording);

}  // namespace cablefit
