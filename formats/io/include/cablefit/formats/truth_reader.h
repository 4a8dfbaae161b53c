// Reader for the truth.json that comes with public sample cases (format "cable-truth/1"): what
// effect was put into a recording. For tests and tools only; the diagnosis never sees it.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

struct CaseTruth {
  std::string case_name;
  std::string effect;                         // catalogue name, e.g. "intrinsic_curvature"
  std::optional<std::pair<double, double>> interval;  // [m] s_start, s_end; absent when null
  std::optional<int> clamp;                   // clamp index for clamp effects
  std::map<std::string, double> parameters;   // the numeric entries of `parameters`
};

/// Reads truth.json (or a folder holding one). Non-numeric parameters (strings, vectors) are
/// left out of `parameters`. Throws FileError on a wrong format or malformed fields.
CaseTruth ReadTruth(const std::string& path);

/// Reads `extra.<key>` = {"s": [...], "xyz": [[x,y,z], ...]} as a polyline; `key` is
/// "nominal_centerline" or "truth_centerline". Throws FileError when absent or malformed.
Polyline ReadTruthCenterline(const std::string& path, const std::string& key);

}  // namespace cablefit
