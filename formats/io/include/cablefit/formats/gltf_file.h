// Binary glTF 2.0 (.glb, Khronos glTF 2.0 specification, section 4.4 "GLB File Format
// Specification"): a 12-byte header, one JSON chunk and one BIN chunk holding, per mesh, float
// positions and uint32 triangle indices. Writing is atomic (formats/base's AtomicFile).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// One mesh of a glTF scene: a node of that name with one triangle primitive.
struct GltfMesh {
  std::string name;
  TriangleMesh mesh;                           ///< [m], z up (the CAD frame)
  std::array<double, 4> colour{0.2, 0.45, 0.85, 0.5};  ///< linear RGBA 0..1 (alpha < 1: blended)
};

/// GLB bytes of `meshes`. glTF is y-up: a root node turns the CAD frame's z up to y up (-90
/// degrees about x), so viewers show the harness the right way up; coordinates stay metres.
/// `generator` goes into asset.generator. Empty meshes are left out.
std::string EncodeGlb(const std::vector<GltfMesh>& meshes, const std::string& generator);

/// Writes EncodeGlb(meshes, generator) to `path` atomically. FileError naming `path` on failure.
void WriteGlb(const std::string& path, const std::vector<GltfMesh>& meshes,
              const std::string& generator);

}  // namespace cablefit
