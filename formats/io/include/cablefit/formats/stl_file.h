// Binary STL (the de-facto format of 3D Systems' StereoLithography interface: an 80-byte
// header, a little-endian uint32 triangle count, then per triangle a float normal, three float
// vertices and a uint16 attribute). Writing is atomic (formats/base's AtomicFile).
#pragma once

#include <string>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// Binary STL bytes of `mesh` (coordinates as stored, [m]; facet normals from the winding).
/// `header` is cut or padded to 80 bytes (it must not start with "solid", which marks ASCII STL).
std::string EncodeStl(const TriangleMesh& mesh, const std::string& header);

/// Writes EncodeStl(mesh, header) to `path` atomically. FileError naming `path` on failure.
void WriteStl(const std::string& path, const TriangleMesh& mesh, const std::string& header);

/// Reads a binary STL: one vertex per triangle corner (not merged). Throws FileError when the
/// file cannot be read or its size does not match its triangle count.
TriangleMesh ReadBinaryStl(const std::string& path);

}  // namespace cablefit
