// What a relax run wrote next to an input's STEP and JSON besides them: the envelope files of
// its motion and tolerances and the motion's pictures (names relative to the output folder).
#pragma once

#include <string>
#include <vector>

#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

/// One envelope file pair.
struct EnvelopeFiles {
  std::string kind;      ///< "motion" or "tolerance"
  std::string stl, glb;  ///< file names next to the other outputs
  /// The same as STEP (per cable a compound of its pose tubes as solids), or empty with the
  /// reason in `step_problem` when OCCT could not make it.
  std::string step, step_problem;
  struct Cable {
    std::string name;
    int shapes = 0;         ///< poses or set-ups solved (converged)
    int shapes_used = 0;    ///< of them in the mesh (repeats and a cap left out)
    long triangles = 0;
  };
  std::vector<Cable> cables;
};

/// The envelope file names of `stem` (to check the output folder before the run).
std::vector<std::string> EnvelopeFileNames(const std::string& stem);
/// The relax JSON's file-level "envelopes" array.
json::Json EnvelopeFilesToJson(const std::vector<EnvelopeFiles>& files);

/// What WriteMotionAnimation wrote (names relative to the output folder).
struct MotionPictures {
  std::string animation;            ///< "<stem>-motion.png", empty when nothing was written
  std::vector<std::string> frames;  ///< "<stem>-motion-frames/pose-<k>.png", one per frame
  std::vector<std::string> captions;  ///< per frame: pose and parameter
};

/// Folder of the still frames of `stem` (relative to the output folder).
std::string MotionFramesFolder(const std::string& stem);

}  // namespace cablefit::addin
