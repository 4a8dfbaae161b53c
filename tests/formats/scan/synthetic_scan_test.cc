// Scan -> centreline on synthetic scans of known curves (helix, sag, a loop passing close to
// itself), down to 120 degrees of visible circumference, plus bad input and a timing figure.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/scan_centerline_extractor.h"
#include "scan_test_data.h"
#include "synthetic_tube_scan.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::MakeSyntheticScan;
using testing::SampleCurve;
using testing::SyntheticScanSpec;

ScanGuide GuideFor(const Polyline& curve) {
  const int n = curve.size();
  ScanGuide g;
  g.start_position = curve.points.col(0);
  g.start_tangent = curve.points.col(1) - curve.points.col(0);
  g.end_position = curve.points.col(n - 1);
  g.end_tangent = curve.points.col(n - 1) - curve.points.col(n - 2);
  g.length = curve.s(n - 1);
  return g;
}

// Checks geometry, s, noise and gaps against the generating curve; prints the figures.
void ExpectMatches(const char* name, const Polyline& curve, const SyntheticScanSpec& spec,
                   const ScanCenterline& c) {
  SCOPED_TRACE(name);
  ASSERT_GT(c.size(), 10);
  double max_d = 0.0, sum_d2 = 0.0, max_ds = 0.0;
  for (int i = 0; i < c.size(); ++i) {
    const auto [d, s_true] = testing::ProjectOnPolyline(curve, c.points.col(i));
    max_d = std::max(max_d, d);
    sum_d2 += d * d;
    max_ds = std::max(max_ds, std::abs(c.s(i) - s_true));
  }
  const double rms = std::sqrt(sum_d2 / c.size());
  std::printf("[scan] %-12s n=%4d max=%.3f mm rms=%.3f mm |ds|max=%.2f mm (bound %.2f) sigma=%.4f/%.4f mm"
              " outliers=%d gaps=%zu/%zu\n",
              name, c.size(), max_d * 1e3, rms * 1e3, max_ds * 1e3, c.s_error_bound * 1e3,
              c.noise_sigma * 1e3, spec.noise_sigma * 1e3, c.outlier_count, c.coverage.size() - 1,
              spec.gaps.size());
  EXPECT_LE(max_d, 0.3e-3);
  EXPECT_LE(rms, 0.1e-3);
  EXPECT_LE(max_ds, std::max(c.s_error_bound, 1e-3));
  EXPECT_NEAR(c.noise_sigma, spec.noise_sigma, 0.3 * spec.noise_sigma);
  ASSERT_EQ(c.coverage.size(), spec.gaps.size() + 1);
  EXPECT_NEAR(c.coverage.front().s_start, spec.clamp_margin, 4e-3);
  EXPECT_NEAR(c.coverage.back().s_end, curve.s(curve.size() - 1) - spec.clamp_margin, 4e-3);
  for (std::size_t k = 0; k < spec.gaps.size(); ++k) {
    EXPECT_NEAR(c.coverage[k].s_end, spec.gaps[k](0), 4e-3);
    EXPECT_NEAR(c.coverage[k + 1].s_start, spec.gaps[k](1), 4e-3);
  }
  for (int i = 1; i < c.size(); ++i) EXPECT_GT(c.s(i), c.s(i - 1));
}

Polyline Helix() {
  return SampleCurve([](double u) {
    const double th = 3.0 * M_PI * u;
    return Vec3(0.06 * std::cos(th), 0.06 * std::sin(th), 0.08 / (2.0 * M_PI) * th);
  });
}

// A prolate trochoid: one loop whose strands cross `rise` apart in z.
Polyline Loop(double rise) {
  const double a = 0.04, lambda = 2.5, alpha = 2.1333;  // alpha: sin(alpha) / alpha = 1 / lambda
  return SampleCurve([=](double u) {
    const double th = -M_PI + 2.0 * M_PI * u;
    return Vec3(a * (th - lambda * std::sin(th)), -a * lambda * std::cos(th), rise / (2.0 * alpha) * th);
  });
}

TEST(SyntheticScan, HelixSeenOver120Degrees) {
  const Polyline curve = Helix();
  SyntheticScanSpec spec;
  spec.diameter = 5e-3;
  spec.coverage_deg = 120.0;
  spec.noise_sigma = 0.1e-3;
  spec.gaps = {{0.20, 0.24}, {0.40, 0.43}};
  spec.points = 20000;
  const auto scan = MakeSyntheticScan(curve, spec);
  ScanCenterlineOptions options;
  options.diameter = spec.diameter;
  ExpectMatches("helix-120", curve, spec, ExtractScanCenterline(scan.cloud, options, GuideFor(curve)));
}

TEST(SyntheticScan, SaggingThinCable) {
  const Polyline curve = SampleCurve([](double u) {
    return Vec3(0.7 * u, 0.04 * std::sin(M_PI * u), -0.15 * std::sin(M_PI * u));
  });
  SyntheticScanSpec spec;
  spec.diameter = 3e-3;
  spec.coverage_deg = 150.0;
  spec.noise_sigma = 0.15e-3;
  spec.gaps = {{0.3, 0.35}};
  spec.points = 15000;
  spec.outlier_fraction = 0.01;
  const auto scan = MakeSyntheticScan(curve, spec);
  ScanCenterlineOptions options;
  options.diameter = spec.diameter;
  ExpectMatches("sag-150", curve, spec, ExtractScanCenterline(scan.cloud, options, GuideFor(curve)));
}

TEST(SyntheticScan, LoopPassingCloseToItself) {
  const double diameter = 5e-3;
  const Polyline curve = Loop(diameter + 2.5e-3);
  // The strands must really come close (surfaces a few mm apart) for this test to mean anything.
  double closest = 1e9;
  for (int i = 0; i < curve.size(); i += 10)
    for (int j = i; j < curve.size(); j += 10)
      if (curve.s(j) - curve.s(i) > 0.1) closest = std::min(closest, (curve.points.col(i) - curve.points.col(j)).norm());
  ASSERT_LT(closest, 2.0 * diameter);
  SyntheticScanSpec spec;
  spec.diameter = diameter;
  spec.coverage_deg = 180.0;
  spec.scanner_direction = Vec3(0.2, 0.1, 1.0);
  spec.noise_sigma = 0.08e-3;
  spec.gaps = {{0.12, 0.15}, {0.5, 0.53}};
  spec.points = 25000;
  const auto scan = MakeSyntheticScan(curve, spec);
  ScanCenterlineOptions options;
  options.diameter = diameter;
  ExpectMatches("loop-180", curve, spec, ExtractScanCenterline(scan.cloud, options, GuideFor(curve)));
}

TEST(SyntheticScan, WithoutGuideOrdersFromAnEndAndStartsAtZero) {
  const Polyline curve = Helix();
  SyntheticScanSpec spec;
  spec.diameter = 5e-3;
  spec.gaps = {{0.25, 0.28}};
  const auto scan = MakeSyntheticScan(curve, spec);
  ScanCenterlineOptions options;
  options.diameter = spec.diameter;
  const ScanCenterline c = ExtractScanCenterline(scan.cloud, options);
  ASSERT_EQ(c.coverage.size(), 2u);
  EXPECT_NEAR(c.coverage.front().s_start, 0.0, 1e-9);
  const double seen_length = curve.s(curve.size() - 1) - 2.0 * spec.clamp_margin;
  EXPECT_NEAR(c.coverage.back().s_end, seen_length, 4e-3);
  double max_d = 0.0;
  for (int i = 0; i < c.size(); ++i) max_d = std::max(max_d, testing::ProjectOnPolyline(curve, c.points.col(i)).first);
  EXPECT_LE(max_d, 0.3e-3);
}

TEST(SyntheticScan, Timing40kPoints) {
  const Polyline curve = Helix();
  SyntheticScanSpec spec;
  spec.diameter = 5e-3;
  spec.coverage_deg = 200.0;
  spec.points = 40000;
  spec.gaps = {{0.2, 0.24}};
  const auto scan = MakeSyntheticScan(curve, spec);
  ScanCenterlineOptions options;
  options.diameter = spec.diameter;
  const auto start = std::chrono::steady_clock::now();
  const ScanCenterline c = ExtractScanCenterline(scan.cloud, options, GuideFor(curve));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[scan] timing: %d points -> %d centres in %.3f s\n", scan.cloud.size(), c.size(), seconds);
  EXPECT_EQ(c.coverage.size(), 2u);  // the figure is reported, never asserted
}

TEST(ScanBadInput, EmptyTinyAndNoiseOnlyScansAreRejected) {
  ScanCenterlineOptions options;
  options.diameter = 4e-3;
  PointCloud empty;
  EXPECT_THROW_WITH(ExtractScanCenterline(empty, options), InvalidInput, "scan is empty");
  PointCloud three;
  three.points = Eigen::Matrix3Xd::Random(3, 3);
  EXPECT_THROW_WITH(ExtractScanCenterline(three, options), InvalidInput, "scan has 3 points");
  PointCloud noise;
  noise.points = 0.15 * Eigen::Matrix3Xd::Random(3, 5000);
  EXPECT_THROW_WITH(ExtractScanCenterline(noise, options), InvalidInput, "no cable surface");
  PointCloud nan = noise;
  nan.points(1, 7) = std::nan("");
  EXPECT_THROW_WITH(ExtractScanCenterline(nan, options), InvalidInput, "non-finite");
  ScanCenterlineOptions no_diameter;
  EXPECT_THROW_WITH(ExtractScanCenterline(noise, no_diameter), InvalidInput, "diameter");
}

TEST(ScanBadInput, ScanFarFromTheClampsIsRejected) {
  const Polyline curve = Helix();
  SyntheticScanSpec spec;
  spec.diameter = 5e-3;
  spec.points = 8000;
  auto scan = MakeSyntheticScan(curve, spec);
  scan.cloud.points.colwise() += Vec3(3.0, 0.0, 0.0);  // scan in another frame
  ScanCenterlineOptions options;
  options.diameter = spec.diameter;
  EXPECT_THROW_WITH(ExtractScanCenterline(scan.cloud, options, GuideFor(curve)), InvalidInput,
                    "from a clamp, farther than the cable length");
}

TEST(ScanGuideTest, FromRodSpecTakesTheOuterSupports) {
  RodSpec spec;
  spec.length = 0.5;
  SupportSpec a, b, mid;
  a.s = 0.0;
  a.position = Vec3(1, 0, 0);
  a.tangent = Vec3(0, 2, 0);
  b.s = 0.5;
  b.position = Vec3(2, 0, 0);
  mid.s = 0.2;
  spec.supports = {b, mid, a};
  const ScanGuide g = ScanGuide::FromRodSpec(spec);
  EXPECT_TRUE(g.start_position.isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(g.start_tangent.isApprox(Vec3(0, 1, 0)));
  EXPECT_TRUE(g.end_position.isApprox(Vec3(2, 0, 0)));
  EXPECT_DOUBLE_EQ(g.length, 0.5);
  spec.supports = {a};
  EXPECT_THROW_WITH(ScanGuide::FromRodSpec(spec), InvalidInput, "two supports");
}

}  // namespace
}  // namespace cablefit
