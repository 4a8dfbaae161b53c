// Recordings that do not match their set-up. A recording listed from the last clamp to the first
// is reversed with a note; one out of the cable's reach (millimetres, shifted) is refused with
// one line naming it; one that no catalogue effect can explain (a two-clamp recording told it is
// a cantilever) is diagnosed as not explained, with low confidence and the test stated.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/json_util.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

/// sample-none with only its centreline, as `name` under `root`, the case passed through `edit`
/// and the centreline through `move`.
template <typename EditCase, typename EditLine>
void MakeCase(const fs::path& root, const std::string& name, EditCase edit, EditLine move) {
  const fs::path from = testing::PublicCasesDir() / "sample-none";
  const fs::path dir = root / name;
  fs::create_directories(dir);
  json::Json c = json::ReadJsonFile((from / "case.json").string());
  c["name"] = name;
  c["recordings"] = json::Json::array({{{"kind", "centerline"}, {"file", "centerline.csv"}}});
  edit(c);
  json::WriteJsonFile((dir / "case.json").string(), c);
  Polyline line = ReadCenterlineCsv((from / "centerline.csv").string());
  move(line);
  WriteCenterlineCsv((dir / "centerline.csv").string(), line);
}

json::Json Diagnosis(const fs::path& out, const std::string& name) {
  return json::ReadJsonFile((out / name / "diagnosis.json").string());
}

TEST(DiagnoseSetupMismatch, ReversedRefusedAndUnexplainedRecordings) {
  const fs::path root = testing::FreshTempDir("diagnose-mismatch");
  const fs::path in = root / "in", out = root / "out";
  auto same = [](auto&) {};
  MakeCase(in, "as-recorded", same, same);
  MakeCase(in, "cantilever", [](json::Json& c) { c["clamps"].erase(1); }, same);
  MakeCase(in, "reversed", same, [](Polyline& p) {
    const double end = p.s[p.size() - 1];
    p.points = p.points.rowwise().reverse().eval();
    p.s = (end - p.s.reverse().array()).matrix();
  });
  MakeCase(in, "millimetres", same, [](Polyline& p) { p.points *= 1000.0; });
  MakeCase(in, "shifted-1km", same, [](Polyline& p) { p.points.row(0).array() += 1000.0; });

  const auto run =
      testing::RunCablefit("diagnose '" + in.string() + "' --out '" + out.string() + "' --jobs 2");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  for (const char* refused : {"millimetres", "shifted-1km"}) {
    const std::string line = "cablefit: " + (in / refused / "centerline.csv").string() +
                             ": the recording does not fit its set-up";
    EXPECT_NE(run.err.find(line), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out / refused / "diagnosis.json"));
  }

  const json::Json control = Diagnosis(out, "as-recorded");
  EXPECT_TRUE(control["explained"].get<bool>()) << control.dump(1);
  EXPECT_EQ(control["effect"], "none");
  EXPECT_LE(control["adequacy"]["chi_square"].get<double>(),
            control["adequacy"]["limit_999"].get<double>());

  const json::Json reversed = Diagnosis(out, "reversed");
  EXPECT_TRUE(reversed["explained"].get<bool>()) << reversed.dump(1);
  EXPECT_EQ(reversed["effect"], "none");
  ASSERT_TRUE(reversed.contains("notes"));
  EXPECT_NE(reversed["notes"].dump().find("it was reversed"), std::string::npos);
  EXPECT_NEAR(reversed["fitted"]["max_deviation"].get<double>(),
              control["fitted"]["max_deviation"].get<double>(), 1e-4);

  const json::Json cantilever = Diagnosis(out, "cantilever");
  EXPECT_FALSE(cantilever["explained"].get<bool>()) << cantilever.dump(1);
  EXPECT_LE(cantilever["confidence"].get<double>(), 0.1);
  EXPECT_GT(cantilever["adequacy"]["chi_square"].get<double>(),
            cantilever["adequacy"]["limit_999"].get<double>());
  EXPECT_NE(cantilever["explanation"].get<std::string>().find("No effect of the catalogue"),
            std::string::npos);
}

// A force case whose nominal response is orders of magnitude from the recorded one (here a
// length of 1e300 m) is not a stiffness change: refused, naming the curve's file.
TEST(DiagnoseSetupMismatch, ForceCaseOffByOrdersOfMagnitudeIsRefused) {
  const fs::path root = testing::FreshTempDir("diagnose-force-mismatch");
  const fs::path from = testing::PublicCasesDir() / "sample-force-none";
  const fs::path dir = root / "in" / "long";
  fs::create_directories(dir);
  json::Json c = json::ReadJsonFile((from / "case.json").string());
  c["cable"]["length"] = 1e300;
  json::WriteJsonFile((dir / "case.json").string(), c);
  std::string curve;
  for (const auto& r : c["recordings"]) {
    curve = r["file"].get<std::string>();
    fs::copy_file(from / curve, dir / curve);
  }
  const auto run = testing::RunCablefit("diagnose '" + dir.string() + "' --out '" +
                                        (root / "out").string() + "'");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("cablefit: " + (dir / curve).string() + ": the recorded"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("orders of magnitude apart"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace cablefit
