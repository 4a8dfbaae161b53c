// A KBL harness file as an input of `cablefit relax`: the segments as drawn cables, and what the
// file says about their physics as harness settings layered under the user's harness.json.
// Mapping and assumptions: docs/kbl.md.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/input/input_kind.h"
#include "cablefit/formats/harness_drawing.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/formats/kbl_file.h"

namespace cablefit::addin {

/// Fraction of a round bundle's cross-section its wires fill. Round wires packed by hand or
/// machine into a taped bundle fill about 70-80 % of the disc; mid value, an assumption.
inline constexpr double kBundlePackingFraction = 0.75;

/// What a protection adds, assumed (a KBL file gives its part number, not its mechanics); the
/// values are those of samples/materials/automotive.json, the section library. A tape wrap: PVC
/// harness tape 0.13 mm wound half-overlapped, so two layers [m], of PVC tape film [Pa] (on a
/// 10 mm bundle it adds ~12 % to the bundle's estimated EI).
inline constexpr double kTapeWrapThickness = 2 * 0.13e-3;
inline constexpr double kTapeModulus = 40e6;
/// A corrugated tube over the bundle, as a smooth annulus of the library's effective PA6 values:
/// wall 1.5 mm (NW 7-13 tubes: outer minus inner diameter ~3 mm), effective modulus [Pa].
inline constexpr double kCorrugatedWall = 1.5e-3;
inline constexpr double kCorrugatedModulus = 40e6;

/// [m] Accuracy a KBL harness is relaxed to unless --accuracy says otherwise: a tenth of the ~1 mm
/// a harness drawing is read to, far below the uncertainty of an estimated bundle stiffness, and
/// reachable within the network element cap (the general 1 um default is not, on a harness).
inline constexpr double kKblAccuracy = 1e-4;

/// A segment's bundle from its wires.
struct KblBundle {
  /// [m] one wire: its outside diameter; several: sqrt(sum d_i^2 / kBundlePackingFraction);
  /// 0 when no wire gives an outside diameter.
  double diameter = 0.0;
  int wires_with_diameter = 0;
  /// [kg/m] sum of the wires' mass per length; 0 unless every wire gives one.
  double linear_density = 0.0;
  /// [m] the largest of the wires' minimum bend radii (the tightest limit); 0 when none given.
  double min_bend_radius = 0.0;
};

/// The bundle of the wires routed through a segment.
KblBundle BundleOf(const std::vector<KblWire>& wires);

/// A protection's kind from its Protection_type, in English or German (Band, Wellrohr,
/// Wellschlauch, as the VDA samples are written): "tape", "corrugated tube", or "" (unknown:
/// its stiffness is not added).
std::string ProtectionKind(const std::string& type);

/// What `relax` reads from a KBL file.
struct KblInput {
  HarnessDrawing drawing;  ///< cables named by segment id, diameters = bundle diameters
  /// The user's harness.json with one cable entry per segment: material from the bundle, the
  /// wires' bend radius limit, fixings as clips; a segment's own harness.json entry overrides
  /// them field by field (see docs/kbl.md).
  HarnessConfig config;
  std::map<std::string, json::Json> cable_json;  ///< by segment id: its "kbl" object of the JSON
  std::vector<std::string> notes;                ///< the reader's findings and the defaults taken
};

/// Reads `path` (ReadKblFile) and builds the above. Throws FileError.
KblInput ReadKblInput(const std::string& path, const HarnessConfig& user);

}  // namespace cablefit::addin
