// The STEP/IGES read itself, without the crash probe: what the probe's helper process runs, and
// what ReadCadFile runs in this process once the probe came back clean.
#pragma once

#include <string>

#include "cablefit/formats/cad_file.h"

namespace cablefit::internal {

/// ReadCadFile's work after its checks of the path and the probe. Throws FileError like it.
HarnessDrawing ReadCadFileInThisProcess(const std::string& path, const CadReadOptions& options);

}  // namespace cablefit::internal
