#include "cablefit/core/section/section.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cablefit/core/base/errors.h"
#include "test_support.h"

namespace cablefit {
namespace {

constexpr double kPi = std::numbers::pi;

SectionPart Part(const std::string& name, Vec2 centre, double outer, double inner, double e,
                 double g, double rho = 1000.0) {
  SectionPart p;
  p.name = name;
  p.centre = centre;
  p.outer_radius = outer;
  p.inner_radius = inner;
  p.material = {name + "-material", e, g, rho};
  return p;
}

TorsionOptions Coarse() {
  TorsionOptions o;
  o.finest_cells = 128;
  return o;
}

// Eq. 2 by brute force: midpoint rule on a fine grid, independent of the parallel-axis sums.
Mat2 BendingByQuadrature(const SectionSpec& spec, int n) {
  Vec2 lo, hi;
  CircularPartsRegion(spec.parts).Bounds(&lo, &hi);
  const double h = (hi - lo).maxCoeff() / n;
  double ea = 0.0;
  Vec2 first = Vec2::Zero();
  Mat2 second = Mat2::Zero();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Vec2 s = lo + h * Vec2(i + 0.5, j + 0.5);
      for (const SectionPart& p : spec.parts) {
        const double d = (s - p.centre).norm();
        if (d < p.outer_radius && d >= p.inner_radius) {
          const double w = p.material.youngs_modulus * h * h;
          ea += w;
          first += w * s;
          second += w * s * s.transpose();
        }
      }
    }
  }
  const Vec2 s0 = first / ea;
  return second - ea * s0 * s0.transpose();
}

TEST(SectionTest, HomogeneousCircleAndTubeMatchClosedForms) {
  const double e = 2e9, g = 0.7e9, r = 1.5e-3, ri = 0.9e-3;
  for (double inner : {0.0, ri}) {
    SectionSpec spec;
    spec.parts = {Part("c", Vec2(1e-3, 2e-3), r, inner, e, g, 1200.0)};
    const SectionResult res = ComputeSection(spec, Coarse());
    const double r4 = std::pow(r, 4) - std::pow(inner, 4);
    EXPECT_NEAR(res.bending_max / (0.25 * kPi * e * r4), 1.0, 1e-12);
    EXPECT_NEAR(res.bending_min / (0.25 * kPi * e * r4), 1.0, 1e-12);
    EXPECT_TRUE(testing::MatricesNear(res.modulus_centre, Vec2(1e-3, 2e-3), 1e-15));
    EXPECT_TRUE(res.coaxial.applies);
    EXPECT_NEAR(res.coaxial.torsional_stiffness / (0.5 * kPi * g * r4), 1.0, 1e-12);
    EXPECT_LT(std::abs(res.torsion.torsional_stiffness / (0.5 * kPi * g * r4) - 1.0), 0.005);
    EXPECT_NEAR(res.linear_density, 1200.0 * kPi * (r * r - inner * inner), 1e-15);
    EXPECT_NEAR(res.outer_diameter, 2 * r, 1e-12);
  }
}

TEST(SectionTest, TwoMaterialCoaxialMatchesEq4AndEq9) {
  SectionSpec spec;
  spec.parts = {Part("core", Vec2(0, 0), 0.5e-3, 0.0, 30e9, 11e9),
                Part("jacket", Vec2(0, 0), 1.1e-3, 0.5e-3, 0.05e9, 0.017e9)};
  const SectionResult res = ComputeSection(spec, Coarse());
  const double eq4 = 0.25 * kPi * (30e9 * std::pow(0.5e-3, 4) +
                                   0.05e9 * (std::pow(1.1e-3, 4) - std::pow(0.5e-3, 4)));
  const double eq9 = 0.5 * kPi * (11e9 * std::pow(0.5e-3, 4) +
                                  0.017e9 * (std::pow(1.1e-3, 4) - std::pow(0.5e-3, 4)));
  ASSERT_TRUE(res.coaxial.applies);
  EXPECT_NEAR(res.coaxial.bending_stiffness / eq4, 1.0, 1e-12);
  EXPECT_NEAR(res.bending_max / eq4, 1.0, 1e-12);
  EXPECT_NEAR(res.coaxial.torsional_stiffness / eq9, 1.0, 1e-12);
  EXPECT_LT(std::abs(res.torsion.torsional_stiffness / eq9 - 1.0), 0.005);
  EXPECT_LE(std::abs(res.torsion.torsional_stiffness - eq9), 3.0 * res.torsion.error_estimate);
}

TEST(SectionTest, TwoWiresGiveTwoPrincipalStiffnessesAtTheRightAngle) {
  // Two equal wires touching along a line at 30 degrees: the stiff bending axis is normal to
  // that line (120 degrees, i.e. -60 degrees in (-90, 90]).
  const double r = 1e-3, e = 5e9, beta = kPi / 6;
  const Vec2 u(std::cos(beta), std::sin(beta));
  SectionSpec spec;
  spec.parts = {Part("a", r * u, r, 0.0, e, 2e9), Part("b", -r * u, r, 0.0, e, 2e9)};
  const SectionResult res = ComputeSection(spec, Coarse());
  const double ei = 0.25 * kPi * e * std::pow(r, 4), ea = e * kPi * r * r;
  EXPECT_NEAR(res.bending_max / (2 * (ei + ea * r * r)), 1.0, 1e-12);  // = 10 EI
  EXPECT_NEAR(res.bending_min / (2 * ei), 1.0, 1e-12);
  EXPECT_NEAR(res.principal_angle, -kPi / 3, 1e-12);
  EXPECT_FALSE(res.coaxial.applies);
  EXPECT_NEAR(res.outer_diameter, 4 * r, 1e-9);
  const MaterialSpec m = SectionToMaterial(res);
  EXPECT_NEAR(m.bending_ratio, 5.0, 1e-12);
  EXPECT_NEAR(m.bending_stiffness, std::sqrt(res.bending_max * res.bending_min), 1e-18);
  EXPECT_DOUBLE_EQ(m.principal_angle, res.principal_angle);
  EXPECT_DOUBLE_EQ(m.torsional_stiffness, res.torsion.torsional_stiffness);
}

TEST(SectionTest, AsymmetricBundleMatchesQuadratureOfEq2) {
  SectionSpec spec;
  spec.parts = {Part("w1", Vec2(0, 0), 1.0e-3, 0.0, 20e9, 7e9),
                Part("w1-ins", Vec2(0, 0), 1.3e-3, 1.0e-3, 0.3e9, 0.1e9),
                Part("w2", Vec2(2.2e-3, 0.4e-3), 0.8e-3, 0.0, 3e9, 1e9),
                Part("w3", Vec2(-0.5e-3, -2.0e-3), 0.7e-3, 0.3e-3, 1e9, 0.4e9)};
  const SectionResult res = ComputeSection(spec, Coarse());
  const Mat2 quad = BendingByQuadrature(spec, 1500);
  EXPECT_TRUE(testing::MatricesNear(res.bending_matrix, quad, 2e-3 * quad.norm()))
      << res.bending_matrix << "\n" << quad;
  EXPECT_GT(res.bending_max, 1.2 * res.bending_min);
  // Bonded torsion is bounded below by the parts twisting separately.
  EXPECT_GT(res.torsion.torsional_stiffness, res.torsion_unbonded);
  EXPECT_GT(res.bending_min, res.bending_unbonded);
}

TEST(SectionTest, TapedBundleHasEnclosedVoidsAndActsAsClosedTube) {
  // Three touching wires wrapped by a thin tape: the gaps inside the tape are holes.
  const double r = 1e-3;
  SectionSpec spec;
  const char* names[] = {"w0", "w1", "w2"};
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * kPi * k / 3;
    spec.parts.push_back(Part(names[k],
                              (2 * r / std::sqrt(3.0)) * Vec2(std::cos(a), std::sin(a)), r, 0.0,
                              1e9, 0.4e9));
  }
  Vec2 c;
  double rad = 0;
  SmallestEnclosingCircle(spec.parts, &c, &rad);
  EXPECT_NEAR(rad, r * (1 + 2 / std::sqrt(3.0)), 1e-12);
  EXPECT_TRUE(testing::MatricesNear(c, Vec2(0, 0), 1e-12));
  const SectionResult bare = ComputeSection(spec, Coarse());
  spec.parts.push_back(Part("tape", c, rad + 0.1e-3, rad, 1e9, 0.4e9));
  const SectionResult taped = ComputeSection(spec, Coarse());
  // Bonded at the contacts, the central gap (area r^2 (sqrt(3) - pi/2)) is already a closed
  // cell; the tape adds the three much larger outer gaps.
  const double centre_gap = r * r * (std::sqrt(3.0) - 0.5 * kPi);
  EXPECT_NEAR(bare.torsion.grids.back().enclosed_void_area, centre_gap, 0.15 * centre_gap);
  EXPECT_GT(taped.torsion.grids.back().enclosed_void_area, 4 * centre_gap);
  std::printf("bare: %s\ntaped: %s\nunbonded %g / %g\n", bare.torsion.BriefReport().c_str(),
              taped.torsion.BriefReport().c_str(), bare.torsion_unbonded,
              taped.torsion_unbonded);
  // The tape alone as a closed tube is stiffer in torsion than the three bonded wires.
  const double tape_tube = 0.5 * kPi * 0.4e9 * (std::pow(rad + 0.1e-3, 4) - std::pow(rad, 4));
  EXPECT_GT(taped.torsion.torsional_stiffness, bare.torsion.torsional_stiffness + tape_tube);
}

TEST(SectionTest, GapFillerWithSameMaterialAsItsWiresIsAHomogeneousDisc) {
  const double big = 2e-3, e = 1e9, g = 0.35e9;
  SectionSpec spec;
  spec.parts = {Part("jacket", Vec2(0, 0), big, 0.0, e, g, 1000),
                Part("w1", Vec2(0.9e-3, 0.1e-3), 0.8e-3, 0.0, e, g, 1000),
                Part("w2", Vec2(-0.9e-3, -0.3e-3), 0.8e-3, 0.3e-3, e, g, 1000),
                Part("w3", Vec2(-0.9e-3, -0.3e-3), 0.3e-3, 0.0, e, g, 1000)};
  spec.parts[0].fills_gaps = true;
  const SectionResult res = ComputeSection(spec, Coarse());
  EXPECT_NEAR(res.area / (kPi * big * big), 1.0, 1e-12);
  EXPECT_NEAR(res.bending_max / (0.25 * kPi * e * std::pow(big, 4)), 1.0, 1e-12);
  EXPECT_NEAR(res.bending_min / (0.25 * kPi * e * std::pow(big, 4)), 1.0, 1e-12);
  EXPECT_TRUE(testing::MatricesNear(res.modulus_centre, Vec2(0, 0), 1e-15));
  const double gj = 0.5 * kPi * g * std::pow(big, 4);
  EXPECT_LT(std::abs(res.torsion.torsional_stiffness / gj - 1.0), 0.003);
  EXPECT_EQ(res.torsion.grids.back().enclosed_voids, 0);
  // A stiffer wire moves the modulus centre towards it and stiffens the section.
  spec.parts[1].material.youngs_modulus = 50 * e;
  spec.parts[1].material.shear_modulus = 50 * g;
  const SectionResult stiff = ComputeSection(spec, Coarse());
  EXPECT_GT(stiff.modulus_centre.x(), 0.5e-3);
  EXPECT_GT(stiff.torsion.torsional_stiffness, 1.5 * gj);
  // A wire straddling the filler's edge is rejected.
  spec.parts[1].centre.x() = 1.5e-3;
  EXPECT_THROW_WITH(ValidateSection(spec), InvalidInput, "wholly inside a gap filler");
}

TEST(SectionTest, RejectsBadInputWithOneLineNamingThePart) {
  SectionSpec spec;
  EXPECT_THROW_WITH(ComputeSection(spec, Coarse()), InvalidInput, "no components");
  spec.parts = {Part("a", Vec2(0, 0), 1e-3, 0, 1e9, 1e9), Part("b", Vec2(1.9e-3, 0), 1e-3, 0, 1e9, 1e9)};
  EXPECT_THROW_WITH(ValidateSection(spec), InvalidInput, "part 'a' and part 'b' overlap");
  spec.parts[1].centre.x() = 2e-3;  // touching is fine
  EXPECT_NO_THROW(ValidateSection(spec));
  spec.parts[1].material.youngs_modulus = 0.0;
  EXPECT_THROW_WITH(ValidateSection(spec), InvalidInput, "part 'b': Young's modulus");
  spec.parts[1].material.youngs_modulus = 1e9;
  spec.parts[1].material.shear_modulus = -1.0;
  EXPECT_THROW_WITH(ValidateSection(spec), InvalidInput, "shear modulus");
  spec.parts[1].material.shear_modulus = 1e9;
  spec.parts[1].outer_radius = NAN;
  EXPECT_THROW_WITH(ValidateSection(spec), InvalidInput, "outer radius");
  spec.parts[1].outer_radius = 1e-3;
  spec.parts[1].inner_radius = 1e-3;
  EXPECT_THROW_WITH(ValidateSection(spec), InvalidInput, "inner radius");
  // A wire inside a conduit's bore does not overlap it; one crossing its wall does.
  spec.parts = {Part("tube", Vec2(0, 0), 5e-3, 4e-3, 1e9, 1e9),
                Part("wire", Vec2(1e-3, 0), 2e-3, 0, 1e9, 1e9)};
  EXPECT_NO_THROW(ValidateSection(spec));
  spec.parts[1].centre.x() = 2.5e-3;
  EXPECT_THROW_WITH(ValidateSection(spec), InvalidInput, "overlap");
}

}  // namespace
}  // namespace cablefit
