// `cablefit relax --config` with a motion that moves a cable of a network: the branched-tubes
// sample (three cables meeting at a breakout, each clamped at its far end: branched_tubes#3 runs
// from the breakout to its clamp) with that clamp swung about the vertical axis and back. The whole network moves: every cable of it has
// its motion, comes back to its start shape, and the swung clamp is where the rotation puts it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "cablefit/formats/json_util.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using json::Json;
using testing::Q;

Eigen::Vector3d Vec(const Json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

TEST(RelaxMotionNetworkCli, ACableOfANetworkSwungOutAndBackMovesTheWholeNetwork) {
  const fs::path dir = testing::FreshTempDir("relax_motion_network");
  const fs::path config = dir / "harness.json";
  std::ofstream(config) << R"({
  "format": "cablefit-harness/1",
  "motion": {
    "name": "swing",
    "rotation": {"axis": [0, 0, 1], "point": [0, 0, 0], "angles": [0, 20]},
    "steps": 10,
    "return": true,
    "moving": [{"cable": "branched_tubes#3", "support": "end"}]
  }
})";
  const fs::path sample = testing::SourceDir() / "samples/harness/branched_tubes.stl";
  const auto run = testing::RunCablefit("relax " + Q(sample) + " --config " + Q(config) +
                                        " --out " + Q(dir / "out") + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  EXPECT_NE(run.out.find("swept as one network with branched_tubes#1, branched_tubes#2, "
                         "branched_tubes#3"),
            std::string::npos)
      << run.out;
  const Json j = json::ReadJsonFile((dir / "out" / "branched_tubes.json").string());
  EXPECT_TRUE(j["motion"]["problems"].empty()) << j["motion"]["problems"].dump();
  ASSERT_EQ(j["motion"]["cables"].size(), 3u);
  ASSERT_EQ(j["cables"].size(), 3u);
  double largest_move = 0.0;
  for (const Json& cable : j["cables"]) {
    const Json& m = cable["motion"];
    SCOPED_TRACE(cable["name"].get<std::string>());
    ASSERT_EQ(m["poses"].size(), 21u);
    EXPECT_TRUE(m["completed"].get<bool>());
    EXPECT_TRUE(m["stability_lost"].is_null());
    EXPECT_LT(m["back_to_start"].get<double>(), 1e-9);
    ASSERT_FALSE(m["network"].is_null());
    EXPECT_GT(m["network"]["elements"].get<int>(), 0);
    // Pose 0 is the drawn pose: within the sweep's reported resolution of the relaxed cable.
    const double resolution = m["network"]["resolution_error"].get<double>();
    EXPECT_LT(resolution, 1e-4);
    const Json& relaxed = cable["relaxed_centreline"]["rows"];
    const Json& pose0 = m["poses"][0]["centreline"]["rows"];
    EXPECT_LT((Vec({pose0.back()[1], pose0.back()[2], pose0.back()[3]}) -
               Vec({relaxed.back()[1], relaxed.back()[2], relaxed.back()[3]}))
                  .norm(),
              resolution + 1e-9);
    const Json& open = m["poses"][10]["centreline"]["rows"];
    for (size_t k = 0; k < open.size(); ++k)
      largest_move = std::max(
          largest_move, (Vec({open[k][1], open[k][2], open[k][3]}) -
                         Vec({pose0[k][1], pose0[k][2], pose0[k][3]}))
                            .norm());
  }
  // The swung clamp (the end of branched_tubes#3) is where the rotation by 20 degrees puts it,
  // up to the clamp's give: relax holds an extensible cable's clamps through a compliant row,
  // and the relaxed cable's own end sits about 1 um off its clamp too.
  const Json& swung = j["cables"][2];
  ASSERT_EQ(swung["name"].get<std::string>(), "branched_tubes#3");
  EXPECT_EQ(swung["motion"]["moving_supports"].size(), 1u);
  EXPECT_TRUE(j["cables"][0]["motion"]["moving_supports"].empty());
  const Eigen::Vector3d drawn = Vec(swung["supports"][0]["position"]);
  const Eigen::Vector3d target = Eigen::AngleAxisd(20 * M_PI / 180, Eigen::Vector3d::UnitZ()) * drawn;
  const Json& end = swung["motion"]["poses"][10]["centreline"]["rows"].back();
  EXPECT_LT((Vec({end[1], end[2], end[3]}) - target).norm(), 1e-5);
  EXPECT_GT(largest_move, 0.01);  // the breakout and the other cables moved with it
}

}  // namespace
}  // namespace cablefit
