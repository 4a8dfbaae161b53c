#include "cablefit/formats/harness_drawing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

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

namespace {

// The sort key of a cable: its two end points rounded to 1 um, the smaller one first.
std::array<long long, 6> GeometricKey(const Polyline& centreline) {
  std::array<long long, 6> key{};
  if (centreline.size() < 1) return key;
  auto rounded = [](const Vec3& p) {
    return std::array<long long, 3>{std::llround(p.x() * 1e6), std::llround(p.y() * 1e6),
                                    std::llround(p.z() * 1e6)};
  };
  std::array<long long, 3> a = rounded(centreline.points.col(0));
  std::array<long long, 3> b = rounded(centreline.points.col(centreline.size() - 1));
  if (b < a) std::swap(a, b);
  std::copy(a.begin(), a.end(), key.begin());
  std::copy(b.begin(), b.end(), key.begin() + 3);
  return key;
}

}  // namespace

void NameCablesUniquely(HarnessDrawing* drawing) {
  std::vector<DrawnCable>& cables = drawing->cables;
  std::vector<size_t> order(cables.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::vector<std::array<long long, 6>> keys;
  for (const DrawnCable& c : cables) keys.push_back(GeometricKey(c.centreline));
  // Ties (two cables with the same ends) keep the file's order.
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return keys[a] < keys[b]; });
  std::map<std::string, int> uses;
  for (const DrawnCable& c : cables) ++uses[c.name];
  std::map<std::string, int> counter;
  int unnamed = 0;
  for (size_t i : order) {
    std::string& name = cables[i].name;
    if (name.empty()) {
      name = "cable-" + std::to_string(++unnamed);
    } else if (uses[name] > 1) {
      const int k = ++counter[name];
      name += '#';  // appended piecewise: GCC 12 -Wrestrict misfires on "#" + string
      name += std::to_string(k);
    }
  }
  int unnamed_solids = 0;
  for (DrawnSolid& s : drawing->solids) {
    if (s.name.empty()) s.name = "solid-" + std::to_string(++unnamed_solids);
  }
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
  if (!(probe_seconds_per_megabyte >= 0 && std::isfinite(probe_seconds_per_megabyte)))
    return fail("probe_seconds_per_megabyte must be finite and >= 0");
  return true;
}

double CadReadOptions::ProbeSecondsFor(std::uintmax_t bytes) const {
  return probe_seconds + probe_seconds_per_megabyte * static_cast<double>(bytes) * 1e-6;
}

}  // namespace cablefit
