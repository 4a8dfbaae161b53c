// The user-editable description of one cable set-up (from case.json, harness.json or CAD).
// It is plain data; CompileRodModel() validates it and turns it into an immutable RodModel.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

enum class SupportKind {
  kClamp,  ///< position and full frame fixed
  kClip,   ///< position and tangent fixed, free rotation about the tangent
  kPin,    ///< position fixed, free rotation
};
const char* ToString(SupportKind kind);
/// Accepts "clamp", "clip", "pin"; throws InvalidInput otherwise.
SupportKind SupportKindFromString(const std::string& name);

/// A support at arc length `s`. `tangent`/`normal` follow recording-v1 (need not be unit).
struct SupportSpec {
  SupportKind kind = SupportKind::kClamp;
  double s = 0.0;                    // [m]
  Vec3 position = Vec3::Zero();      // [m]
  Vec3 tangent = Vec3::UnitX();      // direction of increasing s (clamp, clip)
  Vec3 normal = Vec3::UnitZ();       // material d1 (clamp)
  /// Compliant clamp: rotation = compliance * moment, 3x3 in the clamp frame (d1, d2, d3)
  /// [rad/(N m)]. Absent = rigid. Only meaningful for kClamp.
  std::optional<Mat3> compliance;
  /// Sliding support: free translation along its tangent (clamp or clip only).
  bool sliding = false;
};

/// A natural (intrinsic) curvature/twist over [s_start, s_end], switched on and off by smooth
/// ramps of width `ramp` inside the interval. Components in the material frame (d1, d2, d3).
struct NaturalCurvatureSpec {
  double s_start = 0.0;  // [m]
  double s_end = 0.0;    // [m]
  double ramp = 0.0;     // [m], 0 = sharp
  Vec3 kappa = Vec3::Zero();  // [1/m] (bending about d1, bending about d2, twist)
};

/// A dead point load at arc length `s` (world frame).
struct PointLoadSpec {
  double s = 0.0;               // [m]
  Vec3 force = Vec3::Zero();    // [N]
};

struct MaterialSpec {
  double bending_stiffness = 0.0;    // EI [N m^2]; isotropic nominal, or the geometric mean
  double bending_ratio = 1.0;        // B_max / B_min (>= 1); 1 = isotropic
  double principal_angle = 0.0;      // [rad] angle of the B_max bending axis from d1 about d3
  double torsional_stiffness = 0.0;  // GJ [N m^2]
  double linear_density = 0.0;       // [kg/m]
  double diameter = 0.0;             // [m]
  /// EA [N]: stretching under tension. 0 = inextensible (exact for a cable with slack, where
  /// the tension is orders below EA); a cable drawn taut between two supports needs it, since
  /// an inextensible one has no defined tension there.
  double axial_stiffness = 0.0;
};

/// The largest stretch (strain) an extensible cable may need to reach its supports: beyond it the
/// linear law T = EA strain the solver uses no longer describes a cable (insulation and copper
/// yield long before), so a cable cut that much shorter than its span is a length error.
constexpr double kMaxAxialStrain = 0.1;

/// A sleeve over part of the cable: a protection of a harness segment (tape, corrugated tube,
/// heat-shrink, a hose over a bundle), or anything else that adds stiffness and weight to the
/// cable over [s_begin, s_end] only. Its bending and torsional stiffness act in parallel with the
/// cable's own there (isotropic in bending), its mass per length adds to the cable's.
struct SleeveSpec {
  double s_begin = 0.0;              // [m]
  double s_end = 0.0;                // [m], > s_begin
  double bending_stiffness = 0.0;    // EI added [N m^2]
  double torsional_stiffness = 0.0;  // GJ added [N m^2]
  double linear_density = 0.0;       // [kg/m] added
};

struct RodSpec {
  std::string name;
  double length = 0.0;  // [m]
  MaterialSpec material;
  std::vector<SleeveSpec> sleeves;  ///< sleeves may overlap: where they do, both add
  Vec3 gravity = Vec3(0, 0, -9.81);  // [m/s^2]
  std::vector<SupportSpec> supports;
  std::vector<NaturalCurvatureSpec> natural_curvature;
  std::vector<PointLoadSpec> point_loads;
};

}  // namespace cablefit
