// Centreline sampling: a cubic through the nodes is reproduced exactly (the stencil is cubic
// Lagrange), in any sample order, and the ends clamp.
#include "cablefit/core/solver/centerline_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cablefit {
namespace {

Vec3 Cubic(double s) { return Vec3(s, 0.3 * s * s - s * s * s, 2.0 - 0.5 * s * s * s); }

TEST(CenterlineSamplingTest, ReproducesACubicInAnyOrder) {
  // Uneven node spacing, as a network's stretch or a refined rod has.
  Polyline nodes;
  const int n = 23;
  nodes.s.resize(n);
  nodes.points.resize(3, n);
  for (int i = 0; i < n; ++i) {
    nodes.s[i] = std::pow(static_cast<double>(i) / (n - 1), 1.3);
    nodes.points.col(i) = Cubic(nodes.s[i]);
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  Eigen::VectorXd ascending = UniformArcLengths(1.0, 501), shuffled(300);
  for (int k = 0; k < shuffled.size(); ++k) shuffled[k] = u(rng);
  for (const Eigen::VectorXd& s : {ascending, shuffled}) {
    const Polyline out = SampleCenterline(nodes, s);
    ASSERT_EQ(out.points.cols(), s.size());
    for (int k = 0; k < s.size(); ++k) {
      const double x = std::clamp(s[k], 0.0, 1.0);
      EXPECT_LT((out.points.col(k) - Cubic(x)).norm(), 1e-12) << s[k];
      EXPECT_EQ(out.s[k], s[k]);
    }
  }
}

TEST(CenterlineSamplingTest, FewNodes) {
  for (int n : {2, 3, 4}) {
    Polyline nodes;
    nodes.s = Eigen::VectorXd::LinSpaced(n, 0.0, 1.0);
    nodes.points.resize(3, n);
    for (int i = 0; i < n; ++i) nodes.points.col(i) = Vec3(nodes.s[i], 2 * nodes.s[i], 0);
    const Polyline out = SampleCenterline(nodes, UniformArcLengths(1.0, 11));
    for (int k = 0; k < 11; ++k)
      EXPECT_LT((out.points.col(k) - Vec3(0.1 * k, 0.2 * k, 0)).norm(), 1e-12) << n;
  }
}

}  // namespace
}  // namespace cablefit
