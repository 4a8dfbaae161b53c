// The stripped core ends of a multi-core cable (short thin tubes or curves leaving the jacket's
// end face) are part of that cable; a breakout's branches and a thick neighbour are not.
#include "core_tails.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cablefit/formats/cad_file.h"
#include "curve_distance.h"

namespace cablefit {
namespace {

using internal::AbsorbedTubes;
using internal::DrawnTube;

Polyline Line(const Vec3& a, const Vec3& b) { return testing::StraightLine(a, b); }

DrawnCable Cable(const std::string& name, const Polyline& route, double diameter) {
  DrawnCable c;
  c.name = name;
  c.centreline = route;
  c.diameter = diameter;
  return c;
}

DrawnTube SolidTube(HarnessDrawing* d, const std::string& name, const Polyline& route,
                    double radius) {
  DrawnSolid s;
  s.name = name;
  d->solids.push_back(s);
  DrawnTube t;
  t.index = static_cast<int>(d->solids.size()) - 1;
  t.centres = route.points;
  t.radius = radius;
  return t;
}

std::vector<std::string> Names(const HarnessDrawing& d) {
  std::vector<std::string> names;
  for (const DrawnCable& c : d.cables) names.push_back(c.name);
  for (const DrawnSolid& s : d.solids) names.push_back("solid " + s.name);
  return names;
}

TEST(CoreTails, TailsOutOfAJacketEndBelongToItsCable) {
  HarnessDrawing d;
  // A 9 mm cable along x from 0 to 0.3 m; three 2.8 mm cores leave its start face 20 mm
  // towards -x, 2.9 mm apart, one drawn as a tube part, two as tube cables.
  d.cables = {Cable("jacket", Line({0, 0, 0}, {0.3, 0, 0}), 0.009),
              Cable("core-a", Line({0, 0.0029, 0}, {-0.02, 0.0029, 0}), 0.0028),
              Cable("core-b", Line({0, -0.0029, 0}, {-0.02, -0.0029, 0}), 0.0028),
              // A thick cable continuing the route: a splice, not a core.
              Cable("next", Line({0.3, 0, 0}, {0.32, 0, 0}), 0.009)};
  std::vector<DrawnTube> tubes = {SolidTube(&d, "core-c", Line({0, 0, 0}, {-0.02, 0, 0}), 0.0014)};
  for (int c : {1, 2}) {
    DrawnTube t;
    t.is_cable = true;
    t.index = c;
    t.centres = d.cables[static_cast<size_t>(c)].centreline.points;
    t.radius = 0.0014;
    tubes.push_back(t);
  }
  AbsorbedTubes absorbed(d);
  internal::MergeCoreTails(tubes, 10.0, 1e-4, &d, &absorbed);
  absorbed.RemoveFrom(&d);
  EXPECT_EQ(Names(d), (std::vector<std::string>{"jacket", "next"}));
  ASSERT_EQ(d.skipped.size(), 3u);
  for (const std::string& line : d.skipped)
    EXPECT_NE(line.find("out of the end of cable 'jacket'"), std::string::npos) << line;
}

TEST(CoreTails, BareCurveTailsSideBySideGoButBreakoutBranchesStay) {
  HarnessDrawing d;
  // A bare route from x = 0 to 0.12 m; at its start three 20 mm curves leave it side by side
  // (a stripped multi-core end); at its end two 40 mm curves start at one point (a breakout).
  d.cables = {Cable("route", Line({0, 0, 0}, {0.12, 0, 0}), 0.0)};
  for (double y : {-0.003, 0.0, 0.003})
    d.cables.push_back(Cable("tail", Line({0, y, 0}, {-0.02, y, 0}), 0.0));
  d.cables.push_back(Cable("branch", Line({0.12, 0, 0}, {0.16, 0.01, 0}), 0.0));
  d.cables.push_back(Cable("branch", Line({0.12, 0, 0}, {0.16, -0.01, 0}), 0.0));
  AbsorbedTubes absorbed(d);
  internal::MergeCoreTails({}, 10.0, 1e-4, &d, &absorbed);
  absorbed.RemoveFrom(&d);
  EXPECT_EQ(Names(d), (std::vector<std::string>{"route", "branch", "branch"}));
  EXPECT_EQ(d.skipped.size(), 3u);
}

TEST(CoreTails, ALongBranchANodesBranchOrAThickNeighbourIsNoTail) {
  HarnessDrawing d;
  // A 9 mm cable; a 3 mm cable leaving its end face but 0.2 m long (over 10 diameters of the
  // cable: a branch), and a 12 mm tube at its end (thicker than the cable).
  // At the other end a 1.6 mm wire of 40 mm leaves the node where the cable meets a 6 mm one:
  // a thin branch of a harness node, not a core end.
  d.cables = {Cable("jacket", Line({0, 0, 0}, {0.3, 0, 0}), 0.009),
              Cable("branch", Line({0, 0.002, 0}, {-0.2, 0.002, 0}), 0.003),
              Cable("onward", Line({0.3, 0, 0}, {0.3, 0.1, 0}), 0.006),
              Cable("wire", Line({0.3, 0, 0}, {0.34, 0, 0}), 0.0016)};
  std::vector<DrawnTube> tubes = {SolidTube(&d, "boot", Line({0, 0, 0}, {-0.02, 0, 0}), 0.006)};
  AbsorbedTubes absorbed(d);
  internal::MergeCoreTails(tubes, 10.0, 1e-4, &d, &absorbed);
  absorbed.RemoveFrom(&d);
  EXPECT_EQ(Names(d), (std::vector<std::string>{"jacket", "branch", "onward", "wire", "solid boot"}));
  EXPECT_TRUE(d.skipped.empty());
}

TEST(CoreTails, ASegmentBeyondASpliceIsNoTailButAWiresBareConductorIs) {
  HarnessDrawing d;
  // A harness's bundles: a 9 mm one thinning at a splice (its start) to a 4 mm segment of 60 mm
  // that runs on to a node with two other segments; at its end a 3.2 mm leaf of 40 mm (12.5 of
  // its own diameters: slender, a cable) on its own. A 3 mm wire with its 1.6 mm conductor bare
  // for 8 mm (5 diameters) at one end.
  d.cables = {Cable("bundle", Line({0, 0, 0}, {0.3, 0, 0}), 0.009),
              Cable("thinner", Line({0, 0, 0}, {-0.06, 0, 0}), 0.004),
              Cable("node-a", Line({-0.06, 0, 0}, {-0.06, 0.1, 0}), 0.004),
              Cable("node-b", Line({-0.06, 0, 0}, {-0.06, -0.1, 0}), 0.004),
              Cable("leaf", Line({0.3, 0, 0}, {0.34, 0, 0}), 0.0032),
              Cable("wire", Line({0, 0.1, 0}, {0.3, 0.1, 0}), 0.003),
              Cable("conductor", Line({0.3, 0.1, 0}, {0.308, 0.1, 0}), 0.0016)};
  AbsorbedTubes absorbed(d);
  internal::MergeCoreTails({}, 10.0, 1e-4, &d, &absorbed);
  absorbed.RemoveFrom(&d);
  EXPECT_EQ(Names(d), (std::vector<std::string>{"bundle", "thinner", "node-a", "node-b", "leaf", "wire"}));
  ASSERT_EQ(d.skipped.size(), 1u);
  EXPECT_NE(d.skipped[0].find("'conductor': a 1.6 mm core 8 mm long out of the end of cable 'wire'"),
            std::string::npos)
      << d.skipped[0];
}

}  // namespace
}  // namespace cablefit
