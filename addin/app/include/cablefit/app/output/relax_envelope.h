// The envelope files of one relaxed input: per cable the swept envelope (swept_envelope.h) of
// its motion poses and of its tolerance set-ups, written as <stem>-motion-envelope.{stl,glb,step}
// and <stem>-tolerance-envelope.{stl,glb,step} (one STL with every cable's envelope, one glTF with a
// named mesh per cable, one STEP with a named, coloured body per cable).
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/output/relax_file.h"

namespace cablefit::addin {


/// Builds the motion and tolerance envelopes of `f` (those it has) and writes them into `dir`
/// atomically. Returns what was written. Throws FileError when a file cannot be written.
std::vector<EnvelopeFiles> WriteEnvelopeFiles(const std::string& dir, const RelaxedFile& f,
                                              const HarnessConfig& config);

}  // namespace cablefit::addin
