// The relaxed cables of one drawing: what clearance, motion and tolerances start from, without
// the outputs of a run (those are RelaxedFile's, addin/app/output).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cablefit/app/relax/relax_cable.h"
#include "cablefit/formats/harness_drawing.h"

namespace cablefit::addin {

struct RelaxedHarness {
  HarnessDrawing drawing;
  std::vector<std::optional<CableRelaxation>> cables;  ///< per drawn cable; empty when it failed
  std::vector<std::string> cable_errors;               ///< per drawn cable; empty when it succeeded
};

}  // namespace cablefit::addin
