// The KBL-sized synthetic harness (a tree of splices, breakouts, fixings and clamped connectors)
// relaxes as one network whether its segments are cut as drawn, shorter (pulled taut and
// stretched) or longer (slack that sags and buckles): the solve starts from the drawing taken as
// its own rest shape, where it is in equilibrium, and follows the path to the real one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cablefit/app/bench/bench_harness.h"
#include "cablefit/app/relax/relax_network.h"
#include "cablefit/core/network/network_simulator.h"

namespace cablefit::addin {
namespace {

double PolylineLength(const Polyline& p) {
  double l = 0.0;
  for (int i = 1; i < p.size(); ++i) l += (p.points.col(i) - p.points.col(i - 1)).norm();
  return l;
}

TEST(KblSizedHarness, RelaxesShorterAsDrawnAndLongerThanDrawn) {
  for (const double change : {-0.02, 0.0, 0.02, 0.05}) {
    KblSizedHarnessSize size;
    size.segments = 40;
    size.fixings = 4;
    size.length_change = change;
    const NetworkSpec spec = KblSizedHarness(size);
    const NetworkRelaxPlan planned = PlanNetworkRelax(spec, SimulationOptions{});
    const NetworkSimulation sim = SimulateNetwork(spec, planned.plan, planned.options);
    const std::string label = std::to_string(100 * change) + " %";
    ASSERT_TRUE(sim.converged) << label << ": " << sim.finest.summary.BriefReport();
    ASSERT_EQ(sim.centerlines.size(), spec.branches.size());
    // Inextensible where slack; where pulled taut the bundle stretches by its EA only: within
    // 1 % of the length it is built with either way.
    for (size_t b = 0; b < spec.branches.size(); ++b)
      EXPECT_NEAR(PolylineLength(sim.centerlines[b]), spec.branches[b].length,
                  0.01 * spec.branches[b].length)
          << label << ", " << spec.branches[b].name;
  }
}

}  // namespace
}  // namespace cablefit::addin
