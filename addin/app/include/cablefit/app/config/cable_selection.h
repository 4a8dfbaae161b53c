// Which of a drawing's cables are cables: harness.json can say that some drawn "cables" are rigid
// parts (exhaust pipes, brake lines, bars) that must be kept but never relaxed.
#pragma once

#include "cablefit/app/config/harness_config.h"
#include "cablefit/formats/harness_drawing.h"

namespace cablefit::addin {

/// Moves every cable that `config` calls rigid (HarnessConfig::RigidReason) to the drawing's
/// solids: a tube keeps its CAD shape (copied to the output STEP) and gets a swept mesh for
/// supports and contact; a bare curve has no body and is dropped. Each one is listed in
/// `drawing->skipped` with the reason; junctions are renumbered, and those left with fewer than
/// two ends removed. Throws FileError naming the input when no cable is left.
void ApplyCableSelection(const HarnessConfig& config, HarnessDrawing* drawing);

}  // namespace cablefit::addin
