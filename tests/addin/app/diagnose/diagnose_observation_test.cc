// The observation the shape diagnosis is given: centre-point noise estimated from a measured
// centreline, and from a scan's extraction statistics.
#include "diagnose/diagnose_observation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cablefit::addin {
namespace {

/// A sagging arc (radius 0.4 m, 0.6 m long) sampled every `step` with Gaussian noise `sigma`.
Polyline NoisyArc(double sigma, double step, unsigned seed) {
  const int n = static_cast<int>(0.6 / step) + 1;
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  Polyline line;
  line.points.resize(3, n);
  line.s.resize(n);
  for (int i = 0; i < n; ++i) {
    const double s = i * step, a = s / 0.4;
    line.s[i] = s;
    line.points.col(i) = Vec3(0.4 * std::sin(a), 0.1 * s, 0.4 * (std::cos(a) - 1.0)) +
                         Vec3(noise(rng), noise(rng), noise(rng));
  }
  return line;
}

TEST(EstimateCenterlineNoise, RecoversTheNoiseOfACurvedLine) {
  for (double sigma : {2e-5, 1e-4, 5e-4}) {
    for (unsigned seed : {1u, 2u, 3u}) {
      const double est = EstimateCenterlineNoise(NoisyArc(sigma, 0.003, seed));
      EXPECT_NEAR(est, sigma, 0.15 * sigma) << "sigma " << sigma << " seed " << seed;
    }
  }
}

TEST(EstimateCenterlineNoise, CurvatureAloneIsNotNoise) {
  // Noise-free but strongly curved (radius 0.4 m at 3 mm steps): the floor, not the curvature.
  EXPECT_DOUBLE_EQ(EstimateCenterlineNoise(NoisyArc(0.0, 0.003, 1)), kMinCentreNoise);
}

TEST(EstimateCenterlineNoise, OutliersDoNotInflateIt) {
  Polyline line = NoisyArc(1e-4, 0.003, 7);
  for (int i = 10; i < line.size(); i += 40) line.points(2, i) += 0.01;  // 1 cm spikes
  EXPECT_NEAR(EstimateCenterlineNoise(line), 1e-4, 0.3e-4);
}

TEST(EstimateCenterlineNoise, ShortLinesGetTheDefault) {
  Polyline line = NoisyArc(1e-3, 0.1, 1);
  ASSERT_LT(line.size(), 8);
  EXPECT_DOUBLE_EQ(EstimateCenterlineNoise(line), kDefaultCentreNoise);
}

TEST(ObservationFromCenterline, CoversTheWholeCableAndFillsMissingS) {
  Polyline line = NoisyArc(1e-4, 0.003, 4);
  line.s.resize(0);
  const ShapeObservation obs = ObservationFromCenterline(line, 0.61);
  ASSERT_EQ(obs.s.size(), line.size());
  EXPECT_DOUBLE_EQ(obs.s[0], 0.0);
  EXPECT_GT(obs.s[obs.s.size() - 1], 0.59);
  ASSERT_EQ(obs.coverage.size(), 1u);
  EXPECT_DOUBLE_EQ(obs.coverage[0].second, 0.61);
  EXPECT_NEAR(obs.noise_sigma, 1e-4, 0.2e-4);
}

TEST(ObservationFromScan, CentreNoiseAveragesTheSupportingPoints) {
  ScanCenterline scan;
  scan.points = Eigen::Matrix3Xd::Zero(3, 4);
  scan.s = Eigen::Vector4d(0.1, 0.2, 0.4, 0.5);
  scan.support = Eigen::Vector4i(100, 100, 100, 100);
  scan.noise_sigma = 2e-3;
  scan.coverage = {{0.05, 0.25}, {0.35, 0.55}};
  const ShapeObservation obs = ObservationFromScan(scan);
  EXPECT_NEAR(obs.noise_sigma, 2e-4, 1e-12);  // 2 mm / sqrt(100)
  ASSERT_EQ(obs.coverage.size(), 2u);
  EXPECT_DOUBLE_EQ(obs.coverage[1].first, 0.35);
  scan.noise_sigma = 1e-5;  // a very clean scan still gets the floor
  EXPECT_DOUBLE_EQ(ObservationFromScan(scan).noise_sigma, kMinCentreNoise);
}

}  // namespace
}  // namespace cablefit::addin
