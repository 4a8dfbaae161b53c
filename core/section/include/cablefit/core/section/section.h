// Stiffness and mass of a composite cable cross-section made of circular discs and annuli (wires,
// insulation, fillers, tapes, conduits, jackets), after Wienss et al., "Simulation of wiring
// harnesses and hoses for product design and manufacturing", section 4 "Precomputation of Material Properties": eq. 1-2 bending stiffness matrix about the
// modulus-weighted centre, eq. 4 / 9 coaxial closed forms, eq. 5-6 Prandtl torsion (solved
// numerically in section_torsion.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cablefit/core/rod/rod_spec.h"
#include "cablefit/core/section/section_spec.h"
#include "cablefit/core/section/section_torsion.h"

namespace cablefit {

using Mat2 = Eigen::Matrix2d;

/// Throws InvalidInput (one line, names the part) on empty sections, non-finite or non-positive
/// radii/moduli, inner >= outer radius, negative density, two parts whose areas overlap, or a
/// part straddling the boundary of a gap filler.
void ValidateSection(const SectionSpec& spec);

/// Closed forms for a coaxial section (all parts share one centre): Wienss et al. eq. 4 and eq. 9.
struct CoaxialClosedForm {
  bool applies = false;               // every part centred on one point (within 1e-9 * size)
  double bending_stiffness = 0.0;     // eq. 4, sum pi/4 E_i (R1^4 - R2^4) [N m^2]
  double torsional_stiffness = 0.0;   // eq. 9, sum pi/2 G_i (R1^4 - R2^4) [N m^2]
};

struct SectionResult {
  double area = 0.0;                  // material area [m^2]
  double axial_stiffness = 0.0;       // sum E_i A_i [N]
  double linear_density = 0.0;        // sum rho_i A_i [kg/m]
  Vec2 modulus_centre = Vec2::Zero(); // 2 [m], E-weighted centre s0 of eq. 2
  Vec2 enclosing_centre = Vec2::Zero();  // 2 [m], centre of the smallest enclosing circle
  double outer_diameter = 0.0;        // [m], diameter of the smallest enclosing circle
  /// Eq. 2: B_ij = int E (s - s0)_i (s - s0)_j dA, 2 x 2 [N m^2]. B_xx resists bending whose
  /// strain varies along x, i.e. curvature about the y axis.
  Mat2 bending_matrix = Mat2::Zero();
  double bending_max = 0.0;           // largest eigenvalue of B [N m^2]
  double bending_min = 0.0;           // smallest eigenvalue of B [N m^2]
  /// [rad] in (-pi/2, pi/2]: angle from x of the rotation axis about which the section is
  /// stiffest (perpendicular to the eigenvector of B_max, which is the strain direction).
  double principal_angle = 0.0;
  CoaxialClosedForm coaxial;
  TorsionResult torsion;
  /// Sum of the parts' own eq. 9 values: the torsional stiffness when separate wires twist
  /// freely against each other (a lower bound to the bonded value; for a gap filler its polar
  /// moment is used, which over-estimates that part's own GJ).
  double torsion_unbonded = 0.0;      // [N m^2]
  /// Sum of the parts' own smallest E_i I_i about their own centroids: the bending stiffness
  /// when the parts slip freely (a lower bound to the bonded eigenvalues).
  double bending_unbonded = 0.0;      // [N m^2]
  std::vector<std::string> notes;     // modelling assumptions and limits, one sentence each
};

/// Validates `spec`, then computes bending (exact, analytic over discs and annuli), mass and
/// the bonded Prandtl torsion (numerical, `options`; UsageError when they are invalid).
SectionResult ComputeSection(const SectionSpec& spec, const TorsionOptions& options);

/// Smallest circle enclosing every part's outer circle (for `outer_diameter` and for wrapping
/// tapes around a bundle). Returns centre 2 [m] and radius [m].
void SmallestEnclosingCircle(const std::vector<SectionPart>& parts, Vec2* centre, double* radius);

/// True when the annuli of `a` and `b` overlap by more than `tolerance` [m] (touching is
/// allowed); fills_gaps is ignored.
bool PartsOverlap(const SectionPart& a, const SectionPart& b, double tolerance);

/// True when the outer disc of `inner` lies within the annulus of `outer` (to `tolerance` [m]).
bool PartInsideAnnulus(const SectionPart& inner, const SectionPart& outer, double tolerance);

/// For every part with fills_gaps, the indices of the parts whose outer discs it excludes: the
/// parts inside its annulus that are not themselves inside another such part's outer disc
/// (empty lists for ordinary parts). `parts` must be valid.
std::vector<std::vector<int>> FillerExclusions(const std::vector<SectionPart>& parts);

/// The rod material a section stands for: bending_stiffness = sqrt(B_max B_min), bending_ratio =
/// B_max / B_min, principal_angle, torsional_stiffness = bonded numerical GJ (extrapolated),
/// linear_density, diameter = outer_diameter.
MaterialSpec SectionToMaterial(const SectionResult& result);

}  // namespace cablefit
