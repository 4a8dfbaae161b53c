#pragma once

#include <vector>

#include "cablefit/formats/harness_drawing.h"

namespace cablefit::internal {

/// IGES writes a route as several curve entities of one name, each read on its own, while a
/// STEP curve set joins the same pieces at their shared end points. Curve cables of one name
/// whose ends meet (within `tolerance` [m]) where no other cable end is are joined into one
/// route, in chains, so the same drawing gives the same cables from either format. A chain that
/// closes in one plane is a sketch profile: it leaves the cables with a line in `skipped`.
/// Returns, per cable before, its index after (-1 when it went into another or was dropped).
std::vector<int> JoinCurvePieces(HarnessDrawing* drawing, double tolerance);

}  // namespace cablefit::internal
