// `cablefit relax --config` with a motion and clearances, end to end on the door-hinge sample:
// the door opens and closes and the cable comes back to its relaxed shape; a pose reached in
// one step or in nine is the same equilibrium; the relaxed cable is pose 0; clearance
// violations are printed; a moving support naming no cable is a problem line, not a failure; the
// tolerance envelope of a length variation matches single relaxes at its extremes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "cablefit/formats/json_util.h"
#include "cli_runner.h"
#include "relax_test_util.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using json::Json;
using testing::Q;
using testing::RunCablefit;

fs::path Sample(const std::string& name) { return testing::SourceDir() / "samples/harness" / name; }

// The sample's harness.json with `edit` applied to its JSON.
fs::path Config(const fs::path& dir, const std::function<void(Json*)>& edit) {
  Json j = json::ReadJsonFile(Sample("door_hinge.json").string());
  edit(&j);
  const fs::path path = dir / "harness.json";
  std::ofstream(path) << j.dump(1);
  return path;
}

Json Relax(const fs::path& config, const fs::path& out, std::string* stdout_text = nullptr) {
  const auto run = RunCablefit("relax " + Q(Sample("door_hinge.stl")) + " --config " +
                               Q(config) + " --out " + Q(out) + " --no-pictures");
  EXPECT_EQ(run.exit_code, 0) << run.err << run.out;
  if (stdout_text) *stdout_text = run.out;
  return json::ReadJsonFile((out / "door_hinge.json").string());
}

TEST(RelaxMotionCli, TheDoorOpensAndClosesAndTheCableComesBack) {
  const fs::path dir = testing::FreshTempDir("relax_motion_door");
  std::string text;
  const Json j = Relax(Sample("door_hinge.json"), dir / "out", &text);
  std::printf("%s", text.c_str());
  EXPECT_NE(text.find("motion 'door opening' (rotation 0..75 deg, 31 poses)"), std::string::npos);
  ASSERT_TRUE(j.contains("motion"));
  EXPECT_EQ(j["motion"]["parameters"].size(), 31u);
  EXPECT_TRUE(j["motion"]["problems"].empty());
  const Json& cable = j["cables"][0];
  const Json& m = cable["motion"];
  ASSERT_EQ(m["poses"].size(), 31u);
  EXPECT_TRUE(m["completed"].get<bool>());
  EXPECT_LT(m["back_to_start"].get<double>(), 1e-9);
  // Pose 0 is the drawn pose: the relaxed cable itself (same solver, same accuracy).
  const Json& rows = cable["relaxed_centreline"]["rows"];
  const Json& pose0 = m["poses"][0]["centreline"]["rows"];
  EXPECT_NEAR(pose0.back()[1].get<double>(), rows.back()[1].get<double>(), 1e-9);
  EXPECT_NEAR(pose0[25][3].get<double>(), rows[(rows.size() - 1) / 2][3].get<double>(), 1e-5);
  // The worst poses are poses of the sweep, and the door end's reaction is in every pose.
  for (const char* w : {"min_bend_radius", "max_tension", "max_support_force", "min_clearance"}) {
    ASSERT_TRUE(m["worst"].contains(w)) << w;
    const int k = m["worst"][w]["pose"].get<int>();
    ASSERT_GE(k, 0);
    ASSERT_LT(k, 31);
  }
  EXPECT_EQ(m["poses"][15]["reactions"].size(), cable["supports"].size());
  // The end moved: its reaction at 75 degrees differs from the drawn pose's.
  const auto force = [&](int pose) {
    const Json& f = m["poses"][pose]["reactions"][1]["force"];
    return std::hypot(f[0].get<double>(), f[1].get<double>(), f[2].get<double>());
  };
  EXPECT_GT(std::abs(force(15) - force(0)), 1e-3);
  const std::string report = testing::ReadTextFile(dir / "out" / "report.html");
  EXPECT_NE(report.find("<h2>Motion</h2>"), std::string::npos);
  EXPECT_NE(report.find("<h2>Clearance</h2>"), std::string::npos);
}

TEST(RelaxMotionCli, APoseReachedInOneStepOrInNineIsTheSameEquilibrium) {
  const fs::path dir = testing::FreshTempDir("relax_motion_steps");
  auto at45 = [&](int steps, const std::string& name) {
    const fs::path config = Config(dir, [&](Json* j) {
      (*j)["motion"]["rotation"]["angles"] = {0, 45};
      (*j)["motion"]["steps"] = steps;
      (*j)["motion"]["return"] = false;
    });
    const Json out = Relax(config, dir / name);
    return out["cables"][0]["motion"]["poses"].back();
  };
  const Json one = at45(1, "one"), nine = at45(9, "nine");
  EXPECT_NEAR(one["q"].get<double>(), 45.0, 1e-9);
  EXPECT_NEAR(nine["q"].get<double>(), 45.0, 1e-9);
  for (int k = 0; k < 2; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(one["reactions"][k]["force"][c].get<double>(),
                  nine["reactions"][k]["force"][c].get<double>(), 1e-5);
  const Json& a = one["centreline"]["rows"];
  const Json& b = nine["centreline"]["rows"];
  for (size_t i = 0; i < a.size(); ++i)
    for (int c = 1; c <= 3; ++c)
      EXPECT_NEAR(a[i][c].get<double>(), b[i][c].get<double>(), 1e-5) << i;
}

TEST(RelaxMotionCli, ClearanceViolationsArePrintedAndAMissingCableIsAProblemLine) {
  const fs::path dir = testing::FreshTempDir("relax_motion_clearance");
  const fs::path config = Config(dir, [](Json* j) {
    (*j)["solids"]["*part4"]["min_clearance"] = 0.1;  // the loudspeaker: 76 mm as relaxed
    (*j)["motion"]["moving"].push_back({{"cable", "no_such_cable"}, {"support", "start"}});
    (*j)["motion"]["steps"] = 3;
  });
  std::string text;
  const Json j = Relax(config, dir / "out", &text);
  EXPECT_NE(text.find("CLEARANCE: door_hinge#1 to solid 'door_hinge-part4'"), std::string::npos)
      << text;
  EXPECT_EQ(j["clearance"]["violations"].get<int>(), 1);
  EXPECT_TRUE(j["cables"][0]["clearance"]["violation"].get<bool>());
  ASSERT_EQ(j["motion"]["problems"].size(), 1u);
  EXPECT_NE(j["motion"]["problems"][0].get<std::string>().find("no cable 'no_such_cable'"),
            std::string::npos);
  // Old fields are still there, unchanged in name.
  for (const char* key : {"deviation", "min_bend_radius", "max_tension", "supports", "solver"})
    EXPECT_TRUE(j["cables"][0].contains(key)) << key;
}

TEST(RelaxMotionCli, TheLengthEnvelopeMatchesSingleRelaxesAtItsExtremes) {
  const fs::path dir = testing::FreshTempDir("relax_tolerance_length");
  const fs::path config = Config(dir, [](Json* j) {
    j->erase("motion");
    (*j)["tolerances"] = {{"length", 0.02}};
  });
  std::string text;
  const Json env = Relax(config, dir / "envelope", &text);
  EXPECT_NE(text.find("tolerance: door_hinge#1: max excursion"), std::string::npos) << text;
  EXPECT_NE(
      testing::ReadTextFile(dir / "envelope" / "report.html").find("<h2>Tolerance envelope</h2>"),
      std::string::npos);
  const Json& t = env["cables"][0]["tolerance"];
  ASSERT_EQ(t["corners"].size(), 2u);
  EXPECT_TRUE(t["interior_within_corners"].get<bool>());
  const Json nominal = env["cables"][0];
  for (int k = 0; k < 2; ++k) {
    const Json& corner = t["corners"][k];
    const double fraction = corner["length"].get<double>();
    ASSERT_NEAR(std::abs(fraction), 0.02, 1e-15);
    // The same cable relaxed on its own at that length (harness.json "length": "+-2%").
    const fs::path single = Config(dir, [&](Json* j) {
      j->erase("motion");
      (*j)["cables"]["door_hinge#1"]["length"] = fraction > 0 ? "+2%" : "-2%";
    });
    const Json one = Relax(single, dir / ("single" + std::to_string(k)));
    const double largest = testing::FarthestFromCentreline(nominal, one["cables"][0]);
    // The relax's ~1 mm output rows against the corner's 201 points on a 1 mm nominal: well
    // under the sampling error.
    EXPECT_NEAR(corner["excursion"].get<double>(), largest, 2e-5) << fraction;
    EXPECT_GT(largest, 1e-3);  // a 2 % longer or shorter cable does move
  }
}

}  // namespace
}  // namespace cablefit
