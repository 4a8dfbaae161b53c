// Clearance in the relax output: what is a violation (the larger min_clearance of the two, not
// where the cable rests), cables joined at a breakout, and the harness.json fields that ask.
#include "cablefit/app/clearance/relax_clearance.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cablefit/core/base/errors.h"
#include "curve_distance.h"
#include "test_support.h"

namespace cablefit::addin {
namespace {

Polyline Line(const Vec3& a, const Vec3& b, int n = 41) { return testing::StraightLine(a, b, n); }

// The plane z = 0 facing +z.
TriangleMesh Floor() {
  TriangleMesh m;
  m.vertices.resize(3, 4);
  m.vertices << -1, 1, 1, -1, -1, -1, 1, 1, 0, 0, 0, 0;
  m.faces.resize(3, 2);
  m.faces << 0, 0, 1, 2, 2, 3;
  return m;
}

TEST(RelaxClearance, TheLargerMinClearanceOfThePairDecidesAViolation) {
  const Polyline high = Line({0, 0, 0.05}, {0.5, 0, 0.05});
  const Polyline low = Line({0, 0.2, 0.012}, {0.5, 0.2, 0.012});
  const SolidClearance floor(Floor());
  std::vector<ClearanceCable> cables = {{"high", &high, 0.005, 0.0, {}},
                                        {"low", &low, 0.005, 0.0, {}}};
  std::vector<ClearanceSolid> solids = {{"floor", &floor, 0.01}};
  std::vector<ClearancePair> pairs = MeasureClearances(cables, solids);
  ASSERT_EQ(pairs.size(), 3u);  // high-floor, high-low, low-floor: each pair once
  // Order: each cable's solids, then the cables after it.
  EXPECT_EQ(pairs[0].cable, "high");
  EXPECT_EQ(pairs[0].other, "floor");
  EXPECT_NEAR(pairs[0].hit.clearance, 0.045, 1e-12);
  EXPECT_FALSE(pairs[0].violation());
  EXPECT_EQ(pairs[1].other, "low");
  EXPECT_NEAR(pairs[1].hit.clearance, std::hypot(0.2, 0.038) - 0.01, 1e-12);
  EXPECT_EQ(pairs[2].cable, "low");
  EXPECT_NEAR(pairs[2].hit.clearance, 0.007, 1e-12);
  EXPECT_TRUE(pairs[2].violation());  // 7 mm < the floor's 10 mm
  EXPECT_NE(ClearanceViolationText(pairs[2]).find("7.0 mm, less than the 10.0 mm"),
            std::string::npos);
  // The cable's own min_clearance counts too, when larger.
  cables[0].min_clearance = 0.3;
  pairs = MeasureClearances(cables, solids);
  EXPECT_TRUE(pairs[0].violation());
  EXPECT_DOUBLE_EQ(pairs[1].required, 0.3);
  EXPECT_TRUE(pairs[1].violation());
}

TEST(RelaxClearance, ACableRestingOnOrHeldByASolidIsNoViolation) {
  const Polyline lying = Line({0, 0, 0.005}, {0.5, 0, 0.005});  // radius 5 mm: on the floor
  const SolidClearance floor(Floor());
  std::vector<ClearanceCable> cables = {{"lying", &lying, 0.005, 0.02, {}}};
  std::vector<ClearanceSolid> solids = {{"floor", &floor, 0.0}};
  ClearancePair p = MeasureClearances(cables, solids).at(0);
  EXPECT_NEAR(p.hit.clearance, 0.0, 1e-12);
  EXPECT_TRUE(p.rests_on);
  EXPECT_FALSE(p.violation());
  // Held 3 cm above it by a clip on it: still resting, whatever the distance.
  const Polyline held = Line({0, 0, 0.03}, {0.5, 0, 0.03});
  cables = {{"held", &held, 0.005, 0.05, {"floor"}}};
  p = MeasureClearances(cables, solids).at(0);
  EXPECT_TRUE(p.rests_on);
  EXPECT_FALSE(p.violation());
  cables[0].clipped_to.clear();
  EXPECT_TRUE(MeasureClearances(cables, solids).at(0).violation());
}

TEST(RelaxClearance, BranchesOfABreakoutAreMeasuredAwayFromIt) {
  // Two branches leaving a common point at 60 degrees: near it they touch by construction.
  const double r = 0.004;
  const Polyline a = Line({0, 0, 0}, {0.3, 0, 0}, 301);
  const Polyline b = Line({0, 0, 0}, {0.3 * 0.5, 0.3 * std::sqrt(3.0) / 2, 0}, 301);
  const std::vector<ClearanceCable> cables = {{"a", &a, r, 0.0, {}}, {"b", &b, r, 0.0, {}}};
  const ClearancePair p = MeasureClearances(cables, {}).at(0);
  // Left out: kJunctionSkipFactor * 2r of each, so the nearest kept points are at that arc
  // length on both: 2 s sin(30 deg) = s apart.
  const double s = kJunctionSkipFactor * 2 * r;
  EXPECT_NEAR(p.hit.clearance, s - 2 * r, 1e-3 * r);
  EXPECT_GT(p.hit.clearance, 0.0);
}

TEST(RelaxClearance, HarnessJsonAsksPerCableAndPerSolid) {
  const auto dir = testing::FreshTempDir("relax_clearance_config");
  const std::string path = (dir / "harness.json").string();
  std::ofstream(path) << R"({"default": {"min_clearance": 0.01},
      "cables": {"hot": {"min_clearance": 0.05}},
      "solids": {"exhaust*": {"min_clearance": 0.08}, "*": {"min_clearance": 0.002}}})";
  const HarnessConfig h = ReadHarnessConfig(path);
  EXPECT_DOUBLE_EQ(h.For("hot").min_clearance.value(), 0.05);
  EXPECT_DOUBLE_EQ(h.For("other").min_clearance.value(), 0.01);
  EXPECT_DOUBLE_EQ(h.SolidMinClearance("exhaust_pipe"),
                   0.08);  // the largest of the matching patterns
  EXPECT_DOUBLE_EQ(h.SolidMinClearance("bracket"), 0.002);
  for (const char* bad : {R"({"default": {"min_clearance": -0.01}})",
                          R"({"solids": {"x": {"min_clearance": "NaN"}}})",
                          R"({"solids": {"x": {}}})", R"({"solids": {"x": {"gap": 1}}})"}) {
    std::ofstream(path) << bad;
    EXPECT_THROW(ReadHarnessConfig(path), FileError) << bad;
  }
}

}  // namespace
}  // namespace cablefit::addin
