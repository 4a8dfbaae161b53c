// A hollow tube (a hose, a conduit) drawn as a mesh is one closed surface of genus one: the
// outer wall, the bore and the two ends (annuli, or the rims where the walls meet). Its skeleton
// is a loop through the wall, not the tube's axis. Cut along its sharp edges it falls into
// regions; the walls are the regions with two boundary loops that are not flat, and each wall
// with its two loops capped is a solid tube the ordinary recovery reads.
#pragma once

#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::internal {

/// V - E + F of a closed triangle surface: 2 for a sphere-like solid, 0 for a hollow tube.
int EulerCharacteristic(const TriangleMesh& mesh);

/// The walls of a closed mesh (regions between edges sharper than 60 degrees that have two
/// boundary loops and are not flat), each closed by a fan over each loop, oriented like the
/// mesh. Empty when the mesh is not manifold or has no such region.
std::vector<TriangleMesh> CappedWalls(const TriangleMesh& mesh);

}  // namespace cablefit::internal
