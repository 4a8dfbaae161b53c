// Closed surfaces drawn inside a tube around its axis: the layers of one cable (a coax's
// dielectric and conductor inside its jacket).
#pragma once

#include <optional>
#include <vector>

#include "cablefit/formats/mesh_file.h"

namespace cablefit::internal {

/// The outer diameter [m] of `component` as a concentric layer of `host` (a tube already
/// recovered), or nullopt when it is none: every vertex within the host's radius of its route (a
/// layer never reaches beyond the wall around it), and along the route the vertices of each stretch
/// centred on it (their mean offset from the route under a quarter of their mean distance from it:
/// round about the axis, not a core beside it). Twice the farthest vertex's distance from the
/// route. Cheap: no skeleton of the layer (a coax of four hollow layers took 27 s with one each).
std::optional<double> ConcentricLayerDiameter(const TriangleMesh& component, const MeshTube& host);

}  // namespace cablefit::internal
