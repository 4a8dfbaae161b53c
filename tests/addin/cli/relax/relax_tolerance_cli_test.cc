// `cablefit relax --config` with tolerances on a network: the branched-tubes sample (three
// cables meeting at a breakout) varies as one network, and each corner's excursion is what the
// whole harness relaxed on its own with that length gives; a fixing's place on a cable solved
// alone (the legacy harness's hose clip) is varied as far as the hose's slack allows.
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

Json Relax(const fs::path& input, const std::string& config_text, const fs::path& out,
           std::string* stdout_text = nullptr) {
  fs::create_directories(out);
  const fs::path config = out / "harness.json";
  std::ofstream(config) << config_text;
  const auto run = testing::RunCablefit("relax " + Q(input) + " --config " + Q(config) +
                                        " --out " + Q(out / "result") + " --no-pictures");
  EXPECT_EQ(run.exit_code, 0) << run.err << run.out;
  if (stdout_text) *stdout_text = run.out;
  return json::ReadJsonFile((out / "result" / (input.stem().string() + ".json")).string());
}

TEST(RelaxToleranceCli, ANetworkVariesAsOneAndItsCornersAreTheHarnessRelaxedThatLong) {
  const fs::path dir = testing::FreshTempDir("relax_tolerance_network");
  const fs::path sample = testing::SourceDir() / "samples/harness/branched_tubes.stl";
  std::string text;
  const Json env =
      Relax(sample, R"({"format": "cablefit-harness/1", "tolerances": {"length": 0.02}})",
            dir / "envelope", &text);
  EXPECT_TRUE(env["tolerance_problems"].empty()) << env["tolerance_problems"].dump();
  EXPECT_NE(text.find("2 corners of its network"), std::string::npos) << text;
  ASSERT_EQ(env["cables"].size(), 3u);
  for (int k = 0; k < 2; ++k) {
    const double fraction = env["cables"][0]["tolerance"]["corners"][k]["length"].get<double>();
    ASSERT_NEAR(std::abs(fraction), 0.02, 1e-15);
    const Json one = Relax(sample,
                           std::string(R"({"format": "cablefit-harness/1", "default": {"length": ")") +
                               (fraction > 0 ? "+2%" : "-2%") + "\"}}",
                           dir / ("single" + std::to_string(k)));
    for (size_t c = 0; c < 3; ++c) {
      const Json& cable = env["cables"][c];
      const Json& t = cable["tolerance"];
      SCOPED_TRACE(cable["name"].get<std::string>());
      EXPECT_EQ(t["network"].get<std::string>(), "branched_tubes#1, branched_tubes#2, branched_tubes#3");
      EXPECT_EQ(t["corner_selection"], "all");
      EXPECT_GT(t["elements"].get<int>(), 0);
      const double resolution = t["resolution_error"].get<double>();
      EXPECT_LT(resolution, 1e-3);
      const Json& corner = t["corners"][k];
      ASSERT_TRUE(corner["converged"].get<bool>());
      EXPECT_EQ(corner["length"].get<double>(), fraction);
      const double alone = testing::FarthestFromCentreline(cable, testing::CableNamed(one, cable["name"]));
      // The corner is solved at a coarser level than the relaxes; its error mostly cancels
      // against the nominal at that level.
      EXPECT_NEAR(corner["excursion"].get<double>(), alone, 2 * resolution + 1e-4) << fraction;
      EXPECT_GT(alone, 1e-3);  // 2 % of length does move a 0.1 m branch by millimetres
    }
  }
}

TEST(RelaxToleranceCli, TheHoseClipIsShiftedAlongTheHoseAsFarAsItsSlackAllows) {
  const fs::path dir = testing::FreshTempDir("relax_tolerance_clip");
  const fs::path sample = testing::SourceDir() / "samples/harness/legacy_harness.step";
  Json config = json::ReadJsonFile((testing::SourceDir() / "samples/harness/harness.json").string());
  config["tolerances"] = {{"clip_position", 0.01}};
  // The config is written elsewhere: its section file by absolute path.
  config["cables"]["sensor_cable"]["material"]["section"] =
      (testing::SourceDir() / "samples/materials/examples/single-wire.json").string();
  std::string text;
  const Json env = Relax(sample, config.dump(), dir / "clip", &text);
  const Json& hose = testing::CableNamed(env, "hose")["tolerance"];
  ASSERT_EQ(hose["clip_positions"].size(), 1u) << hose.dump();
  // The hose runs nearly straight on either side of its clip: less than the 10 mm asked
  // either way, said in tolerance_problems.
  const Json& clip = hose["clip_positions"][0];
  EXPECT_EQ(clip["origin"].get<std::string>(), "harness.json");
  const double lo = clip["shift_min"].get<double>(), hi = clip["shift_max"].get<double>();
  EXPECT_LT(lo, -1e-3);
  EXPECT_GE(lo, -0.01);
  EXPECT_GT(hi, 1e-3);
  EXPECT_LE(hi, 0.01);
  bool said = false;
  for (const Json& p : env["tolerance_problems"])
    said = said || p.get<std::string>().find("cable 'hose': the support at") != std::string::npos;
  EXPECT_TRUE(said) << env["tolerance_problems"].dump();
  ASSERT_EQ(hose["corners"].size(), 2u);
  for (const Json& c : hose["corners"]) {
    ASSERT_TRUE(c["converged"].get<bool>());
    ASSERT_EQ(c["clip_shift"].size(), 1u);
    const double shift = c["clip_shift"][0].get<double>();
    EXPECT_TRUE(shift == lo || shift == hi) << shift;
    EXPECT_GT(c["excursion"].get<double>(), 1e-4);  // a fixing millimetres off moves the hose
  }
  EXPECT_NE(text.find("tolerance: hose: max excursion"), std::string::npos) << text;
  EXPECT_NE(text.find("clips "), std::string::npos) << text;
}

}  // namespace
}  // namespace cablefit
