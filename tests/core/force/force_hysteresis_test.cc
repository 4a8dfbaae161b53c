// Jenkins / Iwan elements (Iwan 1966) against hand-derived loops, and the NNLS solver.
#include "cablefit/core/force/force_hysteresis.h"

#include <gtest/gtest.h>

#include "cablefit/core/force/force_nnls.h"
#include "test_support.h"

namespace cablefit {
namespace {

Eigen::VectorXd Vec(std::initializer_list<double> v) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double d : v) out[i++] = d;
  return out;
}

TEST(ForceHysteresis, JenkinsElementSticksThenSlipsThenReverses) {
  // Slip displacement 0.2: elastic up to 0.2, saturated at +1, reversal unloads elastically.
  const Eigen::VectorXd x = Vec({0.1, 0.2, 0.5, 0.4, 0.1, -0.2});
  const Eigen::VectorXd z = UnitJenkinsResponse(0.2, x);
  EXPECT_TRUE(testing::MatricesNear(z, Vec({0.5, 1.0, 1.0, 0.5, -1.0, -1.0}), 1e-14));
}

TEST(ForceHysteresis, SingleElementLoopIsParallelogram) {
  // Cycle 0 -> D -> 0 -> D -> 0 after a virgin start at 0; the stable loop of a Jenkins element
  // encloses 2 f (D - 2 u) (Masing). The first cycle starts from the virgin state, so compare
  // the second one by starting the rows at the first return to 0.
  const double f = 2.0, u = 0.1, d = 1.0;
  Eigen::VectorXd x(801);
  for (int i = 0; i <= 800; ++i) {
    const double t = (i % 400) / 200.0;
    x[i] = d * (t <= 1.0 ? t : 2.0 - t);
  }
  const Eigen::VectorXd y = IwanResponse({{f / u, f}}, x);
  const Eigen::VectorXd x2 = x.tail(401), y2 = y.tail(401);
  EXPECT_NEAR(FirstCycleLoopArea(x2, y2), 2 * f * (d - 2 * u), 1e-9);
  // A single-valued curve encloses nothing.
  EXPECT_NEAR(FirstCycleLoopArea(x2, x2.array().square().matrix()), 0.0, 1e-12);
}

TEST(ForceHysteresis, FirstCycleEndFindsReturn) {
  EXPECT_EQ(FirstCycleEnd(Vec({1, 2, 3, 2, 1, 2, 3, 2, 1})), 4);
  EXPECT_EQ(FirstCycleEnd(Vec({0, 1, 2, 1, 0.5})), 4);  // never returns: last row
  EXPECT_EQ(FirstCycleEnd(Vec({0, -1, -2, -1, 0, 1})), 4);
}

TEST(ForceNnls, MatchesUnconstrainedWhenInteriorAndClampsOtherwise) {
  Eigen::MatrixXd A(4, 2);
  A << 1, 0, 0, 1, 1, 1, 1, -1;
  const Eigen::VectorXd truth = Vec({2.0, 3.0});
  const Eigen::VectorXd x = SolvePartlyNonNegativeLeastSquares(A, A * truth, {true, true});
  EXPECT_TRUE(testing::MatricesNear(x, truth, 1e-12));
  // Unconstrained optimum has x1 = -3 < 0: NNLS puts x1 = 0 and refits x0 alone.
  const Eigen::VectorXd b = A * Vec({2.0, -3.0});
  const Eigen::VectorXd c = SolvePartlyNonNegativeLeastSquares(A, b, {true, true});
  EXPECT_NEAR(c[1], 0.0, 1e-15);
  EXPECT_NEAR(c[0], A.col(0).dot(b) / A.col(0).squaredNorm(), 1e-12);
  // Free unknown keeps its sign.
  const Eigen::VectorXd f = SolvePartlyNonNegativeLeastSquares(A, b, {true, false});
  EXPECT_TRUE(testing::MatricesNear(f, Vec({2.0, -3.0}), 1e-12));
}

TEST(ForceNnls, KktConditionsHoldOnRandomProblem) {
  std::srand(7);
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(30, 8);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(30);
  std::vector<bool> nn(8, true);
  nn[0] = false;
  const Eigen::VectorXd x = SolvePartlyNonNegativeLeastSquares(A, b, nn);
  const Eigen::VectorXd grad = A.transpose() * (A * x - b);  // gradient of half the RSS
  EXPECT_NEAR(grad[0], 0.0, 1e-10);
  for (int j = 1; j < 8; ++j) {
    EXPECT_GE(x[j], 0.0);
    if (x[j] > 0.0)
      EXPECT_NEAR(grad[j], 0.0, 1e-10);
    else
      EXPECT_GE(grad[j], -1e-10);
  }
}

}  // namespace
}  // namespace cablefit
