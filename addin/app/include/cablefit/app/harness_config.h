// harness.json (format "cablefit-harness/1"): the physics a CAD drawing does not carry, per
// cable name, for `cablefit relax`. Every field is optional; what is missing is defaulted (and
// the relax output says so). Format described in the relax command's README text.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

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

  /// `defaults` overlaid with the entry for `name` (if any).
  CableConfig For(const std::string& name) const;
  /// Why the cable `name` is a rigid part by `rigid` / `only`; empty when it is a cable.
  std::string RigidReason(const std::string& name) const;
};

/// `base` with every field that `top` sets replaced by top's (supports: when top has any). The
/// layering of a cable's own harness.json entry over what an input file says about the cable.
CableConfig Overlaid(CableConfig base, const CableConfig& top);

/// Reads and validates harness.json. Throws FileError naming the file and field.
HarnessConfig ReadHarnessConfig(const std::string& path);

}  // namespace cablefit::addin
