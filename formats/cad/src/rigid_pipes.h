// Straight tubes that the drawing fits as rigid pipes (pipelines, exhaust and hydraulic lines).
#pragma once

#include <string>
#include <vector>

#include "cablefit/formats/harness_drawing.h"
#include "drawn_sweeps.h"

namespace cablefit::internal {

struct RigidPipe {
  int cable = 0;    ///< index into HarnessDrawing::cables
  std::string why;  ///< the `skipped` line that says why it is a part
};

/// Tube cables that are rigid pipes, not cables: a straight hollow tube (its route nowhere farther
/// from its chord than a tenth of its radius; cables are drawn solid) fitted at an end with
/// - a flange: a solid part around that end, round about the tube's axis, at least 1.3 times as
///   wide as the tube and no longer along it than its own radius (a disc, not a connector body
///   or a clip block), or
/// - a pipe elbow: a hollow tube part of the same diameter, too stout to be a cable, turning
///   through 30 degrees or more at a bend radius under three of its diameters (a cable's bend
///   radius is several of its diameters), continuing the hollow tube from that end.
/// A bent tube with flanges (a flexible hose between two flanges) stays a cable.
std::vector<RigidPipe> FindRigidPipes(const std::vector<DrawnTube>& tubes,
                                      const AbsorbedTubes& absorbed, const HarnessDrawing& drawing);

}  // namespace cablefit::internal
