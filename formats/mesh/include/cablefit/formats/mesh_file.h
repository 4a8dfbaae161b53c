// Tessellated cables (STL, OBJ, PLY, glTF, 3MF ... through assimp): each connected component is
// skeletonised and its skeleton split at branch points into routes with a diameter.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// A tube recovered from a mesh.
struct MeshTube {
  int component = 0;     ///< which connected component of the mesh it came from
  Polyline centreline;   ///< s from 0 [m], points 3 x n [m]; starts at its lexicographically
                         ///< smaller end (x, then y, then z) so the result is deterministic
  double diameter = 0.0; ///< [m], twice the median distance of its surface to the centreline
  double inner_diameter = 0.0; ///< [m] bore of a hollow tube (hose, conduit), 0 when solid
  double fit_error = 0.0;///< RMS of (surface distance to centreline - radius) [m]
  /// Concentric layers drawn inside it as closed surfaces of their own (a coax cable's
  /// dielectric and conductor), outermost first: their diameters [m] and components.
  std::vector<double> layers;
  std::vector<int> layer_components;
  /// The cable's unit direction (along increasing s) at its start and at its end where that end
  /// is a flat cap: the cap's normal, exact however coarse the tessellation, where the route's
  /// last points (a blend onto the cap over three radii) give it only to a milliradian.
  std::optional<Vec3> start_direction, end_direction;
};

/// A connected component of a mesh that is no cable: a bracket, a frame, a short stout part.
struct MeshPart {
  int component = 0;
  TriangleMesh mesh;   ///< [m]
  std::string reason;  ///< why it is no tube ("component 2 is not a tube (cross-sections ...)")
  /// When it is a tube too short to be a cable (a bush, a stripped core end): its route (empty
  /// otherwise) and diameter [m].
  Polyline centreline;
  double diameter = 0.0;
};

/// Everything a mesh holds: its tubes, and the other components, kept as parts (drawn, and
/// usable as clips and for contact) rather than a reason to drop the whole file.
struct MeshContents {
  std::vector<MeshTube> tubes;
  std::vector<MeshPart> parts;
};

/// A tube shorter than this many diameters is a part (a screw shank, a bush, a stout cylinder),
/// not a cable: a cable is slender and bends. The CAD reader's default (CadReadOptions).
inline constexpr double kMinMeshTubeAspect = 10.0;

/// Reads a mesh file: tubes and other parts. Throws FileError(path, problem) when the file
/// cannot be read or holds no triangles.
MeshContents ReadMeshContents(const std::string& path, double unit,
                              double min_aspect = kMinMeshTubeAspect);

/// Tubes and other parts of an already loaded mesh [m]. A component that is a single tube
/// shorter than `min_aspect` diameters is a part.
MeshContents RecoverMeshContents(const TriangleMesh& mesh, double min_aspect = kMinMeshTubeAspect);

/// Reads a mesh file and recovers its tubes. `unit` is the length of one file unit in metres
/// (meshes carry no unit: 0.001 for millimetres). Throws FileError(path, problem) when the file
/// cannot be read, holds no triangles, or a component is not a tube.
std::vector<MeshTube> ReadMeshFile(const std::string& path, double unit);

/// Reads the triangles of a mesh file, vertices welded, scaled by `unit` [m per file unit].
TriangleMesh ReadTriangleMesh(const std::string& path, double unit);

/// Recovers the tubes of an already loaded mesh [m] (see ReadMeshFile). Throws InvalidInput.
std::vector<MeshTube> RecoverTubes(const TriangleMesh& mesh);

/// A closed triangulated tube of diameter `diameter` [m] around `centreline` (flat caps),
/// `sides` vertices per ring. For tests, samples and exporting relaxed cables as meshes.
TriangleMesh SweepTubeMesh(const Polyline& centreline, double diameter, int sides = 24);

/// Writes `mesh` [m] scaled by 1/`unit` as STL, OBJ or PLY (chosen by extension), atomically.
void WriteMeshFile(const std::string& path, const TriangleMesh& mesh, double unit);

}  // namespace cablefit
