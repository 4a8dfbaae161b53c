// The wide axis of a relaxed flat cable along the centreline written to STEP: what turns its
// rectangle or stadium there.
#pragma once

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/solver/rod_solution.h"
#include "cablefit/formats/harness_drawing.h"

namespace cablefit::addin {

/// The wide axes (3 x n unit, each square to the tangent of `written` there) at the samples of
/// `written` (the relaxed centreline as it is written, s from 0 [m]). From `solution`'s element
/// frames: their material d1, interpolated linearly in s between element midpoints (a flat
/// cable's clamps hold d1 at the drawn wide axis, SetUpCable; the principal angle only says
/// which way it bends stiffly). Without material frames (`solution` null: the cable failed, or
/// its frames' d1 not finite: a network's solve keeps tangents only) from the drawing's wide
/// axes at the nearest drawn point, like the clamps'. `drawn.flat` must be set.
Eigen::Matrix3Xd WrittenWideAxes(const Polyline& written, const RodSolution* solution,
                                 const DrawnCable& drawn);

}  // namespace cablefit::addin
