// Natural (intrinsic) curvature profiles: piecewise constant Darboux vectors switched on and off
// by C1 smoothstep ramps inside their interval.
#pragma once

#include <vector>

#include "cablefit/core/rod/rod_spec.h"

namespace cablefit::internal {

/// Natural Darboux vector at arc length s (material frame) [1/m].
Vec3 NaturalCurvatureAt(const std::vector<NaturalCurvatureSpec>& pieces, double s);

/// Average of NaturalCurvatureAt over [s0, s1]: the consistent value for a dual cell, exact
/// enough (composite Gauss) that a sharp interval end costs no more than O(h) locally.
Vec3 AverageNaturalCurvature(const std::vector<NaturalCurvatureSpec>& pieces, double s0, double s1);

}  // namespace cablefit::internal
