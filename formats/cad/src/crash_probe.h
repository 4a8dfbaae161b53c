// A CAD file is read first in the helper process (cablefit/formats/helper_process.h): OCCT
// crashes on some corrupt files in ways no exception handler can catch.
#pragma once

#include <string>
#include <vector>

#include "cablefit/formats/helper_process.h"

namespace cablefit {

/// Runs the helper with `args` as a probe of the file `path`: throws FileError(path, ...) when it
/// dies by a signal or exits non-zero (a sanitizer report), or is still running after
/// `max_seconds` (then it is killed). Does nothing when the helper cannot be started.
void ProbeFileInChild(const std::string& path, const std::string& what,
                      const std::vector<std::string>& args, double max_seconds);

}  // namespace cablefit
