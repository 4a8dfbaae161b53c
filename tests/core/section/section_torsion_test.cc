#include "cablefit/core/section/section_torsion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/section/section.h"
#include "test_support.h"

namespace cablefit {
namespace {

constexpr double kPi = std::numbers::pi;

SectionPart Disc(Vec2 centre, double outer, double inner, double e, double g) {
  SectionPart p;
  p.centre = centre;
  p.outer_radius = outer;
  p.inner_radius = inner;
  p.material = {"m", e, g, 1000.0};
  return p;
}

// Relative error of every grid against `exact`, coarsest first.
std::vector<double> GridErrors(const TorsionResult& r, double exact) {
  std::vector<double> e;
  for (const auto& g : r.grids) e.push_back(std::abs(g.torsional_stiffness - exact) / exact);
  return e;
}

TEST(SectionTorsionTest, HomogeneousCircleConvergesToPiGR4Over2) {
  const double radius = 1e-3, g = 1e9;
  const std::vector<SectionPart> parts = {Disc(Vec2(0.2e-3, -0.1e-3), radius, 0.0, 3e9, g)};
  const double exact = 0.5 * kPi * g * std::pow(radius, 4);
  TorsionOptions options;
  options.finest_cells = 256;
  options.levels = 4;
  const TorsionResult r = SolvePrandtlTorsion(CircularPartsRegion(parts), options);
  const std::vector<double> err = GridErrors(r, exact);
  for (size_t k = 0; k + 1 < err.size(); ++k) {
    std::printf("circle cells %d: rel error %.3e\n", r.grids[k].cells, err[k]);
  }
  std::printf("circle: %s, exact %g\n", r.BriefReport().c_str(), exact);
  // Second-order convergence: each halving of h cuts the error by well over 2.
  EXPECT_LT(err[3], err[1] / 6.0);
  EXPECT_LT(err[3], 0.005);
  EXPECT_LT(std::abs(r.torsional_stiffness - exact) / exact, 0.002);
  EXPECT_LE(std::abs(r.torsional_stiffness - exact), 3.0 * r.error_estimate + 1e-4 * exact);
  EXPECT_EQ(r.grids.back().enclosed_voids, 0);
}

TEST(SectionTorsionTest, HollowTubeUsesHoleCirculationCondition) {
  const double ro = 2e-3, ri = 1.2e-3, g = 0.5e9;
  const std::vector<SectionPart> parts = {Disc(Vec2(0, 0), ro, ri, 1e9, g)};
  const double exact = 0.5 * kPi * g * (std::pow(ro, 4) - std::pow(ri, 4));
  TorsionOptions options;
  options.finest_cells = 256;
  const TorsionResult r = SolvePrandtlTorsion(CircularPartsRegion(parts), options);
  std::printf("tube: %s, exact %g\n", r.BriefReport().c_str(), exact);
  EXPECT_EQ(r.grids.back().enclosed_voids, 1);
  EXPECT_LT(std::abs(r.grids.back().torsional_stiffness - exact) / exact, 0.005);
  EXPECT_LT(std::abs(r.torsional_stiffness - exact) / exact, 0.003);
}

TEST(SectionTorsionTest, SquareMatchesSaintVenantConstant) {
  // Saint-Venant: J = k a^4 with k = 0.140577 for a square of side a (Timoshenko & Goodier,
  // Theory of Elasticity, 3rd ed., sec. 109, table for b/a = 1: 0.1406).
  const double a = 2e-3, g = 1e9;
  const RectangleRegion square(Vec2(-a / 2, -a / 2), Vec2(a / 2, a / 2), g);
  TorsionOptions options;
  options.finest_cells = 128;
  const TorsionResult r = SolvePrandtlTorsion(square, options);
  const double exact = 0.140577 * g * std::pow(a, 4);
  std::printf("square: %s, exact %g\n", r.BriefReport().c_str(), exact);
  EXPECT_EQ(r.convergence, TorsionConvergence::kAsymptotic);
  EXPECT_NEAR(r.observed_order, 2.0, 0.2);
  EXPECT_LT(std::abs(r.grids.back().torsional_stiffness - exact) / exact, 0.005);
  EXPECT_LT(std::abs(r.torsional_stiffness - exact) / exact, 2e-4);
}

TEST(SectionTorsionTest, TwoMaterialCoaxialMatchesEq9) {
  const double r1 = 0.6e-3, r2 = 1.0e-3;
  const std::vector<SectionPart> parts = {Disc(Vec2(0, 0), r1, 0.0, 20e9, 8e9),
                                          Disc(Vec2(0, 0), r2, r1, 0.03e9, 0.01e9)};
  const double exact = 0.5 * kPi * (8e9 * std::pow(r1, 4) +
                                    0.01e9 * (std::pow(r2, 4) - std::pow(r1, 4)));
  TorsionOptions options;
  options.finest_cells = 256;
  const TorsionResult r = SolvePrandtlTorsion(CircularPartsRegion(parts), options);
  std::printf("coaxial: %s, exact %g\n", r.BriefReport().c_str(), exact);
  EXPECT_LT(std::abs(r.grids.back().torsional_stiffness - exact) / exact, 0.005);
  EXPECT_LT(std::abs(r.torsional_stiffness - exact) / exact, 0.003);
}

TEST(SectionTorsionTest, RejectsInvalidOptions) {
  const std::vector<SectionPart> parts = {Disc(Vec2(0, 0), 1e-3, 0.0, 1e9, 1e9)};
  TorsionOptions options;
  options.levels = 1;
  EXPECT_THROW_WITH(SolvePrandtlTorsion(CircularPartsRegion(parts), options), UsageError,
                    "levels");
  options.levels = 3;
  options.finest_cells = 16;
  EXPECT_THROW_WITH(SolvePrandtlTorsion(CircularPartsRegion(parts), options), UsageError,
                    "finest_cells");
}

}  // namespace
}  // namespace cablefit
