#include "cablefit/app/input/kbl_input.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"

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

TEST(KblInput, ProtectionKindsByTheirTypeName) {
  EXPECT_EQ(ProtectionKind("TAPE"), "tape");
  EXPECT_EQ(ProtectionKind("Gewebeband"), "tape");
  EXPECT_EQ(ProtectionKind("Wellrohr NW10"), "corrugated tube");
  EXPECT_EQ(ProtectionKind("corrugated_tube"), "corrugated tube");
  EXPECT_EQ(ProtectionKind("PVC-Schlauch"), "");
  EXPECT_EQ(ProtectionKind(""), "");
}

TEST(KblInput, AProtectionIsASleeveOverItsShareOfTheSegment) {
  // The generator harness: Segment_1's PET tape (6 g/m) from 0.045496 of the segment to its end.
  const KblInput in = ReadKblInput(
      (testing::SourceDir() /
       "tests/data/kbl/kblxml_2.3sr-1_000971230_ltgs_generator_170718.kbl").string(),
      HarnessConfig{});
  const CableConfig& s1 = in.config.cables.at("Segment_1");
  ASSERT_EQ(s1.sleeves.size(), 1u);
  const SleeveConfig& tape = s1.sleeves[0];
  EXPECT_NEAR(tape.from, 0.045496, 1e-12);
  EXPECT_EQ(tape.to, 1.0);
  EXPECT_NEAR(tape.linear_density, 0.006, 1e-15);
  // A wrap of two 0.13 mm layers of PVC tape (40 MPa, the section library's) around the bundle
  // of 1.6, 1.6 and 5.1 mm wires.
  const double d = 1e-3 * std::sqrt((1.6 * 1.6 * 2 + 5.1 * 5.1) / kBundlePackingFraction);
  const double ei = 40e6 * M_PI / 64 * (std::pow(d + 2 * 0.26e-3, 4) - std::pow(d, 4));
  EXPECT_NEAR(tape.bending_stiffness, ei, 1e-12 * ei);
  EXPECT_NEAR(tape.torsional_stiffness, ei / 1.3, 1e-12 * ei);
  // The wires' own mass stays the bundle's: the tape's sits where the tape is.
  EXPECT_NEAR(s1.material->linear_density, 0.080, 1e-12);
}

TEST(KblInput, ASegmentWhoseCurveWasDrawnOntoItsNodeIsBuiltAtItsVirtualLength) {
  // Segment_4's curve starts 30 mm short of Node_3 (tests/data/kbl/README.md): drawn onto it,
  // its drawn length is no longer the file's; the others reach their nodes as drawn.
  const KblInput in = ReadKblInput(
      (testing::SourceDir() / "tests/data/kbl/inconsistent_nodes_4.kbl").string(), HarnessConfig{});
  const CableConfig& s4 = in.config.cables.at("Segment_4");
  ASSERT_TRUE(s4.length.has_value());
  EXPECT_EQ(s4.length->kind, CableLength::Kind::kMetres);
  EXPECT_NEAR(s4.length->value, 0.196364569, 1e-12);
  EXPECT_TRUE(in.cable_json.at("Segment_4")["end_drawn_to_node"].get<bool>());
  for (const char* id : {"Segment_1", "Segment_2", "Segment_3"}) {
    EXPECT_FALSE(in.config.cables.at(id).length.has_value()) << id;
    EXPECT_FALSE(in.cable_json.at(id)["end_drawn_to_node"].get<bool>()) << id;
  }
  // A length the user gives the segment in harness.json still wins.
  HarnessConfig user;
  user.cables["Segment_4"].length = CableLength{CableLength::Kind::kRelative, 0.02};
  const KblInput own = ReadKblInput(
      (testing::SourceDir() / "tests/data/kbl/inconsistent_nodes_4.kbl").string(), user);
  EXPECT_EQ(own.config.cables.at("Segment_4").length->kind, CableLength::Kind::kRelative);
}

}  // namespace
}  // namespace cablefit::addin
