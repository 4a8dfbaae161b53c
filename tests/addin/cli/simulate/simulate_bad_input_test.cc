// `cablefit simulate` on bad input: one clear line naming the file and the problem, exit 2,
// no crash, no output left behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

std::string GoodCase(double length, double ei, const std::string& extra_clamp_1 = "") {
  return std::string(R"({"format": "cable-recording/1", "name": "bad",
    "cable": {"length": )") + std::to_string(length) + R"(, "diameter": 0.006,
      "bending_stiffness": )" + std::to_string(ei) + R"(, "torsional_stiffness": 0.009,
      "linear_density": 0.05},
    "gravity": [0, 0, -9.81],
    "clamps": [
      {"s": 0.0, "position": [0, 0, 0], "tangent": [1, 0, 0], "normal": [0, 0, 1]},
      {"s": )" + std::to_string(length) + R"(, "position": [0.45, 0.1, 0.0], "tangent": [1, 0, 0],
       "normal": [0, 0, 1])" + extra_clamp_1 + R"(}],
    "recordings": [{"kind": "centerline", "file": "c.csv"}]})";
}

struct Bad {
  std::string name;
  std::string json;       // case.json text; empty = no file written
  std::string expected;   // substring of the error line
};

TEST(SimulateBadInputTest, OneLineErrorExitTwo) {
  const std::vector<Bad> cases = {
      {"too-short", GoodCase(0.40, 0.012), "apart but only"},
      {"zero-stiffness", GoodCase(0.6, 0.0), "stiffness"},
      {"negative-stiffness", GoodCase(0.6, -1.0), "stiffness"},
      {"nan", R"({"format": "cable-recording/1", "name": "x", "cable": {"length": "NaN"}})", "length"},
      {"malformed", "{\"format\": \"cable-recording/1\", ", "case.json"},
      {"missing", "", "case.json"},
  };
  for (const Bad& b : cases) {
    const fs::path dir = testing::FreshTempDir(b.name);
    if (!b.json.empty()) {
      std::ofstream(dir / "case.json") << b.json;
      std::ofstream(dir / "c.csv") << "s,x,y,z\n0,0,0,0\n0.6,0.45,0.1,0\n";
    }
    const auto run = testing::RunCablefit("simulate '" + (dir / "case.json").string() + "' --out '" +
                                          (dir / "out").string() + "'");
    EXPECT_EQ(run.exit_code, 2) << b.name << ": " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << b.name << ": " << run.err;
    EXPECT_EQ(run.err.rfind("cablefit: ", 0), 0u) << b.name << ": " << run.err;
    EXPECT_NE(run.err.find(b.expected), std::string::npos) << b.name << ": " << run.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "centerline.csv")) << b.name;
  }
}

TEST(SimulateBadInputTest, MalformedInitialShape) {
  const fs::path dir = testing::FreshTempDir("initial");
  std::ofstream(dir / "case.json") << GoodCase(0.6, 0.012);
  std::ofstream(dir / "c.csv") << "s,x,y,z\n0,0,0,0\n0.6,0.45,0.1,0\n";
  std::ofstream(dir / "init.csv") << "s,x,y,z\n0,0,0,0\n0.3,nan,0,0\n";
  const auto run = testing::RunCablefit("simulate '" + (dir / "case.json").string() + "' --out '" +
                                        (dir / "out").string() + "' --initial '" +
                                        (dir / "init.csv").string() + "'");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("init.csv"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

// A force case has no single shape to solve: simulate says so and where it belongs, writes
// nothing and exits 2 (it once printed "0 Newton iterations ... UNSTABLE" and exited 0).
TEST(SimulateBadInputTest, AForceCaseIsSentToDiagnose) {
  const fs::path out = testing::FreshTempDir("simulate-force") / "out";
  const fs::path force = testing::SourceDir() / "samples/cases/sample-force-hysteresis";
  const testing::CliRun run =
      testing::RunCablefit("simulate '" + force.string() + "' --out '" + out.string() + "'");
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("is a force case"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("'cablefit diagnose'"), std::string::npos) << run.err;
  EXPECT_EQ(run.out.find("Newton"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out / "solution.json"));
}

}  // namespace
}  // namespace cablefit
