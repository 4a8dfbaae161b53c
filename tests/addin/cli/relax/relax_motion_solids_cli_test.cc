// `cablefit relax --config` with solids that move (harness.json motion.solids), on the door-hinge
// sample: the door panel listed as moving carries the cable end held in it, exactly as naming
// that support does; a loudspeaker lifted towards a cable nothing moves comes closer by exactly
// the lift (the distance to its flat top, a closed form); a pattern naming no solid is a problem
// line.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace cablefit
