// `cablefit relax --config` with solids that move (harness.json motion.solids), on the door-hinge
// sample: the door panel listed as moving carries the cable end held in it, exactly as naming
// that support does; a loudspeaker lifted towards a cable nothing moves comes closer by exactly
// the lift (the distance to its flat top, a closed form); a pattern naming no solid is a problem
// line.
#include <gtest/gtest.h>

#include <Eigen/Core>
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

fs::path Sample(const std::string& name) { return testing::SourceDir() / "samples/harness" / name; }

Json Relax(const fs::path& dir, const std::string& name, const std::function<void(Json*)>& edit) {
  Json config = json::ReadJsonFile(Sample("door_hinge.json").string());
  edit(&config);
  const fs::path path = dir / (name + ".json");
  std::ofstream(path) << config.dump(1);
  const auto run = testing::RunCablefit("relax " + Q(Sample("door_hinge.stl")) + " --config " +
                                        Q(path) + " --out " + Q(dir / name) + " --no-pictures");
  EXPECT_EQ(run.exit_code, 0) << run.err << run.out;
  return json::ReadJsonFile((dir / name / "door_hinge.json").string());
}

TEST(RelaxMotionSolidsCli, AMovingDoorCarriesTheCableEndHeldInIt) {
  const fs::path dir = testing::FreshTempDir("relax_motion_solids_door");
  const Json named = Relax(dir, "named", [](Json* c) { (*c)["motion"]["solids"] = Json::array(); });
  const Json carried = Relax(dir, "carried", [](Json* c) {
    (*c)["motion"].erase("moving");
    (*c)["motion"]["solids"] = {"*part3"};  // the door panel
  });
  EXPECT_EQ(carried["motion"]["moving_solids"], Json({"door_hinge-part3"}));
  EXPECT_TRUE(carried["motion"]["problems"].empty()) << carried["motion"]["problems"].dump();
  const Json& a = named["cables"][0]["motion"];
  const Json& b = carried["cables"][0]["motion"];
  EXPECT_EQ(b["moving_supports"], Json({1}));  // the end clamp, held in the door
  ASSERT_EQ(a["poses"].size(), 31u);
  ASSERT_EQ(b["poses"].size(), 31u);
  for (size_t k = 0; k < 31; ++k)
    EXPECT_EQ(a["poses"][k]["centreline"], b["poses"][k]["centreline"]) << k;
}

TEST(RelaxMotionSolidsCli, ALiftedSolidComesCloserByExactlyTheLift) {
  const fs::path dir = testing::FreshTempDir("relax_motion_solids_lift");
  const Json j = Relax(dir, "lift", [](Json* c) {
    (*c)["motion"] = {{"name", "speaker lift"},
                      {"translation", {{"direction", {0, 0, 1}}, {"distances", {0, 0.05}}}},
                      {"steps", 5},
                      {"return", false},
                      {"solids", {"*part4", "no-such-part"}}};
  });
  ASSERT_EQ(j["motion"]["problems"].size(), 1u);
  EXPECT_NE(j["motion"]["problems"][0].get<std::string>().find("no-such-part"), std::string::npos);
  const Json& m = j["cables"][0]["motion"];
  EXPECT_TRUE(m["held_still"].get<bool>());
  ASSERT_EQ(m["poses"].size(), 6u);
  // The cable's lowest stretch hangs above the loudspeaker's flat top: the clearance is the
  // vertical gap, which the lift shrinks by its own amount.
  const double c0 = m["poses"][0]["clearance"]["clearance"].get<double>();
  EXPECT_GT(c0, 0.05);
  for (size_t k = 0; k < 6; ++k) {
    const Json& c = m["poses"][k]["clearance"];
    EXPECT_EQ(c["to"].get<std::string>(), "solid 'door_hinge-part4'");
    EXPECT_NEAR(c["clearance"].get<double>(), c0 - 0.01 * static_cast<double>(k), 1e-9) << k;
    EXPECT_EQ(m["poses"][k]["centreline"], m["poses"][0]["centreline"]) << k;
  }
  EXPECT_EQ(m["worst"]["min_clearance"]["pose"].get<int>(), 5);
}

TEST(RelaxMotionSolidsCli, ATrackedPointOnTheDoorRunsOnACircleAboutTheHinge) {
  const fs::path dir = testing::FreshTempDir("relax_motion_track");
  const Json j = Relax(dir, "track", [](Json* c) {
    // The cable's end (an arc length past its end is taken as the end), held in the door.
    (*c)["motion"]["track"] = {{{"cable", "door_hinge#1"}, {"s", 10.0}},
                               {{"cable", "no-such-cable"}, {"s", 0.1}}};
  });
  const Json& motion = j["motion"];
  ASSERT_EQ(motion["tracks"].size(), 1u);
  ASSERT_EQ(motion["problems"].size(), 1u);
  EXPECT_NE(motion["problems"][0].get<std::string>().find("no-such-cable"), std::string::npos);
  const Json& t = motion["tracks"][0];
  ASSERT_EQ(t["points"].size(), 31u);
  // The door turns 75 degrees about the vertical axis through (0.30, -0.03) in 5-degree steps,
  // there and back: the end runs on a circle about it (up to the clamp's give, about 1 um).
  const Eigen::Vector2d axis(0.30, -0.03);
  const auto at = [&](size_t k) {
    const Json& p = t["points"][k];
    return Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  };
  const double r = (at(0).head<2>() - axis).norm();
  for (size_t k = 0; k < 31; ++k) {
    EXPECT_NEAR((at(k).head<2>() - axis).norm(), r, 1e-5) << k;
    EXPECT_NEAR(at(k).z(), at(0).z(), 1e-5) << k;
  }
  const double step = 5 * M_PI / 180;
  EXPECT_NEAR(t["excursion"]["distance"].get<double>(), 2 * r * std::sin(75 * M_PI / 360), 2e-5);
  EXPECT_EQ(t["excursion"]["pose"].get<int>(), 15);
  EXPECT_NEAR(t["travel"].get<double>(), 30 * 2 * r * std::sin(step / 2), 1e-4);
}

TEST(RelaxMotionSolidsCli, AListOfPosesReachesTheSameEquilibriaAsTheHingeSweep) {
  const fs::path dir = testing::FreshTempDir("relax_motion_poses");
  const Json hinge = Relax(dir, "hinge", [](Json*) {});
  const Json listed = Relax(dir, "listed", [](Json* c) {
    Json& m = (*c)["motion"];
    m.erase("rotation");
    m.erase("steps");
    m["poses"] = Json::array();
    for (double angle : {25.0, 50.0, 75.0})
      m["poses"].push_back(
          {{"rotation", {{"axis", {0, 0, 1}}, {"point", {0.30, -0.03, 0.0}}, {"angle", angle}}}});
  });
  EXPECT_EQ(listed["motion"]["kind"], "poses");
  EXPECT_EQ(listed["motion"]["parameter_unit"], "pose");
  const Json& a = hinge["cables"][0]["motion"]["poses"];  // 0, 5, ..., 75, ..., 0 degrees
  const Json& b = listed["cables"][0]["motion"]["poses"];  // listed poses 0, 1, 2, 3, 2, 1, 0
  ASSERT_EQ(b.size(), 7u);
  for (int k = 0; k < 7; ++k) {
    const int pose = k <= 3 ? k : 6 - k;
    EXPECT_EQ(b[k]["q"].get<double>(), pose);
    // Listed pose k is the hinge at 25 k degrees: the hinge sweep's pose 5 k.
    const Json& rows_a = a[static_cast<size_t>(5 * pose)]["centreline"]["rows"];
    const Json& rows_b = b[static_cast<size_t>(k)]["centreline"]["rows"];
    ASSERT_EQ(rows_a.size(), rows_b.size());
    double largest = 0.0;
    for (size_t i = 0; i < rows_a.size(); ++i)
      for (int c = 1; c <= 3; ++c)
        largest = std::max(largest, std::abs(rows_a[i][c].get<double>() - rows_b[i][c].get<double>()));
    EXPECT_LT(largest, 1e-8) << k;
  }
  EXPECT_LT(listed["cables"][0]["motion"]["back_to_start"].get<double>(), 1e-9);
}

}  // namespace
}  // namespace cablefit
