// The inputs of a relax run as files, and the output stem of each: what a run is given on the
// command line (files and folders) turned into the list of files it reads. Internal to the relax
// pipeline.
#pragma once

#include <string>
#include <vector>

namespace cablefit::addin {

/// Files named directly, and the STEP/IGES/KBL/mesh files directly inside named folders (sorted,
/// so runs are reproducible). A path that does not exist, or a folder without any such file, is
/// a failure of its own: one "<path>: <problem>" line in `failures`.
std::vector<std::string> ExpandInputs(const std::vector<std::string>& inputs,
                                      std::vector<std::string>* failures);

/// Output stems unique within the run: a second "harness" becomes "harness-igs", then "-2"...
/// A stem is cut to kMaxStemBytes so that "<stem>-deviation.png" and the close-ups' names stay
/// within the file system's 255 bytes for any input name.
std::vector<std::string> UniqueStems(const std::vector<std::string>& files);

}  // namespace cablefit::addin
