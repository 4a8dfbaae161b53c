#include "cablefit/app/input/harness_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "cablefit/app/input/input_kind.h"
#include "cablefit/app/input/kbl_input.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/file_kind.h"
#include "cablefit/formats/mesh_file.h"

namespace cablefit::addin {

namespace {

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::string Millimetres(double metres) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3g mm", 1e3 * metres);
  return text;
}

}  // namespace

std::string ImplausibleMeshUnit(const HarnessDrawing& d, double mesh_unit) {
  // Wires, bundles and hoses lie between these diameters; a mesh carries no unit, so sizes far
  // outside mean the unit was most likely wrong.
  constexpr double kMinDiameter = 0.3e-3, kMaxDiameter = 0.15;
  constexpr double kTypicalDiameter = 8e-3;
  std::vector<double> diameters, lengths;
  for (const DrawnCable& c : d.cables) {
    if (c.diameter > 0) diameters.push_back(c.diameter);
    lengths.push_back(c.centreline.ChordLength());
  }
  if (diameters.empty()) return {};
  const double diameter = Median(diameters), length = Median(lengths);
  if (diameter >= kMinDiameter && diameter <= kMaxDiameter) return {};
  std::string best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const char* unit : {"mm", "cm", "m", "in"}) {
    const double scaled = diameter * UnitInMetres(unit) / mesh_unit;
    const double distance = std::abs(std::log(scaled / kTypicalDiameter));
    if (scaled >= kMinDiameter && scaled <= kMaxDiameter && distance < best_distance) {
      best_distance = distance;
      best = std::string("; if the file is in ") + unit + ", use --unit " + unit + " (" +
             Millimetres(scaled) + " across, " +
             Millimetres(length * UnitInMetres(unit) / mesh_unit) + " long)";
    }
  }
  return "the tubes are " + Millimetres(diameter) + " across and " + Millimetres(length) +
         " long (medians), implausible for cables" + best;
}

HarnessDrawing ReadHarnessInput(const std::string& path, double mesh_unit) {
  if (IsCadPath(path)) return ReadCadFile(path);
  if (IsKblInput(path)) return ReadKblInput(path, HarnessConfig{}).drawing;
  const FileKind kind = SniffFileKind(path);
  if (kind == FileKind::kJson) {
    throw FileError(path, "is a JSON file, not CAD or a mesh: a recording case goes to 'cablefit "
                          "diagnose', a harness.json to 'cablefit relax --config'");
  }
  if (!IsMeshPath(path)) {
    throw FileError(path, "unknown extension (expected STEP, IGES, KBL or a mesh: STL, OBJ, PLY, "
                          "glTF...)");
  }
  if (kind == FileKind::kPlyPoints) {
    throw FileError(path, "is a PLY point cloud (no faces), not a mesh: relax needs tube surfaces; "
                          "a scan is diagnosed through the case.json that lists it ('cablefit "
                          "diagnose')");
  }
  MeshContents contents = ReadMeshContents(path, mesh_unit);
  if (contents.tubes.empty()) {
    throw FileError(path, "no tube found in the mesh: " +
                              (contents.parts.empty() ? std::string("it has no closed component")
                                                      : contents.parts.front().reason));
  }
  const std::vector<MeshTube>& tubes = contents.tubes;
  HarnessDrawing d;
  d.source_path = path;
  const std::string stem = std::filesystem::path(path).stem().string();
  double min_diameter = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < tubes.size(); ++k) {
    DrawnCable c;
    c.name = stem + "#" + std::to_string(k + 1);
    c.centreline = tubes[k].centreline;
    c.diameter = tubes[k].diameter;
    c.inner_diameter = tubes[k].inner_diameter;
    c.source = CableSourceKind::kMesh;
    c.fit_error = tubes[k].fit_error;
    c.start_direction = tubes[k].start_direction;
    c.end_direction = tubes[k].end_direction;
    for (size_t l = 0; l < tubes[k].layers.size(); ++l) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "component %d: a %.4g mm layer inside cable '%s' (%.4g mm, on its axis): "
                    "part of that cable, not a separate one",
                    tubes[k].layer_components[l], 1e3 * tubes[k].layers[l], c.name.c_str(),
                    1e3 * c.diameter);
      d.skipped.push_back(line);
    }
    min_diameter = std::min(min_diameter, c.diameter);
    d.cables.push_back(std::move(c));
  }
  // Components that are no tube stay in the harness as parts: drawn, and clips and obstacles
  // for the cables, as a STEP file's other solids are.
  std::vector<TubeSolid> tube_solids;
  for (MeshPart& part : contents.parts) {
    if (part.centreline.size() >= 2) {
      tube_solids.push_back({static_cast<int>(d.solids.size()), part.centreline.points,
                             0.5 * part.diameter, static_cast<int>(d.skipped.size())});
    }
    DrawnSolid solid;
    solid.name = stem + "-part" + std::to_string(part.component + 1);
    solid.mesh = std::move(part.mesh);
    d.skipped.push_back(part.reason);
    d.solids.push_back(std::move(solid));
  }
  if (std::string why = ImplausibleMeshUnit(d, mesh_unit); !why.empty()) d.warnings.push_back(why);
  // Branch ends recovered from a skeleton sit within a fraction of the tube radius of each other.
  const double junction_tolerance = 0.25 * min_diameter;
  // A multi-core cable's stripped core ends, meshed as tubes of their own, belong to it.
  AbsorbCoreTails(tube_solids, kMinMeshTubeAspect, junction_tolerance, &d);
  FindJunctions(&d, junction_tolerance);
  return d;
}

}  // namespace cablefit::addin
