// A helical curve, as coil cords and springs are drawn.
#pragma once

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// A helix about +z through (radius, 0, 0): `radius` and `pitch` (rise per turn) [m], `turns`
/// (> 0), 96 points per turn (fine enough to keep its curvature in a chord polyline),
/// parameterised by chord length [m].
Polyline SampleHelix(double radius, double pitch, double turns);

}  // namespace cablefit
