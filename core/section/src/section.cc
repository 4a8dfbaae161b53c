// Composite section properties after Wienss et al. (section 4): eq. 2 integrated exactly over discs and
// annuli (parallel-axis theorem about the E-weighted centre), eq. 4 and 9 for coaxial sections.
#include "cablefit/core/section/section.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

constexpr double kPi = std::numbers::pi;

// Largest distance from the origin reached by any part [m]: the length scale for tolerances.
double SectionScale(const SectionSpec& spec) {
  double scale = 0.0;
  for (const SectionPart& p : spec.parts) {
    scale = std::max(scale, p.centre.norm() + p.outer_radius);
  }
  return scale;
}

// A signed annulus: gap fillers are their annulus minus the discs of the parts they contain.
struct Piece {
  Vec2 centre;           // 2 [m]
  double outer, inner;   // [m]
  double sign;           // +1 material, -1 removed
  const SectionMaterial* material;
};

std::vector<Piece> Pieces(const std::vector<SectionPart>& parts) {
  const std::vector<std::vector<int>> excluded = FillerExclusions(parts);
  std::vector<Piece> pieces;
  for (size_t i = 0; i < parts.size(); ++i) {
    const SectionPart& p = parts[i];
    pieces.push_back({p.centre, p.outer_radius, p.inner_radius, 1.0, &p.material});
    for (int k : excluded[i]) {
      pieces.push_back({parts[k].centre, parts[k].outer_radius, 0.0, -1.0, &p.material});
    }
  }
  return pieces;
}

std::string PartLabel(const SectionPart& p, size_t index) {
  return p.name.empty() ? "part " + std::to_string(index + 1) : "part '" + p.name + "'";
}

}  // namespace

// Plausibility bounds, far outside any cable or hose but well inside double range: beyond them
// the fourth powers in the stiffness integrals overflow and the result is NaN, not an error.
constexpr double kMaxSectionExtent = 1.0;   // [m] from the origin of the section's coordinates
constexpr double kMaxModulus = 1e13;        // [Pa] diamond is 1.2e12
constexpr double kMaxDensity = 1e5;         // [kg/m^3] osmium is 2.26e4

void ValidateSection(const SectionSpec& spec) {
  if (spec.parts.empty()) throw InvalidInput("section has no components");
  for (size_t i = 0; i < spec.parts.size(); ++i) {
    const SectionPart& p = spec.parts[i];
    const std::string label = PartLabel(p, i);
    if (!p.centre.allFinite()) throw InvalidInput(label + ": position is not finite");
    if (!std::isfinite(p.outer_radius) || p.outer_radius <= 0.0) {
      throw InvalidInput(label + ": outer radius must be finite and > 0");
    }
    if (p.centre.norm() + p.outer_radius > kMaxSectionExtent) {
      throw InvalidInput(label + ": reaches " + MessageNumber(p.centre.norm() + p.outer_radius) +
                         " m from the section's origin; a cable section lies within " +
                         MessageNumber(kMaxSectionExtent) + " m (lengths are in metres)");
    }
    if (!std::isfinite(p.inner_radius) || p.inner_radius < 0.0 ||
        p.inner_radius >= p.outer_radius) {
      throw InvalidInput(label + ": inner radius must be finite, >= 0 and < outer radius");
    }
    const SectionMaterial& m = p.material;
    if (!std::isfinite(m.youngs_modulus) || m.youngs_modulus <= 0.0 || m.youngs_modulus > kMaxModulus) {
      throw InvalidInput(label + ": Young's modulus E must be > 0 and at most " +
                         MessageNumber(kMaxModulus) + " Pa");
    }
    if (!std::isfinite(m.shear_modulus) || m.shear_modulus <= 0.0 || m.shear_modulus > kMaxModulus) {
      throw InvalidInput(label + ": shear modulus G must be > 0 and at most " +
                         MessageNumber(kMaxModulus) + " Pa");
    }
    if (!std::isfinite(m.density) || m.density < 0.0 || m.density > kMaxDensity) {
      throw InvalidInput(label + ": density must be >= 0 and at most " + MessageNumber(kMaxDensity) +
                         " kg/m^3");
    }
  }
  // Round-off in hand-written or CAD coordinates must not turn touching wires into overlaps.
  const double tolerance = 1e-6 * SectionScale(spec);
  for (size_t i = 0; i < spec.parts.size(); ++i) {
    for (size_t j = i + 1; j < spec.parts.size(); ++j) {
      const SectionPart& a = spec.parts[i];
      const SectionPart& b = spec.parts[j];
      if (!PartsOverlap(a, b, tolerance)) continue;
      if (a.fills_gaps && PartInsideAnnulus(b, a, tolerance)) continue;
      if (b.fills_gaps && PartInsideAnnulus(a, b, tolerance)) continue;
      const bool filler = a.fills_gaps || b.fills_gaps;
      throw InvalidInput(PartLabel(a, i) + " and " + PartLabel(b, j) +
                         (filler ? " overlap (a part must lie wholly inside a gap filler or "
                                   "wholly outside it)"
                                 : " overlap"));
    }
  }
}

SectionResult ComputeSection(const SectionSpec& spec, const TorsionOptions& options) {
  ValidateSection(spec);
  std::string why;
  if (!options.IsValid(&why)) throw UsageError("section options: " + why);
  SectionResult r;
  const std::vector<Piece> pieces = Pieces(spec.parts);
  Vec2 first_moment = Vec2::Zero();  // 2 [N m], sum E_i A_i c_i
  for (const Piece& p : pieces) {
    const double area = p.sign * kPi * (p.outer * p.outer - p.inner * p.inner);
    r.area += area;
    r.axial_stiffness += p.material->youngs_modulus * area;
    r.linear_density += p.material->density * area;
    first_moment += p.material->youngs_modulus * area * p.centre;
  }
  r.modulus_centre = first_moment / r.axial_stiffness;

  // Unbonded bounds per part: own E I about the part's own centroid, and eq. 9 per part (for a
  // gap filler the polar moment of its holed area, an over-estimate of its own GJ).
  const double coaxial_tolerance = 1e-9 * SectionScale(spec);
  r.coaxial.applies = true;
  std::vector<double> part_area(spec.parts.size(), 0.0);
  for (const Piece& p : pieces) {
    const double r4 = std::pow(p.outer, 4) - std::pow(p.inner, 4);
    const double area = p.sign * kPi * (p.outer * p.outer - p.inner * p.inner);
    const Vec2 offset = p.centre - r.modulus_centre;  // 2 [m]
    const double e = p.material->youngs_modulus;
    r.bending_matrix += e * (p.sign * 0.25 * kPi * r4 * Mat2::Identity() +
                             area * offset * offset.transpose());
    if ((p.centre - spec.parts[0].centre).norm() > coaxial_tolerance) r.coaxial.applies = false;
  }
  const std::vector<std::vector<int>> excluded = FillerExclusions(spec.parts);
  for (size_t i = 0; i < spec.parts.size(); ++i) {
    const SectionPart& p = spec.parts[i];
    const double r4 = std::pow(p.outer_radius, 4) - std::pow(p.inner_radius, 4);
    double area = kPi * (p.outer_radius * p.outer_radius - p.inner_radius * p.inner_radius);
    Vec2 moment = area * p.centre;  // 2 [m^3]
    double i_polar_origin = 0.5 * kPi * r4 + area * p.centre.squaredNorm();  // [m^4]
    Mat2 i_origin = 0.25 * kPi * r4 * Mat2::Identity() + area * p.centre * p.centre.transpose();
    for (int k : excluded[i]) {
      const SectionPart& q = spec.parts[k];
      const double qa = kPi * q.outer_radius * q.outer_radius, q4 = std::pow(q.outer_radius, 4);
      area -= qa;
      moment -= qa * q.centre;
      i_polar_origin -= 0.5 * kPi * q4 + qa * q.centre.squaredNorm();
      i_origin -= 0.25 * kPi * q4 * Mat2::Identity() + qa * q.centre * q.centre.transpose();
    }
    const Vec2 c = moment / area;  // 2 [m] the part's own centroid
    const Mat2 own = i_origin - area * c * c.transpose();  // 2 x 2 [m^4]
    r.bending_unbonded += p.material.youngs_modulus *
                          Eigen::SelfAdjointEigenSolver<Mat2>(own).eigenvalues()[0];
    r.torsion_unbonded += p.material.shear_modulus * (i_polar_origin - area * c.squaredNorm());
  }
  if (r.coaxial.applies) {
    r.coaxial.bending_stiffness = r.bending_matrix(0, 0);  // eq. 4 (B is isotropic)
    r.coaxial.torsional_stiffness = r.torsion_unbonded;    // eq. 9
  }

  const Eigen::SelfAdjointEigenSolver<Mat2> eig(r.bending_matrix);
  r.bending_min = eig.eigenvalues()[0];
  r.bending_max = eig.eigenvalues()[1];
  // Below 1e-6 the axes are round-off of an isotropic section (e.g. coordinates in nm).
  if (r.bending_max - r.bending_min > 1e-6 * r.bending_max) {
    // The eigenvector is the strain direction; the bending (rotation) axis is 90 degrees on.
    const Vec2 v = eig.eigenvectors().col(1);
    double angle = std::atan2(v.x(), -v.y());
    if (angle <= -kPi / 2) angle += kPi;
    if (angle > kPi / 2) angle -= kPi;
    r.principal_angle = angle;
  }
  SmallestEnclosingCircle(spec.parts, &r.enclosing_centre, &r.outer_diameter);
  r.outer_diameter *= 2.0;

  r.torsion = SolvePrandtlTorsion(CircularPartsRegion(spec.parts), options);

  r.notes.push_back(
      "bending: eq. 2 integrated exactly over discs and annuli about the E-weighted centre; it "
      "assumes plane sections and no slip between parts, so for a loose bundle the real value "
      "lies between bending.unbonded (free slip) and the bonded eigenvalues");
  r.notes.push_back(
      "torsion: Prandtl stress function (eq. 5-6) on nested Cartesian grids with exact cut-edge "
      "coefficients; parts that touch are treated as bonded along their contact");
  if (r.torsion.grids.back().enclosed_voids > 0) {
    r.notes.push_back(
        "torsion: " + std::to_string(r.torsion.grids.back().enclosed_voids) +
        " enclosed void(s) found (e.g. gaps between wires inside a tape): each carries a free "
        "constant stress function fixed by the Bredt-Batho circulation condition, so the "
        "enclosing layer acts as a closed tube; if it can slip or open, use torsion.unbonded");
  }
  // Point contacts between round parts not embedded in a gap filler.
  std::vector<char> embedded(spec.parts.size(), 0);
  for (const std::vector<int>& list : excluded) {
    for (int k : list) embedded[k] = 1;
  }
  int point_contacts = 0;
  const double touch = 1e-6 * SectionScale(spec);
  for (size_t i = 0; i < spec.parts.size(); ++i) {
    for (size_t j = i + 1; j < spec.parts.size(); ++j) {
      const SectionPart& a = spec.parts[i];
      const SectionPart& b = spec.parts[j];
      const double d = (a.centre - b.centre).norm();
      const bool outside = std::abs(d - a.outer_radius - b.outer_radius) < touch;
      const bool in_bore = d > touch && (std::abs(d + b.outer_radius - a.inner_radius) < touch ||
                                         std::abs(d + a.outer_radius - b.inner_radius) < touch);
      if ((outside || in_bore) && !(embedded[i] && embedded[j])) ++point_contacts;
    }
  }
  if (point_contacts > 0) {
    r.notes.push_back(
        "torsion: " + std::to_string(point_contacts) +
        " point contact(s) between round parts: in the continuum limit a point contact carries "
        "no shear flow, so the grid joins the parts over a width ~sqrt(h R) that vanishes with "
        "refinement and the bonded value falls slowly (order ~0.5) towards torsion.unbonded; "
        "read the grid values as upper estimates whose error estimate may be optimistic, and "
        "model a bonded bundle with a gap filler (fills_gaps) instead");
  }
  return r;
}

MaterialSpec SectionToMaterial(const SectionResult& result) {
  MaterialSpec m;
  m.bending_stiffness = std::sqrt(result.bending_max * result.bending_min);
  m.bending_ratio = result.bending_min > 0.0 ? result.bending_max / result.bending_min : 1.0;
  m.principal_angle = result.principal_angle;
  m.torsional_stiffness = result.torsion.torsional_stiffness;
  m.linear_density = result.linear_density;
  m.diameter = result.outer_diameter;
  return m;
}

}  // namespace cablefit
