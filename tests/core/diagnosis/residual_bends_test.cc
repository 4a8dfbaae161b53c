#include "residual_bends.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cablefit {
namespace {

// Offsets of n points along a cable of length L: a kink of `angle` at `at` (the residual a point
// force leaves: straight on both sides, bent where it pushes), plus noise.
Eigen::VectorXd Kinked(const Eigen::VectorXd& s, double at, double angle, double noise,
                       unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, noise);
  Eigen::VectorXd r(3 * s.size());
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    const double y = angle * std::max(0.0, s[i] - at) - angle * s[i] * (1.0 - at);  // zero at 0, 1
    r.segment<3>(3 * i) = Eigen::Vector3d(g(rng), y + g(rng), 0.3 * y + g(rng));
  }
  return r;
}

TEST(ResidualBendsTest, FindsAKinkWhereItIs) {
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(200, 0.0, 1.0);
  for (double at : {0.25, 0.5, 0.7}) {
    const std::vector<ResidualBend> bends =
        FindResidualBends(Kinked(s, at, 0.01, 2e-5, 3), s, 1.0, 2);
    ASSERT_FALSE(bends.empty());
    EXPECT_NEAR(bends.front().s, at, 0.02) << at;
    EXPECT_GT(bends.front().curvature, 0.0);
  }
}

// A recording thinned to a few tens of points (fewer than a window needs in a tenth of the
// cable) still shows where it bends.
TEST(ResidualBendsTest, FindsAKinkAmongFewPoints) {
  for (int n : {20, 40}) {
    const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(n, 0.01, 0.55);
    const std::vector<ResidualBend> bends =
        FindResidualBends(Kinked(s, 0.36, 0.005, 2e-5, 7), s, 0.57, 2);
    ASSERT_FALSE(bends.empty()) << n;
    EXPECT_NEAR(bends.front().s, 0.36, 0.04) << n;
  }
}

TEST(ResidualBendsTest, FindsTwoKinksStrongestFirst) {
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(300, 0.0, 1.0);
  const Eigen::VectorXd r = Kinked(s, 0.3, 0.004, 1e-5, 5) + Kinked(s, 0.75, 0.01, 1e-5, 6);
  const std::vector<ResidualBend> bends = FindResidualBends(r, s, 1.0, 2);
  ASSERT_EQ(bends.size(), 2u);
  EXPECT_NEAR(bends[0].s, 0.75, 0.03);
  EXPECT_NEAR(bends[1].s, 0.3, 0.03);
}

TEST(ResidualBendsTest, SkipsAGapAndTooFewPoints) {
  Eigen::VectorXd s(6);
  s << 0.0, 0.1, 0.2, 0.3, 0.4, 0.5;
  EXPECT_TRUE(FindResidualBends(Eigen::VectorXd::Zero(18), s, 1.0, 2).empty());
  // Points only on either side of a gap of a third of the cable: no window there is centred.
  std::vector<double> seen;
  for (int i = 0; i <= 100; ++i)
    if (i < 33 || i > 66) seen.push_back(i / 100.0);
  const Eigen::VectorXd sg =
      Eigen::Map<Eigen::VectorXd>(seen.data(), static_cast<Eigen::Index>(seen.size()));
  for (const ResidualBend& b : FindResidualBends(Kinked(sg, 0.5, 0.01, 0.0, 1), sg, 1.0, 3))
    EXPECT_TRUE(b.s < 0.33 || b.s > 0.66) << b.s;
}

}  // namespace
}  // namespace cablefit
