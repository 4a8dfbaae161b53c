// The parts of a composite cable cross-section (plain data; ValidateSection in section.h checks
// it). Section coordinates: x is the rod's material direction d1, y is d2, lengths in metres.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cablefit {

using Vec2 = Eigen::Vector2d;

/// A linear-elastic isotropic material (effective values: a stranded conductor carries an
/// effective bending modulus far below the solid metal's, see samples/materials).
struct SectionMaterial {
  std::string name;
  double youngs_modulus = 0.0;  // E [Pa]
  double shear_modulus = 0.0;   // G [Pa]
  double density = 0.0;         // [kg/m^3]
};

/// One circular part: a disc (inner_radius = 0) or an annulus, filled with one material.
struct SectionPart {
  std::string name;
  Vec2 centre = Vec2::Zero();  // 2 [m]
  double outer_radius = 0.0;   // [m]
  double inner_radius = 0.0;   // [m], 0 = solid disc
  SectionMaterial material;
  /// A matrix (extruded jacket, filler compound): occupies its annulus minus the outer discs of
  /// the other parts lying inside it, so it bonds them and leaves no gaps.
  bool fills_gaps = false;
};

/// A whole cross-section: parts must not overlap (touching is allowed), except that a part
/// with fills_gaps may contain others entirely.
struct SectionSpec {
  std::vector<SectionPart> parts;
};

}  // namespace cablefit
