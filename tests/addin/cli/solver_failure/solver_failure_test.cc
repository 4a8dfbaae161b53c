// Solver failure is an answer, not a crash: set-ups without an equilibrium the solver can reach
// are reported in the outputs (simulate: converged=false in solution.json, exit 1), a failed
// case or cable does not stop a batch, and `--timeout` ends an item with "timed out after N s"
// while the others go on.
#include <gtest/gtest.h>

#include <algorithm>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

std::string Slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A two-clamp case. `taut` puts the clamps exactly one cable length apart with tangents across
// the line between them: only a straight cable reaches both positions, and it cannot have those
// end tangents — there is no equilibrium. Otherwise a 10 m cable that is almost limp (EI 1e-9)
// hangs between clamps 0.1 m apart facing each other: simulate's default start does not reach
// that equilibrium within its iterations; diagnose, from the recorded shape, does.
void WriteCase(const fs::path& dir, const std::string& name, bool taut) {
  fs::create_directories(dir);
  const double length = taut ? 0.6 : 10.0;
  std::ofstream(dir / "case.json")
      << R"({"format": "cable-recording/1", "name": ")" << name << R"(",
  "cable": {"length": )" << length << R"(, "diameter": 0.006, "bending_stiffness": )"
      << (taut ? "0.012" : "1e-9") << R"(, "torsional_stiffness": 0.009,
            "linear_density": 0.05},
  "gravity": [0, 0, -9.81],
  "clamps": [{"s": 0, "position": [0, 0, 0], "tangent": )"
      << (taut ? "[0, 1, 0]" : "[1, 0, 0]") << R"(, "normal": [0, 0, 1]},
             {"s": )" << length << R"(, "position": )" << (taut ? "[0.6, 0, 0]" : "[0.1, 0, 0]")
      << R"(, "tangent": )" << (taut ? "[0, 1, 0]" : "[-1, 0, 0]") << R"(, "normal": [0, 0, 1]}],
  "recordings": [{"kind": "centerline", "file": "c.csv"}]})";
  std::ofstream(dir / "c.csv") << "x,y,z\n0,0,0\n0.02,0,-0.01\n0.04,0,-0.02\n0.06,0,-0.02\n"
                                  "0.08,0,-0.01\n0.1,0,0\n";
}

void ExpectNoTempFiles(const fs::path& out) {
  std::error_code ec;
  if (!fs::exists(out, ec)) return;
  for (const auto& e : fs::recursive_directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(SolverFailure, SimulateWritesTheUnconvergedAnswerAndExitsOne) {
  const fs::path dir = testing::FreshTempDir("simulate");
  for (const bool taut : {true, false}) {
    const fs::path c = dir / (taut ? "taut" : "limp");
    WriteCase(c, taut ? "taut" : "limp", taut);
    const auto run = testing::RunCablefit("simulate '" + c.string() + "' --out '" +
                                          (c / "out").string() + "'");
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find((c / "case.json").string() + ": solver did not converge"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.out.find("NOT CONVERGED"), std::string::npos) << run.out;
    // The answer is in the outputs too, for scripts that read them instead of stderr.
    const std::string solution = Slurp(c / "out" / "solution.json");
    EXPECT_NE(solution.find("\"converged\": false"), std::string::npos) << solution;
    EXPECT_TRUE(fs::exists(c / "out" / "centerline.csv"));
    ExpectNoTempFiles(c / "out");
  }
}

TEST(SolverFailure, DiagnoseBatchGoesOnPastCasesWithoutEquilibrium) {
  const fs::path dir = testing::FreshTempDir("diagnose");
  WriteCase(dir / "cases" / "taut", "taut", true);
  WriteCase(dir / "cases" / "limp", "limp", false);  // creates dir / "cases"
  fs::copy(testing::SourceDir() / "samples" / "cases" / "sample-force-hysteresis",
           dir / "cases" / "force", fs::copy_options::recursive);
  const fs::path out = dir / "out";
  const auto run = testing::RunCablefit("diagnose '" + (dir / "cases").string() + "' --out '" +
                                        out.string() + "'");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find((dir / "cases" / "taut" / "case.json").string() + ": "), std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("could not be solved"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::exists(out / "sample-force-hysteresis" / "diagnosis.json"));
  EXPECT_FALSE(fs::exists(out / "taut"));
  // The limp cable has an equilibrium, and the continuation now snaps through to it: the 10 m
  // hang as a U between clamps 0.1 m apart, (10 - 0.1) / 2 m deep as a chain would.
  EXPECT_EQ(run.err.find((dir / "cases" / "limp" / "case.json").string() + ": "), std::string::npos)
      << run.err;
  std::ifstream nominal(out / "limp" / "nominal.csv");
  std::string line;
  std::getline(nominal, line);  // s,x,y,z
  double lowest = 0;
  while (std::getline(nominal, line)) lowest = std::min(lowest, std::stod(line.substr(line.rfind(',') + 1)));
  EXPECT_NEAR(lowest, -4.95, 0.06);
  EXPECT_TRUE(fs::exists(out / "report.html"));
  ExpectNoTempFiles(out);
}

TEST(SolverFailure, DiagnoseTimeoutEndsTheSlowCaseAndTheBatchGoesOn) {
  const fs::path dir = testing::FreshTempDir("diagnose-timeout");
  fs::create_directories(dir / "cases");
  for (const char* c : {"sample-two-effects", "sample-force-hysteresis"})
    fs::copy(testing::SourceDir() / "samples" / "cases" / c, dir / "cases" / c,
             fs::copy_options::recursive);
  const fs::path out = dir / "out";
  const auto t0 = std::chrono::steady_clock::now();
  // The two-effect shape case screens hundreds of pairs (seconds even on a fast machine; a
  // single-effect case can finish within half a second there); the force case needs no Newton
  // solve and is done well within the limit.
  const auto run = testing::RunCablefit("diagnose '" + (dir / "cases").string() + "' --out '" +
                                        out.string() + "' --timeout 0.5");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find((dir / "cases" / "sample-two-effects" / "case.json").string() +
                         ": timed out after 0.5 s"),
            std::string::npos)
      << run.err;
  EXPECT_TRUE(fs::exists(out / "sample-force-hysteresis" / "diagnosis.json"));
  EXPECT_FALSE(fs::exists(out / "sample-two-effects"));
  // Reading the PLY file is not interruptible (a second under ASan); extracting its centreline
  // and the fits after it are.
  EXPECT_LT(seconds, 30.0);
  ExpectNoTempFiles(out);
}

TEST(SolverFailure, RelaxTimeoutFailsEachCableAndStillWritesTheRun) {
  const fs::path dir = testing::FreshTempDir("relax-timeout");
  const fs::path out = dir / "out";
  // A limit no solve can meet, whatever the machine: with 1 ms a fast CI machine solved both
  // cables in time (the deadline is checked before every Newton iteration, so 1 ns always trips).
  const auto run = testing::RunCablefit(
      "relax '" + (testing::SourceDir() / "samples" / "harness" / "bent_tubes.stl").string() +
      "' --out '" + out.string() + "' --timeout 1e-9 --jobs 1");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("cable 'bent_tubes#1': timed out after 1e-09 s"), std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("cable 'bent_tubes#2': timed out after 1e-09 s"), std::string::npos)
      << run.err;
  // The input was read: its JSON (cables with their errors) and the run report are written.
  EXPECT_TRUE(fs::exists(out / "bent_tubes.json"));
  EXPECT_TRUE(fs::exists(out / "report.html"));
  ExpectNoTempFiles(out);
  // Each failed cable still says what it was: its drawn length and diameter (the two tubes are
  // 0.334 m of 10 mm and 0.279 m of 8 mm).
  const nlohmann::json j = nlohmann::json::parse(Slurp(out / "bent_tubes.json"));
  ASSERT_EQ(j.at("cables").size(), 2u);
  for (const nlohmann::json& c : j.at("cables")) {
    EXPECT_EQ(c.at("written_as"), "drawn (not relaxed)");
    EXPECT_GT(c.at("drawn_length").get<double>(), 0.27);
    EXPECT_LT(c.at("drawn_length").get<double>(), 0.34);
    EXPECT_GT(c.at("diameter").get<double>(), 0.007);
    EXPECT_LT(c.at("diameter").get<double>(), 0.011);
  }
}

TEST(SolverFailure, TimeoutMustNotBeNegative) {
  const auto run = testing::RunCablefit("diagnose nowhere --out nowhere --timeout -1");
  EXPECT_EQ(run.exit_code, 2) << run.err;
}

}  // namespace
}  // namespace cablefit
