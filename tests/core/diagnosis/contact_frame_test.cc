#include "contact_frame.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cablefit::internal {
namespace {

// A vertical half-circle of radius r in the x-z plane, sagging below its ends, sampled at
// `count` points (arc length from the left end); its tangent at arc length s is known exactly.
struct Arc {
  double r = 0.5;
  Eigen::Matrix3Xd points;
  Eigen::VectorXd s;
  Vec3 Tangent(double t) const {
    const double phi = M_PI + t / r;  // angle from the centre, starting at the left end
    return Vec3(-std::sin(phi), 0.0, std::cos(phi));
  }
};

Arc SaggingArc(int count) {
  Arc a;
  a.points.resize(3, count);
  a.s.resize(count);
  for (int i = 0; i < count; ++i) {
    a.s[i] = M_PI * a.r * i / (count - 1);
    const double phi = M_PI + a.s[i] / a.r;
    a.points.col(i) = Vec3(a.r * std::cos(phi), 0.0, a.r * std::sin(phi));
  }
  return a;
}

TEST(ContactFrame, IsNormalToTheRecordedCableAndPushesAgainstGravity) {
  const Arc arc = SaggingArc(200);
  const Vec3 g(0, 0, -9.81);
  for (double t : {0.3, 0.6, 0.785, 1.0, 1.3}) {
    SCOPED_TRACE(t);
    const ContactFrame f = RecordedContactFrame(arc.points, arc.s, t, 0.02, g);
    EXPECT_GT(f.tangent.dot(arc.Tangent(t)), std::cos(0.01));
    EXPECT_NEAR(f.up.dot(f.tangent), 0.0, 1e-12);
    EXPECT_NEAR(f.side.dot(f.tangent), 0.0, 1e-12);
    EXPECT_NEAR(f.up.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.side.norm(), 1.0, 1e-12);
    EXPECT_GT(f.up.z(), 0.0);  // a support the cable rests on pushes it up
  }
  // At the bottom of the sag the tangent is horizontal and up is straight up.
  const ContactFrame bottom = RecordedContactFrame(arc.points, arc.s, M_PI * arc.r / 2, 0.02, g);
  EXPECT_GT(bottom.up.z(), std::cos(0.01));
}

TEST(ContactFrame, AGapInTheRecordingWidensTheWindowInsteadOfFailing) {
  const Arc full = SaggingArc(60);
  // Keep only the points far from s = 0.8: none within the 0.02 m window.
  std::vector<int> kept;
  for (int i = 0; i < full.s.size(); ++i)
    if (std::abs(full.s[i] - 0.8) > 0.15) kept.push_back(i);
  Eigen::Matrix3Xd points(3, static_cast<int>(kept.size()));
  Eigen::VectorXd s(static_cast<int>(kept.size()));
  for (size_t k = 0; k < kept.size(); ++k) {
    points.col(static_cast<int>(k)) = full.points.col(kept[k]);
    s[static_cast<int>(k)] = full.s[kept[k]];
  }
  const ContactFrame f = RecordedContactFrame(points, s, 0.8, 0.02, Vec3(0, 0, -9.81));
  ASSERT_TRUE(f.tangent.allFinite());
  // The chord across the gap: within a few degrees of the true tangent there.
  EXPECT_GT(f.tangent.dot(full.Tangent(0.8)), std::cos(0.1));
}

TEST(ContactFrame, AVerticalCableOrNoGravityStillGetsAnOrthonormalFrame) {
  Eigen::Matrix3Xd points(3, 5);
  Eigen::VectorXd s(5);
  for (int i = 0; i < 5; ++i) {
    points.col(i) = Vec3(0, 0, -0.1 * i);
    s[i] = 0.1 * i;
  }
  for (const Vec3& g : {Vec3(0, 0, -9.81), Vec3(0, 0, 0)}) {
    const ContactFrame f = RecordedContactFrame(points, s, 0.2, 0.05, g);
    EXPECT_TRUE(f.tangent.isApprox(Vec3(0, 0, -1), 1e-12));
    EXPECT_NEAR(f.up.dot(f.tangent), 0.0, 1e-12);
    EXPECT_NEAR(f.side.dot(f.up), 0.0, 1e-12);
    EXPECT_NEAR(f.up.norm(), 1.0, 1e-12);
  }
}

TEST(ContactFrame, FewerThanTwoPointsIsRefused) {
  EXPECT_ANY_THROW(RecordedContactFrame(Eigen::Matrix3Xd::Zero(3, 1), Eigen::VectorXd::Zero(1),
                                        0.0, 0.1, Vec3(0, 0, -9.81)));
}

}  // namespace
}  // namespace cablefit::internal
