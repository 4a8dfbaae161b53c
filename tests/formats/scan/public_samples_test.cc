// Scan -> centreline on every public shape case, against truth.json's true centreline.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/ply_reader.h"
#include "cablefit/formats/scan_centerline_extractor.h"
#include "cablefit/formats/truth_reader.h"
#include "scan_test_data.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> ScanCases() {
  std::vector<fs::path> out;
  const fs::path root = testing::PublicCasesDir();
  if (!fs::exists(root)) return out;
  for (const auto& e : fs::directory_iterator(root))
    if (fs::exists(e.path() / "scan.ply") && fs::exists(e.path() / "truth.json")) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(PublicScanSamples, CentrelineNoiseAndGapsMatchTruth) {
  const auto cases = ScanCases();
  ASSERT_GE(cases.size(), 1u) << "no public scan cases under " << testing::PublicCasesDir();
  for (const fs::path& dir : cases) {
    SCOPED_TRACE(dir.filename().string());
    const RecordingCase rc = ReadRecordingCase((dir / "case.json").string());
    const auto scan_ref = std::find_if(rc.recordings.begin(), rc.recordings.end(),
                                       [](const RecordingRef& r) { return r.kind == RecordingKind::kScan; });
    ASSERT_NE(scan_ref, rc.recordings.end());
    const PointCloud cloud = ReadPly(scan_ref->path);
    const testing::TruthScan truth = testing::LoadTruthScan(dir / "truth.json");
    const Polyline true_line = ReadTruthCenterline((dir / "truth.json").string(), "truth_centerline");
    const ScanGuide guide = ScanGuide::FromRodSpec(rc.nominal);
    ScanCenterlineOptions options;
    options.diameter = rc.nominal.material.diameter;
    const auto start = std::chrono::steady_clock::now();
    const ScanCenterline c = ExtractScanCenterline(cloud, options, guide);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_GT(c.size(), 10);

    const Polyline fine = testing::Densify(true_line, 16);
    double max_d = 0.0, sum_d2 = 0.0, max_ds = 0.0;
    for (int i = 0; i < c.size(); ++i) {
      const auto [d, s_true] = testing::ProjectOnPolyline(fine, c.points.col(i));
      max_d = std::max(max_d, d);
      sum_d2 += d * d;
      max_ds = std::max(max_ds, std::abs(c.s(i) - s_true));
    }
    const double rms = std::sqrt(sum_d2 / c.size());
    // Expected gaps: the clamp margins and the listed interior gaps; ours: complement of coverage.
    std::vector<Eigen::Vector2d> gaps_truth = truth.gaps;
    std::vector<Eigen::Vector2d> gaps_ours;
    for (std::size_t k = 1; k < c.coverage.size(); ++k)
      gaps_ours.emplace_back(c.coverage[k - 1].s_end, c.coverage[k].s_start);
    double worst_gap_edge = 0.0;
    if (gaps_ours.size() == gaps_truth.size()) {
      for (std::size_t k = 0; k < gaps_ours.size(); ++k)
        worst_gap_edge = std::max(worst_gap_edge, (gaps_ours[k] - gaps_truth[k]).cwiseAbs().maxCoeff());
    }
    const double first_seen_error = std::abs(c.coverage.front().s_start - truth.clamp_margins(0));
    std::printf("[scan] %-28s n=%5d pts=%6d  max=%.3f mm rms=%.3f mm  |ds|max=%.2f mm (bound %.2f)"
                "  sigma=%.4f/%.4f mm  outliers=%d/%d  gaps=%zu/%zu edge=%.2f mm  start=%.2f mm  %.3f s\n",
                dir.filename().string().c_str(), c.size(), cloud.size(), max_d * 1e3, rms * 1e3,
                max_ds * 1e3, c.s_error_bound * 1e3, c.noise_sigma * 1e3, truth.noise_sigma * 1e3,
                c.outlier_count, truth.n_outliers, gaps_ours.size(), gaps_truth.size(),
                worst_gap_edge * 1e3, first_seen_error * 1e3, seconds);
    for (const auto& w : c.warnings) std::printf("[scan]   warning: %s\n", w.c_str());

    EXPECT_LE(max_d, 0.3e-3);
    EXPECT_LE(rms, 0.1e-3);
    EXPECT_NEAR(c.noise_sigma, truth.noise_sigma, 0.3 * truth.noise_sigma);
    EXPECT_NEAR(c.outlier_count, truth.n_outliers, 0.25 * truth.n_outliers + 10);
    EXPECT_TRUE(c.warnings.empty());
    ASSERT_EQ(gaps_ours.size(), gaps_truth.size());
    EXPECT_LE(worst_gap_edge, 4e-3);
    EXPECT_LE(first_seen_error, 4e-3);
    EXPECT_LE(max_ds, std::max(c.s_error_bound, 1e-3));
    EXPECT_NEAR(c.estimated_length, guide.length, std::max(c.s_error_bound, 2e-3));
  }
}

}  // namespace
}  // namespace cablefit
