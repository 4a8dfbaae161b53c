// The envelope files of one relaxed input: per cable the swept envelope (swept_envelope.h) of
// its motion poses and of its tolerance set-ups, written as <stem>-motion-envelope.{stl,glb,step}
// and <stem>-tolerance-envelope.{stl,glb,step} (one STL with every cable's envelope, one glTF with a
// named mesh per cable, one STEP with a named, coloured body per cable).
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/harness_config.h"
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

struct RelaxedFile;

/// The envelope file names of `stem` (to check the output folder before the run).
std::vector<std::string> EnvelopeFileNames(const std::string& stem);

/// Builds the motion and tolerance envelopes of `f` (those it has) and writes them into `dir`
/// atomically. Returns what was written. Throws FileError when a file cannot be written.
std::vector<EnvelopeFiles> WriteEnvelopeFiles(const std::string& dir, const RelaxedFile& f,
                                              const HarnessConfig& config);

/// The relax JSON's file-level "envelopes" array.
json::Json EnvelopeFilesToJson(const std::vector<EnvelopeFiles>& files);

}  // namespace cablefit::addin
