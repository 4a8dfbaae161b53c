// PLY point clouds (Turk's PLY format: http://paulbourke.net/dataformats/ply/): ASCII,
// binary_little_endian and binary_big_endian.
#pragma once

#include <string>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// Reads the `vertex` element's x, y, z (float or double) from a PLY file. Other vertex
/// properties (any scalar or list type) and other elements (e.g. faces with list properties) are
/// skipped. Header counts are checked against the file size before anything is allocated. Throws
/// FileError for a missing magic/format/end_header, unknown types, missing x/y/z, truncated data
/// and vertices with non-finite coordinates (reported with their count).
PointCloud ReadPly(const std::string& path);

/// Writes `cloud` atomically as a PLY with double x, y, z: binary little endian, or ASCII with
/// shortest round-trip numbers. Throws FileError (and leaves `path` untouched) for non-finite
/// coordinates.
void WritePly(const std::string& path, const PointCloud& cloud, bool binary = true);

}  // namespace cablefit
