// An input drawing of `relax` read into a HarnessDrawing: CAD (STEP/IGES), a KBL file's
// segments, or a mesh whose tubes become cables.
#pragma once

#include <string>

#include "cablefit/formats/harness_drawing.h"

namespace cablefit::addin {

/// Empty when the tubes of a mesh read with `mesh_unit` [m per file unit] are plausible cable
/// sizes; else one line saying why not and which unit would make them plausible.
std::string ImplausibleMeshUnit(const HarnessDrawing& drawing, double mesh_unit);

/// Reads a CAD file (ReadCadFile), a KBL file (ReadKblInput's drawing: segments with their bundle
/// diameters) or a mesh (ReadMeshContents: tubes named "<stem>#k", junctions between tube ends
/// closer than a quarter of the smaller diameter, other components kept as solids
/// "<stem>-part<k>", a warning for implausible sizes). Throws FileError.
HarnessDrawing ReadHarnessInput(const std::string& path, double mesh_unit);

}  // namespace cablefit::addin
