#include "cablefit/app/relax_file.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/file_kind.h"
#include "cablefit/app/provenance.h"
#include "cablefit/formats/mesh_file.h"
#include "cablefit/app/kbl_input.h"
#include "relax_route.h"
#include "relaxed_wide_axes.h"

namespace cablefit::addin {
namespace {

std::string LowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

bool IsCadPath(const std::string& path) {
  const std::string ext = LowerExtension(path);
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

bool IsMeshPath(const std::string& path) {
  static const char* const kExt[] = {".stl", ".obj", ".ply", ".gltf", ".glb",
                                     ".3mf", ".off", ".dae", ".fbx"};
  const std::string ext = LowerExtension(path);
  return std::any_of(std::begin(kExt), std::end(kExt), [&](const char* e) { return ext == e; });
}

double UnitInMetres(const std::string& name) {
  static const std::map<std::string, double> kUnits = {
      {"m", 1.0},     {"cm", 0.01},     {"mm", 0.001}, {"um", 1e-6},
      {"in", 0.0254}, {"inch", 0.0254}, {"ft", 0.3048}};
  const auto it = kUnits.find(name);
  if (it == kUnits.end()) {
    throw InvalidInput("unknown length unit '" + name + "' (use m, cm, mm, um, in or ft)");
  }
  return it->second;
}

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
  for (MeshPart& part : contents.parts) {
    DrawnSolid solid;
    solid.name = stem + "-part" + std::to_string(part.component + 1);
    solid.mesh = std::move(part.mesh);
    d.skipped.push_back(part.reason);
    d.solids.push_back(std::move(solid));
  }
  if (std::string why = ImplausibleMeshUnit(d, mesh_unit); !why.empty()) d.warnings.push_back(why);
  // Branch ends recovered from a skeleton sit within a fraction of the tube radius of each other.
  FindJunctions(&d, 0.25 * min_diameter);
  return d;
}

const HarnessConfig& ConfigOf(const RelaxedFile& f, const HarnessConfig& config) {
  return f.own_config ? *f.own_config : config;
}

double OutputDiameter(const RelaxedFile& f, int cable, const HarnessConfig& config) {
  const auto& relaxed = f.cables[static_cast<size_t>(cable)];
  if (relaxed) return relaxed->setup.spec.material.diameter;
  const DrawnCable& drawn = f.drawing.cables[static_cast<size_t>(cable)];
  const double diameter = config.For(drawn.name).DiameterFor(drawn.diameter);
  return diameter > 0 ? diameter : kDefaultDiameter;
}

namespace {

// The relaxed centreline at about `per_diameter` points per diameter (17 to 401 points): the
// writer interpolates a B-spline through them, and a spline through a few hundred points with a
// tight turn near an end can make the OCCT pipe sweep fail where a sparser one does not.
Polyline ForWriting(const Polyline& relaxed, double diameter, double per_diameter) {
  const double length = relaxed.s[relaxed.size() - 1];
  const int n =
      std::clamp(static_cast<int>(std::ceil(length / diameter * per_diameter)) + 1, 17, 401);
  return SampleCenterline(relaxed, UniformArcLengths(length, n));
}

// Corners rounded to about two diameters first (no cable bends tighter): a B-spline through a
// drawn polyline's corner (KBL centre curves of degree 1) needs hundreds of knots to stay within
// the writer's tolerance, and the sweep along it fails (a 183-segment harness: 100 s, then a
// second pass).
Polyline AsDrawnForWriting(const Polyline& drawn, double diameter, double per_diameter) {
  try {
    return ForWriting(RoundedRoute(CleanRoute(drawn), 2 * diameter), diameter, per_diameter);
  } catch (const InvalidInput&) {
    return drawn;  // the writer reports what is wrong with it
  }
}

}  // namespace

std::vector<std::string> WriteRelaxedStepFile(const std::string& path, const RelaxedFile& f,
                                              const HarnessConfig& config) {
  std::vector<std::string> best_skipped;
  bool first_pass = true;
  for (const double per_diameter : {2.0, 0.5}) {
    std::vector<RelaxedCable> out;
    for (size_t i = 0; i < f.drawing.cables.size(); ++i) {
      RelaxedCable rc;
      rc.source_cable = static_cast<int>(i);
      rc.diameter = OutputDiameter(f, static_cast<int>(i), config);
      // A failed cable is written as drawn, resampled like a relaxed one: the raw skeleton of a
      // mesh tube is unevenly spaced, which makes the B-spline through it swing. (The crash once
      // seen here was OCCT's MakePipe on a smooth spine; the writer no longer uses it.)
      rc.centreline = f.cables[i] ? ForWriting(f.cables[i]->relaxed, rc.diameter, per_diameter)
                                  : AsDrawnForWriting(f.drawing.cables[i].centreline, rc.diameter,
                                                      per_diameter);
      const DrawnCable& drawn = f.drawing.cables[i];
      if (drawn.flat) {
        rc.flat = *drawn.flat;
        rc.flat->wide_axes = WrittenWideAxes(
            rc.centreline, f.cables[i] ? &f.cables[i]->result.solution : nullptr, drawn);
      }
      out.push_back(std::move(rc));
    }
    // The sparser resampling is a second try for the cables whose sweep failed; the file it
    // writes replaces the first only when it holds more cables.
    std::vector<std::string> skipped;
    const std::string target = first_pass ? path : path + ".retry";  // not *.step: never an input
    WriteRelaxedStep(target, f.drawing, out, &skipped);
    std::error_code ec;
    if (!first_pass && std::filesystem::exists(target, ec)) {
      if (skipped.size() < best_skipped.size()) {
        std::filesystem::rename(target, path, ec);
        if (ec) throw FileError(path, "cannot replace: " + ec.message());
      } else {
        std::filesystem::remove(target, ec);
      }
    }
    if (first_pass || skipped.size() < best_skipped.size()) best_skipped = skipped;
    first_pass = false;
    if (best_skipped.empty()) break;
  }
  for (std::string& problem : best_skipped) problem += " (left out of the STEP file)";
  return best_skipped;
}

json::Json RelaxedFileToJson(const RelaxedFile& f, const HarnessConfig& config) {
  json::Json j;
  j["format"] = "cablefit-relax/1";
  j["input"] = f.input;
  j["length_unit_of_input"] = f.drawing.length_unit;
  j["config"] = config.path.empty() ? json::Json() : json::Json(config.path);
  j["provenance"] = ProvenanceJson({{"input", f.input}, {"config", config.path}});
  j["min_bend_radius_factor"] = config.min_bend_radius_factor;
  j["not_cables"] = f.drawing.skipped;  // what the input drew that was not taken as a cable, and why
  if (!f.drawing.warnings.empty()) j["warnings"] = f.drawing.warnings;
  if (!f.notes.empty()) j["input_notes"] = f.notes;  // what reading found or assumed (KBL)
  if (!f.networks.empty()) {
    j["networks"] = f.networks;
    j["networks_meaning"] =
        "cables solved together: branch_loads are the force and moment each cable exerts on its "
        "junction (world frame, N and N m), contacts the force a solid exerts on the cable";
  }
  json::Json cables = json::Json::array();
  for (size_t i = 0; i < f.drawing.cables.size(); ++i) {
    if (f.cables[i]) {
      cables.push_back(CableToJson(*f.cables[i], f.drawing.cables[i]));
      if (const auto it = f.cable_json.find(f.drawing.cables[i].name); it != f.cable_json.end()) {
        cables.back()["kbl"] = it->second;
        // The length check a harness engineer asks for: the relaxed centreline (the polyline
        // through its samples) against the segment's Virtual_length; they agree to the
        // bundle's stretch and the sampling's chord error.
        const Polyline& relaxed = f.cables[i]->relaxed;
        double length = 0.0;
        for (int k = 0; k + 1 < relaxed.size(); ++k)
          length += (relaxed.points.col(k + 1) - relaxed.points.col(k)).norm();
        json::Json& kbl = cables.back()["kbl"];
        kbl["relaxed_length"] = length;
        const json::Json& virtual_length = kbl["virtual_length"];
        kbl["relaxed_minus_virtual_length"] =
            virtual_length.is_number() ? json::Json(length - virtual_length.get<double>())
                                       : json::Json();
      }
    } else {
      // What the failed cable was, so the reader can see what could not be relaxed.
      const DrawnCable& drawn = f.drawing.cables[i];
      cables.push_back({{"name", drawn.name},
                        {"error", f.cable_errors[i]},
                        {"written_as", "drawn (not relaxed)"},
                        {"drawn_length", json::NumberOrNull(drawn.centreline.ChordLength())},
                        {"diameter", OutputDiameter(f, static_cast<int>(i), config)}});
      if (const auto it = f.cable_json.find(f.drawing.cables[i].name); it != f.cable_json.end())
        cables.back()["kbl"] = it->second;
    }
  }
  // Per cable, its smallest clearance to anything it does not rest on.
  for (json::Json& c : cables) {
    const ClearancePair* least = nullptr;
    for (const ClearancePair& p : f.clearances) {
      const std::string name = c["name"].get<std::string>();
      if (p.rests_on || (p.cable != name && p.other != name)) continue;
      if (!least || p.hit.clearance < least->hit.clearance) least = &p;
    }
    if (least) c["clearance"] = ClearancePairToJson(*least);
  }
  if (f.motion) {
    for (const CableMotion& m : f.motion->cables)
      cables[static_cast<size_t>(m.cable)]["motion"] = CableMotionToJson(m, f.motion->config);
    j["motion"] = FileMotionToJson(*f.motion);
  }
  if (f.tolerance) {
    for (const CableTolerance& t : f.tolerance->cables)
      cables[static_cast<size_t>(t.cable)]["tolerance"] = CableToleranceToJson(t);
    j["tolerance_problems"] = f.tolerance->problems;
  }
  if (!f.envelopes.empty()) j["envelopes"] = EnvelopeFilesToJson(f.envelopes);
  j["cables"] = cables;
  json::Json pairs = json::Json::array();
  int violations = 0;
  for (const ClearancePair& p : f.clearances) {
    pairs.push_back(ClearancePairToJson(p));
    violations += p.violation() ? 1 : 0;
  }
  j["clearance"] = {
      {"pairs", pairs},
      {"violations", violations},
      {"meaning",
       "surface distance [m] of each relaxed cable (tube of its diameter) to each solid and each "
       "other cable, where it is least: s and point on 'cable'; negative = overlap; rests_on = "
       "the cable is clipped to or touches the solid (not a violation); violation = less than "
       "'required', the larger min_clearance harness.json asks of the two"}};
  json::Json solids = json::Json::array();
  for (const DrawnSolid& s : f.drawing.solids) solids.push_back(s.name);
  j["solids"] = solids;
  // Written before the STEP and pictures: their times are in the command's per-input line.
  j["seconds"] = {{"read", f.times.read}, {"relax", f.times.relax}};
  return j;
}

}  // namespace cablefit::addin
