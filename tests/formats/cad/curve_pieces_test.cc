// Curve pieces of one name that meet end to end are one route, as a STEP curve set gives them.
#include "curve_pieces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace cablefit {
namespace {

DrawnCable Piece(const std::string& name, const Vec3& a, const Vec3& b) {
  DrawnCable c;
  c.name = name;
  c.source = CableSourceKind::kCurve;
  c.centreline.points.resize(3, 5);
  for (int k = 0; k < 5; ++k) c.centreline.points.col(k) = a + (b - a) * (k / 4.0);
  c.centreline.ParameteriseByChords(0.0);
  return c;
}

// A circle of radius r in the z = 0 plane as the arc from angle a0 to a1.
DrawnCable Arc(const std::string& name, double r, double a0, double a1) {
  DrawnCable c;
  c.name = name;
  c.source = CableSourceKind::kCurve;
  c.centreline.points.resize(3, 9);
  for (int k = 0; k < 9; ++k) {
    const double a = a0 + (a1 - a0) * k / 8.0;
    c.centreline.points.col(k) = Vec3(r * std::cos(a), r * std::sin(a), 0);
  }
  c.centreline.ParameteriseByChords(0.0);
  return c;
}

TEST(CurvePieces, PiecesOfOneNameMeetingEndToEndAreOneRoute) {
  HarnessDrawing d;
  const std::string n = "3d BsCrv(0)";
  // Three routes of two pieces each, the second of them drawn backwards; a fourth name whose
  // piece touches the first route's end stays separate.
  d.cables = {Piece(n, {0, 0, 0}, {0.1, 0, 0}),      Piece(n, {0.2, 0, 0}, {0.1, 0, 0}),
              Piece(n, {0, 0.1, 0}, {0.1, 0.1, 0}),  Piece(n, {0.1, 0.1, 0}, {0.1, 0.3, 0}),
              Piece(n, {0, 0.5, 0}, {0.2, 0.5, 0}),  Piece(n, {0.2, 0.5, 0}, {0.2, 0.5, 0.2}),
              Piece("other", {0.2, 0, 0}, {0.3, 0, 0})};
  const std::vector<int> moved = internal::JoinCurvePieces(&d, 1e-6);
  ASSERT_EQ(d.cables.size(), 4u);
  EXPECT_NEAR(d.cables[0].centreline.ChordLength(), 0.2, 1e-12);
  EXPECT_NEAR(d.cables[1].centreline.ChordLength(), 0.3, 1e-12);
  EXPECT_NEAR(d.cables[2].centreline.ChordLength(), 0.4, 1e-12);
  EXPECT_NEAR(d.cables[3].centreline.ChordLength(), 0.1, 1e-12);
  EXPECT_EQ(d.cables[3].name, "other");
  // Joined without a doubled point at the seam.
  EXPECT_EQ(d.cables[0].centreline.size(), 9);
  EXPECT_EQ(moved[0], 0);
  EXPECT_EQ(moved[1], -1);
  EXPECT_EQ(moved[6], 3);
}

TEST(CurvePieces, ThreeEndsAtAPointAreABranchNotAJoin) {
  HarnessDrawing d;
  d.cables = {Piece("w", {0, 0, 0}, {0.1, 0, 0}), Piece("w", {0.1, 0, 0}, {0.2, 0, 0}),
              Piece("w", {0.1, 0, 0}, {0.1, 0.1, 0})};
  internal::JoinCurvePieces(&d, 1e-6);
  EXPECT_EQ(d.cables.size(), 3u);
}

TEST(CurvePieces, ACircleDrawnAsTwoArcsIsASketchProfile) {
  HarnessDrawing d;
  d.cables = {Arc("profile", 0.002, 0, M_PI), Arc("profile", 0.002, M_PI, 2 * M_PI),
              Piece("route", {0, 0, 0.01}, {0.1, 0, 0.01})};
  internal::JoinCurvePieces(&d, 1e-9);
  ASSERT_EQ(d.cables.size(), 1u);
  EXPECT_EQ(d.cables[0].name, "route");
  ASSERT_EQ(d.skipped.size(), 1u);
  EXPECT_NE(d.skipped[0].find("sketch profile"), std::string::npos);
}

}  // namespace
}  // namespace cablefit
