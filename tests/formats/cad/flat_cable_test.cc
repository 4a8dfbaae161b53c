// Flat (ribbon) cables: a rectangle or a stadium swept along a route is one cable with its
// width, thickness and the wide axis as drawn; round cores inside a flat jacket are its own.
// Input: tests/data/flat/flat_cables.step (formats/cad/tools/make_flat_cables.cc made it).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "cablefit/formats/cad_file.h"
#include "test_support.h"

namespace cablefit {
namespace {

using Eigen::Vector3d;

// The spines the generator swept along [mm].
Eigen::Matrix3Xd RibbonSpine() {
  Eigen::Matrix3Xd p(3, 5);
  p << 0, 80, 160, 240, 300,  //
      0, 0, 20, 70, 110,     //
      100, 120, 130, 130, 130;
  return p;
}

double Length(const DrawnCable& c) { return c.centreline.s[c.centreline.size() - 1]; }

TEST(FlatCable, ARibbonAndAHouseWireAreOneCableEachWithTheirSections) {
  const HarnessDrawing d =
      ReadCadFile((testing::SourceDir() / "tests/data/flat/flat_cables.step").string());
  for (const std::string& line : d.skipped) std::printf("skipped: %s\n", line.c_str());
  ASSERT_EQ(d.cables.size(), 2u);
  EXPECT_TRUE(d.solids.empty());
  const DrawnCable* ribbon = nullptr;
  const DrawnCable* house = nullptr;
  for (const DrawnCable& c : d.cables) (c.name == "ribbon" ? ribbon : house) = &c;
  ASSERT_TRUE(ribbon && house);
  ASSERT_TRUE(ribbon->flat && house->flat);
  EXPECT_EQ(house->name, "house wire");
  EXPECT_NEAR(ribbon->flat->width, 0.010, 2e-4);
  EXPECT_NEAR(ribbon->flat->thickness, 0.002, 1e-4);
  EXPECT_FALSE(ribbon->flat->rounded_edges);
  EXPECT_NEAR(house->flat->width, 0.012, 2e-4);
  EXPECT_NEAR(house->flat->thickness, 0.0044, 1e-4);
  EXPECT_TRUE(house->flat->rounded_edges);
  // The ends are the end faces' centres, the length the spine's (chords of its samples).
  EXPECT_LT((ribbon->centreline.points.col(0) - 1e-3 * RibbonSpine().col(0)).norm(), 1e-5);
  EXPECT_LT((ribbon->centreline.points.col(ribbon->centreline.size() - 1) -
             1e-3 * RibbonSpine().col(4)).norm(), 1e-5);
  double chord = 0.0;
  for (int i = 0; i < 4; ++i) chord += (RibbonSpine().col(i + 1) - RibbonSpine().col(i)).norm();
  EXPECT_GT(Length(*ribbon), 1e-3 * chord);
  EXPECT_LT(Length(*ribbon), 1e-3 * chord * 1.05);
  // The centreline follows the spine: every point within a tenth of the thickness of the
  // house wire's plane, and the wide axis stays level there (flat side up).
  for (Eigen::Index i = 0; i < house->centreline.size(); ++i) {
    EXPECT_NEAR(house->centreline.points(1, i), 0.2, 2e-4) << i;
    EXPECT_NEAR(std::abs(house->flat->wide_axes(1, i)), 1.0, 1e-3) << i;
  }
  // The ribbon's wide axis stays square to its route, and turns with it.
  const Eigen::Matrix3Xd& axes = ribbon->flat->wide_axes;
  for (Eigen::Index i = 1; i + 1 < ribbon->centreline.size(); ++i) {
    const Vector3d t = (ribbon->centreline.points.col(i + 1) - ribbon->centreline.points.col(i - 1)).normalized();
    EXPECT_LT(std::abs(axes.col(i).dot(t)), 0.05) << i;
  }
  // It turned with the drawing: more than 10 degrees between the two ends' wide axes.
  EXPECT_LT(std::abs(axes.col(0).dot(axes.col(axes.cols() - 1))), std::cos(10 * M_PI / 180));
  // The cores are the house wire's, said so once each.
  int cores = 0;
  for (const std::string& line : d.skipped)
    cores += line.find("inside flat cable 'house wire'") != std::string::npos;
  EXPECT_EQ(cores, 3);
}

}  // namespace
}  // namespace cablefit
