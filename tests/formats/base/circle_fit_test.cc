// The one circle-fit module: the algebraic fit both users rest on, the robust fits of the scan
// tracer and the 3-D fit of the CAD tube recovery.
#include "cablefit/formats/internal/circle_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace cablefit::internal {
namespace {

// `n` points on an arc of `span` [rad] around `centre` with radius `r`.
Eigen::Matrix2Xd Arc(const Eigen::Vector2d& centre, double r, double span, int n) {
  Eigen::Matrix2Xd p(2, n);
  for (int i = 0; i < n; ++i) {
    const double t = span * i / (n - 1.0);
    p.col(i) = centre + r * Eigen::Vector2d(std::cos(t), std::sin(t));
  }
  return p;
}

TEST(CircleFit, AlgebraicFitIsExactOnAPartialArc) {
  const Eigen::Vector2d centre(3.0, -2.0);
  const CircleFitResult fit = FitCircleAlgebraic(Arc(centre, 0.004, 2.0, 12), Eigen::VectorXd::Ones(12));
  ASSERT_TRUE(fit.converged);
  EXPECT_NEAR((fit.centre - centre).norm(), 0.0, 1e-10);
  EXPECT_NEAR(fit.radius, 0.004, 1e-12);
}

TEST(CircleFit, TooFewOrWeightlessPointsDoNotConverge) {
  EXPECT_FALSE(FitCircleAlgebraic(Arc({0, 0}, 1.0, 1.0, 2), Eigen::VectorXd::Ones(2)).converged);
  EXPECT_FALSE(FitCircleAlgebraic(Arc({0, 0}, 1.0, 1.0, 5), Eigen::VectorXd::Zero(5)).converged);
  EXPECT_FALSE(FitCircleFree(Arc({0, 0}, 1.0, 1.0, 3), Eigen::VectorXd::Ones(3)).converged);
}

TEST(CircleFit, FreeAndKnownRadiusFitsFindTheCircle) {
  const Eigen::Vector2d centre(0.01, 0.02);
  Eigen::Matrix2Xd p = Arc(centre, 0.005, 2.5, 40);
  p(0, 7) += 0.003;  // one outlier: the known-radius fit is robust to it
  const CircleFitResult known = FitCircleKnownRadius(p, centre + Eigen::Vector2d(0.001, 0), 0.005, 1e-6);
  ASSERT_TRUE(known.converged);
  EXPECT_NEAR((known.centre - centre).norm(), 0.0, 1e-6);
  const CircleFitResult free = FitCircleFree(Arc(centre, 0.005, 2.5, 40), Eigen::VectorXd::Ones(40));
  ASSERT_TRUE(free.converged);
  EXPECT_NEAR((free.centre - centre).norm(), 0.0, 1e-10);
  EXPECT_NEAR(free.radius, 0.005, 1e-12);
}

TEST(CircleFit, ThreeDimensionalFitFindsCentreNormalAndRadius) {
  const Eigen::Vector3d centre(0.1, -0.2, 0.3);
  const Eigen::Vector3d normal = Eigen::Vector3d(1, 2, 2).normalized();
  const Eigen::Vector3d e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
  const Eigen::Matrix2Xd arc = Arc({0, 0}, 0.007, 0.75 * std::numbers::pi, 16);
  Eigen::Matrix3Xd p(3, arc.cols());
  for (Eigen::Index i = 0; i < arc.cols(); ++i) p.col(i) = centre + arc(0, i) * e1 + arc(1, i) * e2;
  const CircleFit fit = FitCircle(p);
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR((fit.centre - centre).norm(), 0.0, 1e-10);
  EXPECT_NEAR(std::abs(fit.normal.dot(normal)), 1.0, 1e-12);
  EXPECT_NEAR(fit.radius, 0.007, 1e-12);
  EXPECT_LT(fit.rms_residual, 1e-12);
  Eigen::Matrix3Xd line(3, 5);
  for (int i = 0; i < 5; ++i) line.col(i) = centre + i * e1;
  EXPECT_FALSE(FitCircle(line).ok);  // collinear
}

}  // namespace
}  // namespace cablefit::internal
