// The public shape cases end to end: scan -> centreline -> diagnosis, compared with
// truth.json (effect, interval IoU >= 0.4, clamp index, parameters within 15 %).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/ply_reader.h"
#include "cablefit/formats/scan_centerline_extractor.h"
#include "cablefit/formats/truth_reader.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

double IoU(std::pair<double, double> a, std::pair<double, double> b) {
  const double inter = std::max(0.0, std::min(a.second, b.second) - std::max(a.first, b.first));
  const double uni = std::max(a.second, b.second) - std::min(a.first, b.first);
  return uni > 0 ? inter / uni : 0.0;
}

ShapeObservation FromScan(const RecordingCase& rc, const std::string& ply) {
  const PointCloud cloud = ReadPly(ply);
  ScanCenterlineOptions opt;
  opt.diameter = rc.nominal.material.diameter;
  const ScanCenterline sc = ExtractScanCenterline(cloud, opt, ScanGuide::FromRodSpec(rc.nominal));
  ShapeObservation obs;
  obs.points = sc.points;
  obs.s = sc.s;
  obs.noise_sigma = std::max(1e-5, sc.noise_sigma / 10.0);
  for (const auto& c : sc.coverage) obs.coverage.emplace_back(c.s_start, c.s_end);
  return obs;
}

TEST(PublicShapeDiagnosisTest, IdentifiesLocalisesAndQuantifies) {
  const fs::path root = testing::PublicCasesDir();
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(root))
    if (fs::exists(e.path() / "scan.ply")) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  if (testing::SanitizerBuild()) {  // every third case (the long fits take minutes each there)
    std::vector<fs::path> some;
    for (size_t i = 0; i < dirs.size(); i += 3) some.push_back(dirs[i]);
    dirs = some;
  }
  int correct = 0;
  for (const fs::path& d : dirs) {
    const RecordingCase rc = ReadRecordingCase((d / "case.json").string());
    const CaseTruth truth = ReadTruth((d / "truth.json").string());
    const ShapeObservation obs = FromScan(rc, (d / "scan.ply").string());
    const ShapeDiagnosis dg = DiagnoseShape(rc.nominal, obs);
    std::printf("%-30s truth %-24s got %-24s conf %.2f base %.2f mm -> fit %.3f mm  %.1f s\n",
                d.filename().c_str(), truth.effect.c_str(), ToString(dg.effect), dg.confidence,
                dg.baseline_max * 1e3, dg.fitted_max * 1e3, dg.seconds);
    for (const auto& c : dg.candidates)
      std::printf("      %-24s score %.3f bic %.1f\n", ToString(c.effect), c.score, c.bic);
    for (const auto& [k, v] : dg.parameters) std::printf("      param %s = %g\n", k.c_str(), v);
    for (const auto& [k, v] : truth.parameters) std::printf("      truth %s = %g\n", k.c_str(), v);
    if (dg.interval && truth.interval)
      std::printf("      interval [%.3f %.3f] truth [%.3f %.3f] IoU %.2f\n", dg.interval->first,
                  dg.interval->second, truth.interval->first, truth.interval->second,
                  IoU(*dg.interval, *truth.interval));
    std::printf("      explained %d: chi-square %.1f, limit %.1f (dof %d, noise %.1f um)\n",
                dg.explained, dg.adequacy.chi_square, dg.adequacy.limit,
                dg.adequacy.degrees_of_freedom, dg.adequacy.noise_sigma * 1e6);
    EXPECT_TRUE(dg.explained) << d;
    if (ToString(dg.effect) == truth.effect) ++correct;
    if (ToString(dg.effect) != truth.effect || truth.effect == "none") continue;
    // Localised and quantified.
    ASSERT_TRUE(dg.interval && truth.interval) << d;
    EXPECT_GE(IoU(*dg.interval, *truth.interval), 0.4) << d;
    if (truth.clamp) {
      EXPECT_EQ(dg.clamp, truth.clamp) << d;
    }
    for (const char* name : {"ratio", "angle", "curvature", "stiffness", "force", "s"}) {
      if (!truth.parameters.count(name) || !dg.parameters.count(name)) continue;
      EXPECT_NEAR(dg.parameters.at(name), truth.parameters.at(name),
                  0.15 * std::abs(truth.parameters.at(name)))
          << d << " " << name;
    }
    EXPECT_LT(dg.fitted_max, 0.2 * dg.baseline_max) << d;
  }
  std::printf("identified %d of %zu\n", correct, dirs.size());
  EXPECT_EQ(correct, static_cast<int>(dirs.size()));
}

// The candidate fits run on worker threads: the answer must be the same, to the bit, on one.
TEST(PublicShapeDiagnosisTest, TheSameDiagnosisOnAnyNumberOfThreads) {
  const fs::path d = testing::PublicCasesDir() / "sample-support_contact";
  const RecordingCase rc = ReadRecordingCase((d / "case.json").string());
  const ShapeObservation obs = FromScan(rc, (d / "scan.ply").string());
  ShapeDiagnosisOptions one, three;
  three.threads = 3;
  const ShapeDiagnosis a = DiagnoseShape(rc.nominal, obs, one);
  const ShapeDiagnosis b = DiagnoseShape(rc.nominal, obs, three);
  EXPECT_EQ(a.effect, b.effect);
  EXPECT_EQ(a.confidence, b.confidence);
  EXPECT_EQ(a.parameters, b.parameters);
  EXPECT_EQ(a.fitted_max, b.fitted_max);
  ASSERT_EQ(a.candidates.size(), b.candidates.size());
  for (size_t i = 0; i < a.candidates.size(); ++i) {
    EXPECT_EQ(a.candidates[i].effect, b.candidates[i].effect);
    EXPECT_EQ(a.candidates[i].bic, b.candidates[i].bic);
  }
  // The calling thread's time limit stops the workers too.
  const CancellationScope deadline(1e-3);
  EXPECT_THROW(DiagnoseShape(rc.nominal, obs, three), DeadlineExceeded);
}

}  // namespace
}  // namespace cablefit
