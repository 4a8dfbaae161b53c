#include "cablefit/app/output/relax_file.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <unordered_map>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/cad_file.h"
#include "cablefit/app/base/provenance.h"
#include "relax/relax_route.h"
#include "output/relaxed_wide_axes.h"

namespace cablefit::addin {

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

// The fields of the JSON in the order docs/cli.md lists them: a flat list reads best whole.
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
  // Per cable, its smallest clearance to anything it does not rest on (the first such pair on
  // a tie).
  std::unordered_map<std::string, const ClearancePair*> least;
  for (const ClearancePair& p : f.clearances) {
    if (p.rests_on) continue;
    for (const std::string* name : {&p.cable, &p.other}) {
      if (name == &p.other && p.other_is_solid) continue;
      const ClearancePair*& l = least[*name];
      if (!l || p.hit.clearance < l->hit.clearance) l = &p;
    }
  }
  for (json::Json& c : cables)
    if (const auto it = least.find(c["name"].get<std::string>()); it != least.end())
      c["clearance"] = ClearancePairToJson(*it->second);
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
