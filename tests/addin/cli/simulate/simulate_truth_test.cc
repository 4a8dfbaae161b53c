// The proof that the rod core is right: from the recorded (true) shape, the simulator reproduces
// the nominal centreline that an independent high-accuracy shooting solver computed
// (truth.json: extra.nominal_centerline) for every public shape case, within 1e-5 m, with the
// case as written: every clamp's tangent and normal are the frame the reference holds.
#include <gtest/gtest.h>

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
