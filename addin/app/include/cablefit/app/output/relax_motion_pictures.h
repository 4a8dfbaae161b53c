// The picture sequence of a motion: every pose of the swept cables rendered as the deviation
// pictures are (isometric and two axis views, the parts translucent), on one fixed camera, the
// swept cables coloured by their distance from the relaxed shape (pose 0, same arc length) on
// one scale for all frames, written as an animated PNG <stem>-motion.png and as still frames
// <stem>-motion-frames/pose-<k>.png (for the report's slider).
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/output/relax_file.h"

namespace cablefit::addin {


/// Most frames in one animation; a longer motion shows evenly spaced poses (first and last kept).
inline constexpr int kMaxMotionFrames = 61;

/// Renders the motion of `f` (if it swept any cable) and writes the animation and the still
/// frames into `dir`. Enters the OSMesa renderer one thread at a time. Throws FileError when a
/// file cannot be written.
MotionPictures WriteMotionAnimation(const std::string& dir, const RelaxedFile& f,
                                    const HarnessConfig& config);

}  // namespace cablefit::addin
