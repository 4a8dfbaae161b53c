// The proof that the rod core is right: from the recorded (true) shape, the simulator reproduces
// the nominal centreline that an independent high-accuracy shooting solver computed
// (truth.json: extra.nominal_centerline) for every public shape case, within 1e-5 m, with the
// case as written: every clamp's tangent and normal are the frame the reference holds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/formats/truth_reader.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

struct ShapeCase {
  fs::path dir;
  RecordingCase rc;
  Polyline recorded;
  Polyline reference;
  double twist_deg = 0.0;
};

std::vector<ShapeCase> PublicShapeCases() {
  std::vector<ShapeCase> out;
  const fs::path root = testing::PublicCasesDir();
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(root)) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  for (const auto& d : dirs) {
    const fs::path truth = d / "truth.json";
    if (!fs::exists(d / "scan.ply") || !fs::exists(truth)) continue;
    ShapeCase c;
    c.dir = d;
    c.rc = ReadRecordingCase((d / "case.json").string());
    c.recorded = ReadTruthCenterline(truth.string(), "truth_centerline");
    c.reference = ReadTruthCenterline(truth.string(), "nominal_centerline");
    c.twist_deg = json::ReadJsonFile(truth.string())["extra"]["nominal_twist_deg"].get<double>();
    out.push_back(std::move(c));
  }
  return out;
}

// The same, allowing for the precision the reference is written with: its arc lengths have six
// decimals, so each reference point may lie up to 0.5 um along the curve from where its s says.
// Only that much of the distance along the tangent is forgiven; the rest counts.
double MaxDistanceWithinReferencePrecision(const Polyline& ours, const Polyline& ref) {
  constexpr double kArcLengthPrecision = 0.5e-6;  // [m] half of the last written decimal
  constexpr double kTangentStep = 1e-5;           // [m]
  const Polyline at = SampleCenterline(ours, ref.s);
  const Polyline ahead = SampleCenterline(ours, (ref.s.array() + kTangentStep).matrix());
  const Polyline behind = SampleCenterline(ours, (ref.s.array() - kTangentStep).matrix());
  double worst = 0.0;
  for (int k = 0; k < ref.size(); ++k) {
    const Vec3 tangent = (ahead.points.col(k) - behind.points.col(k)).normalized();
    const Vec3 miss = ref.points.col(k) - at.points.col(k);
    const double along = std::clamp(miss.dot(tangent), -kArcLengthPrecision, kArcLengthPrecision);
    worst = std::max(worst, (miss - along * tangent).norm());
  }
  return worst;
}

double MaxDistance(const Polyline& ours, const Polyline& ref) {
  const Polyline at = SampleCenterline(ours, ref.s);
  return (at.points - ref.points).colwise().norm().maxCoeff();
}

TEST(SimulateTruthTest, ReproducesIndependentNominalCenterlinesWithTheCaseAsWritten) {
  const auto cases = PublicShapeCases();
  ASSERT_GE(cases.size(), 8u);
  for (const ShapeCase& c : cases) {
    RodSimulator sim;
    const SimulationResult r = sim.Simulate(c.rc.nominal, &c.recorded);
    ASSERT_TRUE(r.converged) << c.dir;
    const double err = MaxDistance(r.solution.centerline, c.reference);
    std::printf("%-30s reference twist %7.2f deg: max distance %.2e m\n",
                c.dir.filename().c_str(), c.twist_deg, err);
    EXPECT_LE(err, 1e-5) << c.dir;
  }
}

// At the default accuracy the requested accuracy is met and the reported error estimate is
// honest: the distance to the independent reference, at the arc lengths it was sampled at
// (between nodes too, where the result is interpolated), is below the requested accuracy, and,
// up to the precision the reference is written with, below the estimate.
TEST(SimulateTruthTest, ErrorEstimateBoundsTheTrueErrorAtTheRequestedAccuracy) {
  const auto cases = PublicShapeCases();
  ASSERT_GE(cases.size(), 8u);
  for (const ShapeCase& c : cases) {
    SimulationOptions opt;
    RodSimulator sim(opt);
    const SimulationResult r = sim.Simulate(c.rc.nominal, &c.recorded);
    ASSERT_TRUE(r.converged) << c.dir;
    const double err = MaxDistance(r.solution.centerline, c.reference);
    const double err_precise = MaxDistanceWithinReferencePrecision(r.solution.centerline, c.reference);
    std::printf("%-30s true error %.2e m (%.2e m within the reference's precision), "
                "estimate %.2e m, %d elements, %.0f ms\n",
                c.dir.filename().c_str(), err, err_precise, r.estimated_error,
                r.level_elements.empty() ? 0 : r.level_elements.back(), r.seconds * 1e3);
    EXPECT_TRUE(r.accuracy_met) << c.dir;
    EXPECT_LE(err, opt.accuracy) << c.dir;
    EXPECT_LE(err_precise, r.estimated_error) << c.dir;
  }
}

TEST(SimulateTruthTest, CommandLineReproducesTheReferencesWithTheCaseAsWritten) {
  for (const ShapeCase& c : PublicShapeCases()) {
    const fs::path tmp = testing::FreshTempDir(c.dir.filename().string());
    WriteCenterlineCsv((tmp / "initial.csv").string(), c.recorded);
    const auto run = testing::RunCablefit("simulate '" + (c.dir / "case.json").string() +
                                          "' --out '" + (tmp / "out").string() + "' --initial '" +
                                          (tmp / "initial.csv").string() + "'");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Polyline ours = ReadCenterlineCsv((tmp / "out" / "centerline.csv").string());
    const double err = MaxDistance(ours, c.reference);
    std::printf("%-30s (command line) max distance %.2e m\n", c.dir.filename().c_str(), err);
    EXPECT_LE(err, 1e-5) << c.dir;
    EXPECT_TRUE(fs::exists(tmp / "out" / "solution.json"));
  }
}

}  // namespace
}  // namespace cablefit
