// Saint-Venant torsion of a bonded composite section by the Prandtl stress function, Wienss
// et al. eq. 5-6: div((1/G) grad phi) = -2 in the material, phi = 0 on the outer boundary,
// GJ = 2 * integral(phi) for unit twist rate.
//
// Discretisation (section_torsion.cc): finite volumes on a uniform Cartesian grid with the
// symmetric cut-edge treatment of Gibou, Fedkiw, Cheng, Kang, "A second-order-accurate symmetric
// discretization of the Poisson equation on irregular domains", J. Comput. Phys. 176 (2002):
// every grid edge gets the exact harmonic coefficient 1 / mean(G along the edge), computed from
// the circles' exact crossings. Voids (no material) are the limit G -> 0, i.e. 1/G -> infinity:
// grid nodes joined through void edges share one unknown. A void connected to the outside is
// held at phi = 0; an enclosed void (a hole, e.g. the gaps between wires inside a tape) gets one
// free constant, and minimising the discrete complementary energy then imposes exactly the
// Bredt-Batho circulation condition  contour (1/G) dphi/dn ds = 2 A_hole  on its boundary, and
// counts the hole in integral(phi). Three nested grids give an observed order and a Richardson
// extrapolation with Roache's grid convergence index as error estimate (Roache, "Quantification
// of uncertainty in computational fluid dynamics", Annu. Rev. Fluid Mech. 29, 1997).
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/section/section_spec.h"

namespace cablefit {

struct TorsionOptions {
  /// Grid cells across the larger side of the section's bounding box on the finest grid.
  int finest_cells = 512;
  /// Number of nested grids (finest_cells / 2^k, k = 0..levels-1); >= 2 for an error estimate.
  int levels = 3;
  /// False (with a reason) when finest_cells < 8 * 2^(levels-1) or > 1024, or levels < 2 or > 6.
  bool IsValid(std::string* why) const;
};

/// One grid of the refinement study.
struct TorsionGridResult {
  int cells = 0;                     // cells across the bounding box
  double spacing = 0.0;              // h [m]
  int unknowns = 0;                  // size of the linear system
  int enclosed_voids = 0;            // holes carrying a free constant phi (incl. grid-size cusps)
  double enclosed_void_area = 0.0;   // their area counted in grid cells [m^2]
  double torsional_stiffness = 0.0;  // GJ on this grid [N m^2]
  double seconds = 0.0;              // wall time of this grid
};

enum class TorsionConvergence {
  kAsymptotic,   ///< three grids converge monotonically with observed order in [0.5, 4]:
                 ///< value = Richardson extrapolation, error = GCI with safety factor 1.25
  kIrregular,    ///< differences change sign or the order is outside [0.5, 4]: value = finest
                 ///< grid, error = largest difference between the two finest grids' results
  kTwoGrids,     ///< only two grids: value = finest, error = GCI assuming order 2, factor 3
};
const char* ToString(TorsionConvergence c);

struct TorsionResult {
  std::vector<TorsionGridResult> grids;  // coarsest first
  TorsionConvergence convergence = TorsionConvergence::kTwoGrids;
  double observed_order = 0.0;        // p from three grids (0 when not available)
  double finest = 0.0;                // GJ on the finest grid [N m^2]
  double extrapolated = 0.0;          // Richardson value (= finest unless kAsymptotic) [N m^2]
  double torsional_stiffness = 0.0;   // the reported value (see TorsionConvergence) [N m^2]
  double error_estimate = 0.0;        // estimated absolute error of the reported value [N m^2]
  std::string BriefReport() const;
};

/// A stretch of one grid line inside material of shear modulus G.
struct SectionInterval {
  double begin = 0.0;          // [m] along the line
  double end = 0.0;            // [m]
  double shear_modulus = 0.0;  // [Pa]
};

/// What the torsion solver needs to know of a section: where each grid line runs in material.
class SectionRegion {
 public:
  virtual ~SectionRegion() = default;
  /// Bounding box of the material, 2 [m] each.
  virtual void Bounds(Vec2* lo, Vec2* hi) const = 0;
  /// Disjoint stretches of material on the line {coordinate (1 - along) = offset}, where
  /// `along` = 0 means the line runs along x, 1 along y.
  virtual std::vector<SectionInterval> LineIntervals(int along, double offset) const = 0;
  /// Largest shear modulus in the region [Pa].
  virtual double MaxShearModulus() const = 0;
};

/// Non-overlapping discs and annuli and gap fillers (validate first with ValidateSection).
/// Keeps a reference to `parts`.
class CircularPartsRegion : public SectionRegion {
 public:
  explicit CircularPartsRegion(const std::vector<SectionPart>& parts);
  void Bounds(Vec2* lo, Vec2* hi) const override;
  std::vector<SectionInterval> LineIntervals(int along, double offset) const override;
  double MaxShearModulus() const override;

 private:
  const std::vector<SectionPart>& parts_;
  std::vector<std::vector<int>> excluded_;  // per gap filler, the discs cut out of it
};

/// An axis-aligned homogeneous rectangle (flat conductors; torsion reference tests).
class RectangleRegion : public SectionRegion {
 public:
  RectangleRegion(const Vec2& lo, const Vec2& hi, double shear_modulus)
      : lo_(lo), hi_(hi), shear_modulus_(shear_modulus) {}
  void Bounds(Vec2* lo, Vec2* hi) const override;
  std::vector<SectionInterval> LineIntervals(int along, double offset) const override;
  double MaxShearModulus() const override { return shear_modulus_; }

 private:
  Vec2 lo_, hi_;          // 2 [m] corners
  double shear_modulus_;  // [Pa]
};

/// GJ of the bonded section `region` on one grid with `cells` cells across its bounding box.
TorsionGridResult SolvePrandtlTorsionOnGrid(const SectionRegion& region, int cells);

/// Refinement study over options.levels nested grids. Throws UsageError on invalid options.
TorsionResult SolvePrandtlTorsion(const SectionRegion& region, const TorsionOptions& options);

}  // namespace cablefit
