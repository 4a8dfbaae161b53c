#pragma once

#include <vector>

#include "cablefit/formats/harness_drawing.h"
#include "drawn_sweeps.h"

namespace cablefit::internal {

/// A stout tube (under the slenderness rule) whose end meets another cable's end, or another
/// such tube's, is a segment of a network (a breakout's branch, a short segment between two
/// nodes of a harness), not a stub:
/// it is held by its neighbours and relaxed with the network, as a branch of a mesh tube is, and
/// the relaxed STEP of a network reads back as the same network. Such tubes, kept as solid parts while reading, become
/// cables again (their "kept as a solid part" line goes). Ends meet within `tolerance` [m] or a
/// twentieth of the tube's radius (the accuracy of a recovered centre).
void KeepBreakoutBranches(const std::vector<DrawnTube>& tubes, double tolerance,
                          AbsorbedTubes* absorbed, HarnessDrawing* drawing);

}  // namespace cablefit::internal
