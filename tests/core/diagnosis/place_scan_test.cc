#include "place_scan.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cablefit {
namespace {

TEST(PlaceScanTest, GaussNewtonStepRemovesAResidualTheColumnsSpan) {
  Eigen::MatrixXd a(4, 2);
  a << 1, 0, 0, 1, 1, 1, 2, -1;
  const Eigen::Vector2d truth(0.5, -2.0);
  const LinearisedStep step = DampedGaussNewton(-a * truth, a);
  EXPECT_NEAR(step.step[0], truth[0], 1e-2);
  EXPECT_NEAR(step.step[1], truth[1], 1e-2);
  EXPECT_LT(step.cost, 1e-4);
}

// A column the other one nearly repeats: the damping keeps both steps of the size the residual
// needs, instead of two huge ones that cancel.
TEST(PlaceScanTest, NearlyRepeatedColumnsTakeBoundedSteps) {
  Eigen::MatrixXd a(3, 2);
  a << 1, 1 + 1e-9, 1, 1 - 1e-9, 1, 1;
  const LinearisedStep step = DampedGaussNewton(Eigen::Vector3d(-1, -1, -1), a);
  EXPECT_LT(step.step.cwiseAbs().maxCoeff(), 2.0);
  EXPECT_LT(step.cost, 1e-3);
}

TEST(PlaceScanTest, BestPlacesAreSeparatedLocalLeasts) {
  // Two valleys along the cable (at 0.3 and 0.7), the deeper at 0.7; a place next to the best
  // one is lower than the second valley but belongs to the first.
  std::vector<double> where, cost;
  for (int i = 0; i <= 20; ++i) {
    const double s = 0.05 * i;
    where.push_back(s);
    cost.push_back(std::min(1.0 + 50 * (s - 0.3) * (s - 0.3), 0.5 + 50 * (s - 0.7) * (s - 0.7)));
  }
  cost[3] = INFINITY;  // a place that could not be solved
  const std::vector<int> best = BestSeparatedPlaces(cost, where, 0.1, 2);
  ASSERT_EQ(best.size(), 2u);
  EXPECT_NEAR(where[static_cast<size_t>(best[0])], 0.7, 1e-9);
  EXPECT_GT(std::abs(where[static_cast<size_t>(best[1])] - 0.7), 0.1);
  EXPECT_EQ(BestSeparatedPlaces(cost, where, 0.1, 1).size(), 1u);
}

}  // namespace
}  // namespace cablefit
