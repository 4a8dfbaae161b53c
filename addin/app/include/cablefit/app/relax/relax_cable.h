// One cable of a harness drawing relaxed under gravity: its rod set-up (material, supports at
// their drawn poses, clips from the solids it passes through, harness.json), the solve from the
// drawn shape (nearest equilibrium), and what the relax output reports about it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/harness_drawing.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/relax/relax_clips.h"

namespace cablefit::addin {

/// Effective Young's modulus of a PVC-insulated stranded copper bundle treated as a solid disc
/// [Pa]: the strands slip (free-slip copper adds little) and plasticised PVC is 20-200 MPa at
/// room temperature; measured bundles of automotive wires fall around 50-100 MPa. Mid value.
inline constexpr double kDefaultBundleModulus = 75e6;
/// Mass density of such a bundle over its whole disc [kg/m^3]: copper (8930) at ~10-15 %
/// fill plus PVC (1400) and voids.
inline constexpr double kDefaultBundleDensity = 2000.0;
/// Axial (stretching) modulus of such a bundle over its whole disc [Pa]: along the cable the
/// copper strands carry the load without slipping, so it is copper's 110 GPa at the ~12 % fill
/// above, the PVC adding little. Gives EA when harness.json does not.
inline constexpr double kDefaultAxialModulus = 13e9;
/// A stretch between two supports is flagged taut below this relative slack (0.5 %): less than
/// the usual tolerance of a harness's cut lengths, so the built cable may have none at all.
/// Its tension is then set by its stretch (EA) and the supports' exact positions, not by its
/// weight, and a small error in either changes it many times over.
inline constexpr double kTautSlack = 0.005;

/// The note every cable without a material gets (in its JSON `notes`); the report says it once
/// above its table instead of in every row.
inline constexpr const char* kDefaultMaterialNote =
    "material not given: PVC-insulated copper bundle estimated from the diameter "
    "(E_eff = 75 MPa, GJ = EI/1.3, 2000 kg/m^3 over the disc)";
/// Diameter assumed for a bare curve without one in harness.json [m].
inline constexpr double kDefaultDiameter = 0.008;

/// EI = E pi d^4 / 64, GJ = EI / 1.3 (G = E / 2.6, nu ~ 0.3), mass = rho pi d^2 / 4,
/// EA = E_axial pi d^2 / 4; a hollow tube (hose, conduit) of bore b has d^4 - b^4 and
/// d^2 - b^2 in their place.
MaterialSpec DefaultBundleMaterial(double diameter, double bore = 0.0);  // [m]

/// A flat cable's default material: the bundle estimate's moduli and density over a rectangle
/// (or a stadium, `rounded_edges`) of `width` x `thickness` [m]. Bending about the wide axis
/// (the easy way) has I = w t^3 / 12, about the thickness axis I = t w^3 / 12 (a stadium's
/// half-discs added exactly); EI is their geometric mean, `bending_ratio` their ratio and
/// `principal_angle` pi/2, for a material frame whose d1 is the wide axis (the stiff bending is
/// about d2). GJ from Roark's rectangle, J = w t^3 (1/3 - 0.21 t/w (1 - t^4 / (12 w^4))).
MaterialSpec DefaultFlatMaterial(double width, double thickness, bool rounded_edges);

/// The rod set-up of one drawn cable.
struct CableSetup {
  int cable = 0;  ///< index into HarnessDrawing::cables
  std::string name;
  Polyline route;  ///< drawn route, s by chords from 0 [m]
  double drawn_length = 0.0;  ///< [m] of the route; spec.length may differ (harness.json "length")
  RodSpec spec;
  bool diameter_defaulted = false;
  double bore = 0.0;  ///< [m] inner diameter of a hollow tube (hose, conduit), 0 when solid
  /// [m] a flat cable's section (DrawnCable::flat), width along its drawn wide axis; 0 when round.
  double flat_width = 0.0, flat_thickness = 0.0;
  bool material_defaulted = false;
  std::string material_source;  ///< "default bundle estimate", harness.json, section file
  std::vector<std::string>
      support_origin;    ///< per spec support: "start", "end", "harness.json", "clip <solid>"
  std::string junction;  ///< non-empty when an end meets 2+ other cables
  /// [m] the cable's own smallest allowed bend radius (CableConfig::min_bend_radius); 0 = the
  /// run's min_bend_radius_factor diameters.
  double min_bend_radius_limit = 0.0;
  std::vector<std::string> notes;  ///< assumptions, one sentence each
};

/// Which ends of a cable are attached to a junction of a network (they get no end support).
struct JunctionEnds {
  bool start = false, end = false;
  std::string description;  ///< what the relax output says about it
};

/// Builds the set-up. `boxes` are the bounding boxes of `drawing.solids` (same order).
/// Throws InvalidInput (one line, without the file name) when no valid set-up exists.
CableSetup SetUpCable(const HarnessDrawing& drawing, int cable,
                      const std::vector<OrientedBox>& boxes, const HarnessConfig& config,
                      const JunctionEnds& junction_ends = {});

/// The solved cable and its measures.
struct CableRelaxation {
  CableSetup setup;
  SimulationResult result;
  Polyline relaxed;                ///< uniformly sampled solution, s [m], points 3 x n [m]
  Eigen::VectorXd deviation;       ///< n [m] distance of each relaxed sample to the drawn route
  double max_deviation = 0.0;      ///< [m]
  double rms_deviation = 0.0;      ///< [m]
  double max_deviation_s = 0.0;    ///< [m]
  double min_bend_radius = 0.0;    ///< [m] (infinity when straight)
  double min_bend_radius_s = 0.0;  ///< [m]
  bool bend_flag = false;          ///< min bend radius < factor * diameter
  double bend_limit = 0.0;         ///< [m] the set-up's min_bend_radius_limit, else factor * diameter
  double max_tension = 0.0;        ///< [N] largest axial force along the cable (pull > 0)
  double max_tension_s = 0.0;      ///< [m]
  /// The cable between two consecutive supports that hold its position (not sliding).
  struct Stretch {
    double s0 = 0.0, s1 = 0.0;  ///< [m] its ends along the cable
    double chord = 0.0;         ///< [m] distance of the two supports
    double slack = 0.0;         ///< (cable length - chord) / chord
    bool taut = false;          ///< slack < kTautSlack
  };
  std::vector<Stretch> stretches;
  bool taut = false;  ///< some stretch is taut
  /// Why it moved: the same set-up solved without gravity is the cable springing back towards
  /// its natural shape; `springback_max` [m] is that shape's largest distance to the drawn
  /// route, `sag_max` [m] the largest distance gravity then adds (same arc length). Unset when
  /// not computed (`split_note` says why).
  std::optional<double> springback_max, sag_max;
  std::string split_note;
  double seconds = 0.0;
  /// [s] of `seconds`: measuring the solved shape (deviation, bend, tension) and the
  /// springback/sag split; shared by the cables of a network, measured together.
  double measure_seconds = 0.0;
  bool ok() const { return result.converged; }
};

/// Sets springback_max and sag_max from the same set-up's equilibrium without gravity
/// (`weightless`: its centreline, s from 0 [m], points 3 x n [m]); r->relaxed must be measured.
void MeasureSpringbackAndSag(const Polyline& weightless, CableRelaxation* r);

/// Solves the set-up starting from the drawn route and measures the result.
CableRelaxation RelaxCable(CableSetup setup, const SimulationOptions& options,
                           double min_bend_radius_factor);

/// Fills relaxed, deviation and bend radius from `r->result` (its centreline and frames).
void MeasureRelaxation(double min_bend_radius_factor, CableRelaxation* r);
/// The part of MeasureRelaxation that needs no drawn route: min bend radius (and flag), max
/// tension, stretches (what a motion sweep measures at every pose).
void MeasureBendAndTension(double min_bend_radius_factor, CableRelaxation* r);

/// Samples along a relaxed cable for output (at least 201, about one per millimetre up to 2001).
int OutputSamples(double length);  // length [m]

/// The per-cable object of `<stem>.json`.
json::Json CableToJson(const CableRelaxation& r, const DrawnCable& drawn);

}  // namespace cablefit::addin
