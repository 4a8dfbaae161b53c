// Pictures and the run report of `cablefit relax`: each input's relaxed cables as tubes coloured
// by their distance to the drawn route, the drawn routes as ghosts, the supports as markers;
// report.html with one row per cable and each input's picture.
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/output/relax_file.h"

namespace cablefit::addin {

/// Readies the renderer for WriteDeviationPicture (WarmUpRenderer at its picture size) and
/// swallows what fails: the picture itself reports it. For a thread of its own while the
/// cables relax.
void WarmUpDeviationPictures() noexcept;

/// Renders the relaxed cables of `f` (those that failed are drawn grey as drawn) and writes
/// them as a PNG to `path`. Enters the OSMesa renderer one thread at a time.
void WriteDeviationPicture(const std::string& path, const RelaxedFile& f,
                           const HarnessConfig& config);

/// One picture per cable of `f` (that cable alone) into `dir`, named
/// "<stem>-<cable>-deviation.png" (cable name made file-safe); returns the names by cable.
std::vector<std::string> WriteCloseUpPictures(const std::string& dir, const RelaxedFile& f,
                                              const HarnessConfig& config);

/// Writes the self-contained run report (it references only the PNGs next to it).
void WriteRelaxReport(const std::string& path, const std::vector<RelaxedFile>& files,
                      const HarnessConfig& config, double seconds);

}  // namespace cablefit::addin
