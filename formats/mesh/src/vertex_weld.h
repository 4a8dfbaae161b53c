// Vertices of a triangle soup that coincide up to the file's rounding, made one.
#pragma once

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::internal {

/// `mesh` with vertices closer than a millionth of its size (its bounding box's diagonal plus its
/// largest coordinate: float32 files round to 1.2e-7 of a coordinate) merged, the triangles that
/// lose a corner dropped. Meshers write the vertices on the edge between two faces of a CAD body
/// once per face, a few rounding units apart (FreeCAD: 3-8 nm on a 175 mm tube), and welded only
/// where bit-identical the body falls apart into open pieces along that edge.
TriangleMesh WeldNearVertices(const TriangleMesh& mesh);

}  // namespace cablefit::internal
