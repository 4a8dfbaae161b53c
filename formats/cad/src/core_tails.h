#pragma once

#include <vector>

#include "cablefit/formats/harness_drawing.h"
#include "drawn_sweeps.h"

namespace cablefit::internal {

/// A multi-core cable drawn with its cores' stripped ends (conductors, with or without the
/// insulation over part of them) leaves those ends as short thin tubes sticking out of the
/// jacket's end face, each a stub that is no cable of its own. A tube (cable or solid part in
/// `tubes`) that is thinner than a cable, starts inside that cable's section at one of its ends
/// and runs out of it, and is shorter than `min_aspect` of that cable's diameters (a branch of a
/// harness is longer), is marked in `absorbed` as part of the cable, with a line in `skipped`.
/// A tube whose root meets the ends of two other cables (within `junction_tolerance` [m]) is a
/// branch of their breakout (a thin wire leaving a harness node), and one whose far end meets
/// another cable's end is a segment of a network (a bundle thinning at a splice): no core ends.
/// Alone at a cable's end (no other tail beside it) a tube is a core end only when it is not
/// slender on its own (`min_aspect` of its own diameters): a wire's bare conductor, not a leaf
/// segment continuing the cable thinner.
void MergeCoreTails(const std::vector<DrawnTube>& tubes, double min_aspect,
                    double junction_tolerance, HarnessDrawing* drawing, AbsorbedTubes* absorbed);

}  // namespace cablefit::internal
