#include "cablefit/formats/kbl_center_curve.h"

#include <gtest/gtest.h>

#include "cablefit/core/base/errors.h"
#include "test_support.h"

namespace cablefit {
namespace {

// A uniform B-spline of degree 1 is the polyline through its control points.
TEST(KblCenterCurve, DegreeOneIsThePolylineThroughThePoints) {
  Eigen::Matrix3Xd p(3, 3);
  p << 0, 1, 1,  //
      0, 0, 2,   //
      0, 0, 0;
  const Polyline c = SampleUniformBSpline(p, 1, 4);
  EXPECT_TRUE(testing::MatricesNear(c.points.col(0), p.col(0), 1e-14));
  EXPECT_TRUE(testing::MatricesNear(c.points.col(c.size() - 1), p.col(2), 1e-14));
  EXPECT_NEAR(c.s[c.size() - 1], 3.0, 1e-12);
}

// Closed form of the uniform cubic: at the start of its domain the point is
// (P0 + 4 P1 + P2) / 6 (Piegl & Tiller, eq. 2.5 with knots 0..n+p), not P0 as for a Bezier.
TEST(KblCenterCurve, UniformCubicStartsAtTheKnownBlendOfItsFirstThreePoints) {
  Eigen::Matrix3Xd p(3, 5);
  p << 0, 1, 3, 4, 6,  //
      0, 2, 2, 0, 1,   //
      0, 0, 1, 1, 0;
  const Vec3 expected = (p.col(0) + 4 * p.col(1) + p.col(2)) / 6.0;
  EXPECT_TRUE(testing::MatricesNear(EvaluateUniformBSpline(p, 3, 3.0), expected, 1e-14));
  const Vec3 expected_end = (p.col(2) + 4 * p.col(3) + p.col(4)) / 6.0;
  EXPECT_TRUE(testing::MatricesNear(EvaluateUniformBSpline(p, 3, 5.0), expected_end, 1e-14));
}

TEST(KblCenterCurve, RefusesTooFewPointsForTheDegree) {
  Eigen::Matrix3Xd p = Eigen::Matrix3Xd::Zero(3, 3);
  EXPECT_THROW_WITH(SampleUniformBSpline(p, 3, 4), InvalidInput, "3 control points for degree 3");
}

}  // namespace
}  // namespace cablefit
