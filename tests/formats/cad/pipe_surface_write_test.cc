// Round tubes written as a pipe surface built on the spine's poles (MakePipeSurfaceTube): read
// back by ReadCadFile they are the same cables (diameter, centreline, name), including the
// shapes where the surface's frame has to turn most (a tight coil, a straight run next to a
// bend), and the file holds exact circles: a rational surface, no general sweep's approximation.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "cablefit/formats/cad_file.h"
#include "curve_distance.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::MaxDistanceToPolyline;
using testing::SampleCurve;

HarnessDrawing OneCable(const Polyline& centreline, double diameter) {
  HarnessDrawing drawing;
  DrawnCable cable;
  cable.name = "coil";
  cable.has_color = true;
  cable.color = SrgbColor{0.1, 0.5, 0.9};
  cable.diameter = diameter;
  cable.centreline = centreline;
  drawing.cables.push_back(cable);
  return drawing;
}

struct WrittenTube {
  DrawnCable back;
  std::string step_text;
};

WrittenTube WriteAndReadBack(const Polyline& centreline, double diameter, const std::string& tag) {
  const std::string path = (testing::FreshTempDir(tag) / "tube.step").string();
  WriteRelaxedStep(path, OneCable(centreline, diameter), {RelaxedCable{0, centreline, diameter}});
  const HarnessDrawing back = ReadCadFile(path);
  EXPECT_EQ(back.cables.size(), 1u);
  EXPECT_TRUE(back.solids.empty());
  if (back.cables.empty()) return {};
  return {back.cables[0], testing::ReadTextFile(path)};
}

void ExpectSameCable(const WrittenTube& t, const Polyline& centreline, double diameter) {
  EXPECT_EQ(t.back.name, "coil");
  EXPECT_TRUE(t.back.has_color);
  EXPECT_NEAR(t.back.color.b, 0.9, 0.01);
  EXPECT_NEAR(t.back.diameter, diameter, 0.01 * diameter);
  const double length = centreline.s[centreline.size() - 1];
  EXPECT_NEAR(t.back.centreline.s[t.back.centreline.size() - 1], length, 0.005 * length);
  // Both ways: no recovered point off the written centreline, no written stretch missing.
  EXPECT_LT(MaxDistanceToPolyline(t.back.centreline, centreline), 0.02 * diameter);
  EXPECT_LT(MaxDistanceToPolyline(centreline, t.back.centreline), 0.05 * diameter + 2e-3);
  // Exact circles need weights: the pipe shell's approximations are polynomial surfaces.
  EXPECT_NE(t.step_text.find("RATIONAL_B_SPLINE_SURFACE"), std::string::npos);
}

// Three turns of a coil of 15 mm radius (five diameters) rising 12 mm a turn: the frame turns a
// full circle every 94 mm, the tightest a cable of this diameter can be wound without the tube
// overlapping itself by much.
TEST(PipeSurfaceWrite, ATightCoilReadsBackAsTheSameCable) {
  const double radius = 0.015, rise = 0.012, turns = 3.0, diameter = 0.006;
  const Polyline coil = SampleCurve(
      [&](double u) -> Vec3 {
        const double a = 2 * std::numbers::pi * turns * u;
        return Vec3(radius * std::cos(a), radius * std::sin(a), rise * turns * u);
      },
      361);
  ExpectSameCable(WriteAndReadBack(coil, diameter, "pipe_surface_coil"), coil, diameter);
}

// A straight run, a quarter circle of 50 mm radius and a straight run again: the curvature jumps
// where the bend starts, the frame must not.
TEST(PipeSurfaceWrite, AStraightRunIntoABendReadsBackAsTheSameCable) {
  const double r = 0.05, diameter = 0.008;
  const double straight = 0.1, bend = 0.5 * std::numbers::pi * r, total = 2 * straight + bend;
  const Polyline route = SampleCurve(
      [&](double u) -> Vec3 {
        const double s = u * total;
        if (s < straight) return Vec3(s, 0, 0);
        if (s < straight + bend) {
          const double a = (s - straight) / r;
          return Vec3(straight + r * std::sin(a), r * (1 - std::cos(a)), 0);
        }
        return Vec3(straight + r, r + (s - straight - bend), 0);
      },
      301);
  ExpectSameCable(WriteAndReadBack(route, diameter, "pipe_surface_bend"), route, diameter);
}

// The degenerate spine of two points is a straight cylinder.
TEST(PipeSurfaceWrite, TwoPointsGiveAStraightTube) {
  const double diameter = 0.01;
  const Polyline line = testing::StraightLine(Vec3(0, 0, 0), Vec3(0.05, 0.1, -0.2), 2);
  ExpectSameCable(WriteAndReadBack(line, diameter, "pipe_surface_line"), line, diameter);
}

}  // namespace
}  // namespace cablefit
