#include "cablefit/formats/harness_drawing.h"

#include <cmath>

#include "cablefit/formats/cad_file.h"

namespace cablefit {

const char* ToString(CableSourceKind kind) {
  switch (kind) {
    case CableSourceKind::kCurve: return "curve";
    case CableSourceKind::kTube: return "tube";
    case CableSourceKind::kMesh: return "mesh";
  }
  return "unknown";
}

void FindJunctions(HarnessDrawing* drawing, double tolerance) {
  drawing->junctions.clear();
  std::vector<std::vector<bool>> taken(drawing->cables.size(), std::vector<bool>(2, false));
  auto end_point = [&](int cable, bool at_start) -> Vec3 {
    const Polyline& c = drawing->cables[cable].centreline;
    return at_start ? Vec3(c.points.col(0)) : Vec3(c.points.col(c.size() - 1));
  };
  const int n = static_cast<int>(drawing->cables.size());
  for (int i = 0; i < n; ++i) {
    if (drawing->cables[i].centreline.size() < 1) continue;
    for (bool at_start : {true, false}) {
      if (taken[i][at_start ? 0 : 1]) continue;
      CableJunction junction;
      junction.position = end_point(i, at_start);
      junction.ends.push_back({i, at_start});
      for (int j = i; j < n; ++j) {
        if (drawing->cables[j].centreline.size() < 1) continue;
        for (bool other_start : {true, false}) {
          if ((j == i && other_start == at_start) || taken[j][other_start ? 0 : 1]) continue;
          if ((end_point(j, other_start) - junction.position).norm() < tolerance) {
            junction.ends.push_back({j, other_start});
          }
        }
      }
      if (junction.ends.size() < 2) continue;
      for (const auto& e : junction.ends) taken[e.cable][e.at_start ? 0 : 1] = true;
      drawing->junctions.push_back(std::move(junction));
    }
  }
}

bool CadReadOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(sample_spacing > 0)) return fail("sample_spacing must be > 0");
  if (!(mesh_relative_deflection > 0 && mesh_relative_deflection < 1))
    return fail("mesh_relative_deflection must be in (0, 1)");
  if (!(min_tube_area_fraction > 0 && min_tube_area_fraction <= 1))
    return fail("min_tube_area_fraction must be in (0, 1]");
  if (!(min_tube_aspect >= 0)) return fail("min_tube_aspect must be >= 0");
  if (!(junction_tolerance >= 0)) return fail("junction_tolerance must be >= 0");
  if (!(probe_seconds >= 0 && std::isfinite(probe_seconds)))
    return fail("probe_seconds must be finite and >= 0");
  return true;
}

}  // namespace cablefit
