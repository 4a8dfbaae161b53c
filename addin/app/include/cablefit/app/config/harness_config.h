// harness.json (format "cablefit-harness/1"): the physics a CAD drawing does not carry, per
// cable name, for `cablefit relax`. Every field is optional; what is missing is defaulted (and
// the relax output says so). Format described in the relax command's README text.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "cablefit/core/rod/rod_spec.h"

namespace cablefit::addin {

/// How a cable end is held: clamped at its drawn pose (the default), clipped, pinned or free.
struct EndConfig {
  bool free = false;  ///< no support at this end
  SupportKind kind = SupportKind::kClamp;
  bool sliding = false;  ///< free translation along the end tangent (clamp or clip)
};

/// An extra support, placed by arc length or by the point nearest on the drawn route.
struct ExtraSupportConfig {
  SupportKind kind = SupportKind::kClip;
  std::optional<double> s;    ///< [m] arc length along the drawn route
  std::optional<Vec3> point;  ///< [m] support position; s = nearest arc length
  bool sliding = false;
};

/// The length a cable is built with: as drawn, a length in metres, or the drawn length changed
/// by a fraction (harness makers cut cables a few per cent longer than the drawing).
struct CableLength {
  enum class Kind { kDrawn, kMetres, kRelative };
  Kind kind = Kind::kDrawn;
  double value = 0.0;  ///< [m] for kMetres; the fraction (0.02 = "+2%") for kRelative
  double For(double drawn_length) const;  ///< [m]
  std::string ToString() const;           ///< "drawn", "0.52 m", "+2%"
};

/// What harness.json says about one cable (or the defaults for all cables).
/// Stiffness and weight added over part of a cable (a KBL protection: tape, corrugated tube), as
/// shares of its length so that they stay where they are when harness.json changes the length.
struct SleeveConfig {
  double from = 0.0, to = 1.0;       ///< shares of the cable's length, 0 <= from < to <= 1
  double bending_stiffness = 0.0;    ///< EI added [N m^2]
  double torsional_stiffness = 0.0;  ///< GJ added [N m^2]
  double linear_density = 0.0;       ///< [kg/m] added
};

struct CableConfig {
  /// Rod material without diameter; unset -> derived from the diameter (see relax_material.h).
  std::optional<MaterialSpec> material;
  std::string material_source;     ///< "harness.json", or the section file it came from
  /// [m] a cable's own overrides the drawn diameter; one from "default" only fills in for a
  /// cable drawn without one (a bare curve), since the CAD solid's diameter is a measurement.
  std::optional<double> diameter;
  bool diameter_from_default = false;
  std::optional<CableLength> length;
  std::optional<Vec3> gravity;     ///< [m/s^2]
  std::optional<EndConfig> start, end;
  std::vector<ExtraSupportConfig> supports;
  std::optional<bool> auto_clips;  ///< add a clip where the route passes a solid (default on)
  /// [m] the smallest bend radius the cable allows, when its data give one (a KBL file's wires);
  /// unset -> HarnessConfig::min_bend_radius_factor diameters. Not read from harness.json.
  std::optional<double> min_bend_radius;
  std::string min_bend_radius_source;  ///< where min_bend_radius came from
  /// [m] the least surface distance the cable must keep from solids and other cables
  /// ("min_clearance"); unset = none asked (clearances are still measured and reported).
  std::optional<double> min_clearance;
  /// Sleeves over parts of the cable (a KBL file's protections). Not read from harness.json;
  /// they stay when harness.json gives the cable's material (they sit on top of it).
  std::vector<SleeveConfig> sleeves;

  /// [m] the diameter a cable drawn with `drawn_diameter` (0: none) is relaxed with; 0 when
  /// neither the drawing nor harness.json gives one.
  double DiameterFor(double drawn_diameter) const;
};

/// A breakout or splice declared in harness.json: the listed cable ends are joined (whether or
/// not the drawing puts them together; they are expected to meet).
struct JunctionConfig {
  std::string name;
  struct End {
    std::string cable;
    bool at_start = true;
  };
  std::vector<End> ends;     ///< two or more
  double compliance = 0.0;   ///< [rad/(N m)] of every branch attachment, 0 = rigid
  double mass = 0.0;         ///< [kg]
};

/// A motion of the harness ("motion" in harness.json): chosen supports follow a rigid motion
/// (a door hinge: a rotation about an axis through a point; a seat rail: a translation) from
/// `from` to `to` in `steps` equal steps and, when `there_and_back`, back again. The drawing is
/// the pose at parameter 0.
struct MotionConfig {
  enum class Kind { kRotation, kTranslation, kPoses };
  std::string name = "motion";
  Kind kind = Kind::kRotation;
  Vec3 axis = Vec3::UnitZ();       ///< unit; rotation axis or translation direction
  Vec3 point = Vec3::Zero();       ///< [m] a point on the rotation axis
  double from = 0.0, to = 0.0;     ///< [rad] for a rotation, [m] for a translation, pose numbers
  /// >= 1 poses after the first, each way; for a list of poses, the steps from one listed pose
  /// to the next.
  int steps = 10;
  /// A list of poses (Kind::kPoses): rigid motions of the moving parts from their drawn place;
  /// the drawing is pose 0, listed pose k is parameter k, and between two poses the motion
  /// follows the screw from one to the other (turning about and shifting along its axis evenly:
  /// a hinge swings on its arc).
  std::vector<Eigen::Isometry3d> poses;
  bool there_and_back = true;
  /// One moving support: of cable `cable`, its "start", "end" or the index-th support of the
  /// cable's set-up (the order of the relax JSON's "supports").
  struct MovingSupport {
    std::string cable;
    std::string at;  ///< "start" or "end"; empty when `index` is used
    int index = -1;
  };
  std::vector<MovingSupport> supports;
  /// Name patterns (shell globs, as in "solids") of the drawing's solids that move too: the
  /// supports attached to them (clips found on them, cable ends held in them) move with them,
  /// clearance is measured to them where they are at each pose, and contact follows them.
  std::vector<std::string> solids;
  /// Points of cables whose path over the motion is reported ("track": cable and arc length).
  struct TrackedPoint {
    std::string cable;
    double s = 0.0;  ///< [m] along the cable
  };
  std::vector<TrackedPoint> tracks;
  /// The rigid motion at parameter q ([rad], [m] or a pose number): maps a drawn point to its
  /// moved place.
  Eigen::Isometry3d At(double q) const;
  /// The parameters of the poses: from, ..., to (steps + 1) and, there and back, back to from.
  std::vector<double> Poses() const;
  /// "rotation", "translation" or "poses".
  const char* KindName() const;
};

/// "tolerances": relative +- variations of every cable's length, bending (and torsional)
/// stiffness and linear density, and the +- shift of every fixing along its cable; 0 = not
/// varied. The tolerance envelope solves the corners of that box.
struct ToleranceConfig {
  double length = 0.0;             ///< e.g. 0.02 = +-2 % of the built length
  double bending_stiffness = 0.0;  ///< scales EI and GJ together
  double linear_density = 0.0;
  /// [m] where on the cable each support between its ends holds it (a clip's taped position on
  /// the bundle), +- this; the support itself stays where it is in the vehicle.
  double clip_position = 0.0;
  bool any() const {
    return length > 0 || bending_stiffness > 0 || linear_density > 0 || clip_position > 0;
  }
};

struct HarnessConfig {
  std::string path;                           ///< empty when no --config was given
  Vec3 gravity = Vec3(0, 0, -9.81);           ///< [m/s^2] model frame of the CAD file
  double min_bend_radius_factor = 5.0;        ///< flag bends tighter than this many diameters
  CableConfig defaults;                       ///< "default": applies to every cable
  std::map<std::string, CableConfig> cables;  ///< by cable name
  std::vector<JunctionConfig> junctions;      ///< declared junctions
  /// Applied to junctions found in the drawing (ends of 3+ cables meeting).
  double junction_compliance = 0.0;  ///< [rad/(N m)]
  double junction_mass = 0.0;        ///< [kg]

  /// Name patterns as in a shell ('*', '?', "[abc]"): a drawn cable whose name matches one of
  /// `rigid`, or none of `only` when `only` is given, is a rigid part (a pipe, a bar), not a
  /// cable: it is kept as a solid and never relaxed.
  std::vector<std::string> rigid, only;
  /// Name patterns of pre-formed cables (a coiled cable, a moulded hose): still relaxed, but
  /// their drawn shape is their rest shape, so they only sag from it under their weight.
  std::vector<std::string> preformed;
  /// "solids": {"<name pattern>": {"min_clearance": m}}: the least surface distance cables must
  /// keep from the solids a pattern names; when several match a solid, the largest applies.
  std::vector<std::pair<std::string, double>> solid_clearances;
  std::optional<MotionConfig> motion;
  std::optional<ToleranceConfig> tolerances;

  /// [m] the min_clearance harness.json asks of solid `name`; 0 when none.
  double SolidMinClearance(const std::string& name) const;

  /// `defaults` overlaid with the entry for `name` (if any).
  CableConfig For(const std::string& name) const;
  /// Why the cable `name` is a rigid part by `rigid` / `only`; empty when it is a cable.
  std::string RigidReason(const std::string& name) const;
  /// Why the cable `name` keeps its drawn shape as rest shape (`preformed`); empty when not.
  std::string PreformedReason(const std::string& name) const;
};

/// `base` with every field that `top` sets replaced by top's (supports: when top has any). The
/// layering of a cable's own harness.json entry over what an input file says about the cable.
CableConfig Overlaid(CableConfig base, const CableConfig& top);

/// Reads and validates harness.json. Throws FileError naming the file and field.
HarnessConfig ReadHarnessConfig(const std::string& path);

}  // namespace cablefit::addin
