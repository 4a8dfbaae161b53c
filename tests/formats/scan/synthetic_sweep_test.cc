// Robustness sweep: harder synthetic scans (thin sparse cables at 120 degrees, thick cables on
// tight bends, a drop, a loop at 120 degrees) over several random seeds.
#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/formats/scan_centerline_extractor.h"
#include "scan_test_data.h"
#include "synthetic_tube_scan.h"

namespace cablefit {
namespace {

using testing::SampleCurve;
using testing::SyntheticScanSpec;

struct Scenario {
  const char* name;
  Polyline curve;
  SyntheticScanSpec spec;
};

std::vector<Scenario> Scenarios() {
  std::vector<Scenario> out;
  {
    SyntheticScanSpec spec;
    spec.diameter = 3e-3;
    spec.coverage_deg = 120.0;
    spec.noise_sigma = 0.15e-3;
    spec.points = 10000;
    spec.outlier_fraction = 0.01;
    spec.gaps = {{0.2, 0.26}, {0.45, 0.47}};
    const double rise = 3e-3 + 3e-3;
    out.push_back({"loop-thin-120", SampleCurve([=](double u) {
                     const double th = -M_PI + 2.0 * M_PI * u;
                     return Vec3(0.035 * (th - 2.5 * std::sin(th)), -0.035 * 2.5 * std::cos(th),
                                 rise / (2.0 * 2.1333) * th);
                   }),
                   spec});
  }
  {
    SyntheticScanSpec spec;
    spec.diameter = 10e-3;
    spec.coverage_deg = 140.0;
    spec.noise_sigma = 0.12e-3;
    spec.points = 40000;
    spec.gaps = {{0.3, 0.35}};
    out.push_back({"thick-tight", SampleCurve([](double u) {
                     const double th = 4.0 * M_PI * u;  // bend radius 40 mm
                     return Vec3(0.04 * std::cos(th), 0.04 * std::sin(th), 0.03 * th);
                   }),
                   spec});
  }
  {
    SyntheticScanSpec spec;
    spec.diameter = 6e-3;
    spec.coverage_deg = 160.0;
    spec.noise_sigma = 0.05e-3;
    spec.points = 15000;
    spec.gaps = {{0.15, 0.19}, {0.5, 0.55}};
    spec.scanner_direction = Vec3(1.0, 0.2, 0.3);
    // A drop: along x, down a smooth step of 0.2 m, along y.
    out.push_back({"drop", SampleCurve([](double u) {
                     const double x = 0.5 * u;
                     const double step = 0.5 * (1.0 - std::tanh((u - 0.5) * 10.0));
                     return Vec3(x, 0.2 * u * u, 0.2 * step);
                   }),
                   spec});
  }
  return out;
}

TEST(SyntheticScanSweep, HardScenariosOverSeeds) {
  for (const Scenario& sc : Scenarios()) {
    for (unsigned seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(std::string(sc.name) + " seed " + std::to_string(seed));
      SyntheticScanSpec spec = sc.spec;
      spec.seed = seed;
      const auto scan = testing::MakeSyntheticScan(sc.curve, spec);
      ScanCenterlineOptions options;
      options.diameter = spec.diameter;
      const int n = sc.curve.size();
      ScanGuide guide;
      guide.start_position = sc.curve.points.col(0);
      guide.start_tangent = sc.curve.points.col(1) - sc.curve.points.col(0);
      guide.end_position = sc.curve.points.col(n - 1);
      guide.end_tangent = sc.curve.points.col(n - 1) - sc.curve.points.col(n - 2);
      guide.length = sc.curve.s(n - 1);
      const ScanCenterline c = ExtractScanCenterline(scan.cloud, options, guide);
      double max_d = 0.0, sum_d2 = 0.0, max_ds = 0.0;
      for (int i = 0; i < c.size(); ++i) {
        const auto [d, s_true] = testing::ProjectOnPolyline(sc.curve, c.points.col(i));
        if (d > 0.2e-3) std::printf("[scan]   off %.3f mm at s=%.4f (i=%d/%d, support %d, stretch %d)\n", d * 1e3, c.s(i), i, c.size(), c.support(i), c.stretch(i));
        max_d = std::max(max_d, d);
        sum_d2 += d * d;
        max_ds = std::max(max_ds, std::abs(c.s(i) - s_true));
      }
      const double rms = std::sqrt(sum_d2 / std::max(c.size(), 1));
      std::printf("[scan] %-14s seed %u n=%4d max=%.3f rms=%.3f mm |ds|=%.2f (bound %.2f) mm sigma=%.4f/%.4f"
                  " gaps=%zu/%zu L=%.4f/%.4f\n",
                  sc.name, seed, c.size(), max_d * 1e3, rms * 1e3, max_ds * 1e3, c.s_error_bound * 1e3,
                  c.noise_sigma * 1e3, spec.noise_sigma * 1e3, c.coverage.size() - 1, spec.gaps.size(),
                  c.estimated_length, guide.length);
      for (const auto& w : c.warnings) std::printf("[scan]   warning: %s\n", w.c_str());
      EXPECT_LE(max_d, 0.3e-3);
      EXPECT_LE(rms, 0.1e-3);
      EXPECT_LE(max_ds, std::max(c.s_error_bound, 1e-3));
      EXPECT_NEAR(c.noise_sigma, spec.noise_sigma, 0.3 * spec.noise_sigma);
      EXPECT_EQ(c.coverage.size(), spec.gaps.size() + 1);
    }
  }
}

}  // namespace
}  // namespace cablefit
