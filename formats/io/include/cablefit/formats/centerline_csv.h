// Centreline CSV (recording-v1.md): header `s,x,y,z` (s may be empty in every row) or `x,y,z`,
// one point per row from the first clamp to the last.
#pragma once

#include <string>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// Reads a centreline. `s` is taken from the file when given in every row, else filled with the
/// cumulative chord length from 0. Throws FileError for missing x/y/z columns, empty or
/// non-numeric cells, NaN/Inf, s given on some rows only, decreasing s, or fewer than 2 points.
Polyline ReadCenterlineCsv(const std::string& path);

/// Writes `line` atomically with header `s,x,y,z` and shortest round-trip numbers (s cells are
/// left empty when `line.s` is empty). Throws FileError for non-finite values or an `s` whose
/// size differs from the point count.
void WriteCenterlineCsv(const std::string& path, const Polyline& line);

}  // namespace cablefit
