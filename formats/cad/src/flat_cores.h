#pragma once

#include <vector>

#include "cablefit/formats/harness_drawing.h"
#include "drawn_sweeps.h"

namespace cablefit::internal {

/// Flat house wiring is drawn as a flat jacket with its round cores inside it: the cores are
/// the jacket's, not cables of their own. A round tube (a cable, or a solid part recorded in
/// `tubes`) with at least half of its centres inside a flat cable's section leaves the drawing,
/// with a line in `skipped` naming the flat cable it belongs to.
/// With `absorbed` the cores are only marked there (see MergeSweepsIntoCurves).
void MergeCoresIntoFlatJackets(const std::vector<DrawnTube>& tubes, HarnessDrawing* drawing,
                               AbsorbedTubes* absorbed = nullptr);

}  // namespace cablefit::internal
