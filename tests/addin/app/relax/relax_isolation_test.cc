// A network that cannot be solved as one does not fail all its cables: the cables of a Y whose
// one leg is cut far too short to reach its clamp (no equilibrium exists) are relaxed one by
// one, the legs that can be solved get their results with a note, and the short leg alone is
// reported with its reason.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cablefit/app/relax/relax_network.h"

namespace cablefit::addin {
namespace {

Polyline Route(const Vec3& a, const Vec3& b) {
  Polyline p;
  const int n = 21;
  p.points.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / (n - 1);
    // Drawn drooping a little between its ends, as a drawing of a cable with slack is.
    p.points.col(i) = a + u * (b - a) - 0.03 * (b - a).norm() * std::sin(M_PI * u) * Vec3::UnitZ();
  }
  p.ParameteriseByChords();
  return p;
}

TEST(RelaxIsolation, OneUnsolvableLegDoesNotFailTheOtherLegsOfItsNetwork) {
  HarnessDrawing d;
  const Vec3 hub(0, 0, 0);
  const Vec3 ends[3] = {Vec3(0.4, 0, 0), Vec3(-0.2, 0.35, 0), Vec3(-0.2, -0.35, 0)};
  for (int k = 0; k < 3; ++k) {
    DrawnCable c;
    c.name = "leg" + std::to_string(k);
    c.centreline = Route(hub, ends[k]);
    c.diameter = 0.006;
    d.cables.push_back(c);
  }
  CableJunction j;
  j.position = hub;
  for (int k = 0; k < 3; ++k) j.ends.push_back({k, true});
  d.junctions.push_back(j);
  HarnessConfig config;
  // leg0 cut to half its drawn length: with either other leg it is far shorter (0.6 m) than the
  // distance between their clamps (0.69 m), and alone from the hub to its clamp, beyond what any
  // stretch of the bundle makes up for.
  CableConfig short_leg;
  short_leg.length = CableLength{CableLength::Kind::kRelative, -0.5};
  config.cables["leg0"] = short_leg;

  const std::vector<OrientedBox> boxes = SolidBoxes(d);
  const std::vector<RelaxGroup> groups = GroupCables(d, boxes, config);
  ASSERT_EQ(groups.size(), 1u);
  ASSERT_TRUE(groups[0].network());
  const GroupOutcome out = RelaxGroupCables(d, groups[0], boxes, config, SimulationOptions{});
  EXPECT_TRUE(out.problem.empty()) << out.problem;
  ASSERT_EQ(out.cable_problems.size(), 1u);
  EXPECT_EQ(out.cable_problems[0].first, 0);
  EXPECT_FALSE(out.cable_problems[0].second.empty());
  ASSERT_EQ(out.cables.size(), 2u);
  for (const CableRelaxation& r : out.cables) {
    EXPECT_TRUE(r.result.converged) << r.setup.name;
    EXPECT_NE(r.setup.cable, 0);
    bool noted = false;
    for (const std::string& n : r.setup.notes) noted |= n.find("did not converge as one") != std::string::npos;
    EXPECT_TRUE(noted) << r.setup.name;
  }
}

}  // namespace
}  // namespace cablefit::addin
