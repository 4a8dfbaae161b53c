#include "cablefit/app/kbl_input.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cablefit::addin {
namespace {

KblWire Wire(double d, std::optional<double> mass, std::optional<double> bend) {
  KblWire w;
  w.outside_diameter = d;
  w.linear_density = mass;
  w.min_bend_radius = bend;
  return w;
}

TEST(KblBundle, OneWireIsItsOwnBundle) {
  const KblBundle b = BundleOf({Wire(0.004, 0.03, 0.012)});
  EXPECT_DOUBLE_EQ(b.diameter, 0.004);
  EXPECT_DOUBLE_EQ(b.linear_density, 0.03);
  EXPECT_DOUBLE_EQ(b.min_bend_radius, 0.012);
}

TEST(KblBundle, SeveralWiresFillADiscAtThePackingFractionAndTheTightestBendLimitWins) {
  const KblBundle b =
      BundleOf({Wire(0.002, 0.01, 0.006), Wire(0.002, 0.01, 0.006), Wire(0.003, 0.02, 0.009)});
  EXPECT_NEAR(b.diameter, std::sqrt((4e-6 + 4e-6 + 9e-6) / kBundlePackingFraction), 1e-15);
  EXPECT_NEAR(b.linear_density, 0.04, 1e-15);
  EXPECT_DOUBLE_EQ(b.min_bend_radius, 0.009);
  EXPECT_EQ(b.wires_with_diameter, 3);
}

TEST(KblBundle, MassOnlyWhenEveryWireGivesIt) {
  // One wire without mass data: no mass from the wires at all (the estimate takes over), while
  // the diameter still counts both.
  const KblBundle b =
      BundleOf({Wire(0.010, std::nullopt, std::nullopt), Wire(0.001, 0.01, std::nullopt)});
  EXPECT_EQ(b.linear_density, 0.0);
  EXPECT_NEAR(b.diameter, std::sqrt(1.01e-4 / kBundlePackingFraction), 1e-15);
  EXPECT_EQ(b.min_bend_radius, 0.0);
}

TEST(KblBundle, ProtectionMassIsWeightedByTheShareOfTheSegmentItCovers) {
  KblProtection tape;
  tape.start = 0.25;
  tape.end = 0.75;
  tape.linear_density = 0.006;
  KblProtection unknown;  // no mass per length: adds nothing
  EXPECT_NEAR(ProtectionMassPerLength({tape, unknown}), 0.003, 1e-15);
}

}  // namespace
}  // namespace cablefit::addin
