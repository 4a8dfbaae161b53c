// The helper executables the CAD reader's probe and the tube sweeps run in.
#include "crash_probe.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "test_support.h"

namespace cablefit {
namespace {

TEST(CrashProbe, TheHelperIsFoundInTheBuildTree) {
  const std::string helper = OcctChildPath();
  ASSERT_FALSE(helper.empty());
  EXPECT_EQ(std::filesystem::path(helper).filename(), "cablefit-occt-child");
  // It refuses a call it does not know, and one whose parent is not the caller.
  auto outcome = RunOcctChild({"frobnicate"}, 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 64);
  outcome = RunChildProcess(helper, {"1", "sweep", "3", "0.01", "4"}, 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 64);
  // The sweeps moved to cablefit-sweep-child: this helper no longer knows them.
  outcome = RunOcctChild({"sweeps", "3", "4"}, 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 64);
}

TEST(CrashProbe, TheSweepHelperIsFoundInTheBuildTreeAndKnowsOnlySweeps) {
  const std::string helper = HelperPath(kSweepHelper);
  ASSERT_FALSE(helper.empty());
  EXPECT_EQ(std::filesystem::path(helper).filename(), "cablefit-sweep-child");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"read", "x.step", "0.01", "0.01", "0.5", "5", "0.001"},
        std::vector<std::string>{"sweeps", "3"}}) {
    const auto outcome = RunHelper(kSweepHelper, args, 60.0);
    ASSERT_TRUE(outcome.has_value());
    EXPECT_EQ(outcome->exit_code, 64) << args.front();
  }
}

// A fuzzed IGES on which OpenCASCADE's shape healing runs for over ten minutes (see
// tests/data/hostile/README.md): the probe is killed at its limit and the file fails with a
// reason, instead of the run hanging.
TEST(CrashProbe, AFileThatKeepsShapeHealingBusyFailsAtTheLimit) {
  CadReadOptions options;
  options.probe_seconds = 3;
  options.probe_seconds_per_megabyte = 0;
  const std::string path = (testing::SourceDir() / "tests/data/hostile/healing_loop.igs").string();
  const auto start = std::chrono::steady_clock::now();
  try {
    ReadCadFile(path, options);
    FAIL() << "read a file that never finishes healing";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("healing_loop.igs"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("did not finish within 3 s"), std::string::npos)
        << e.what();
  }
  // Killed at the limit, not left to finish (an upper bound only a hang would break).
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60);
}

TEST(CrashProbe, TheLimitGrowsWithTheFileSize) {
  CadReadOptions options;
  EXPECT_DOUBLE_EQ(options.ProbeSecondsFor(0), 30.0);
  EXPECT_DOUBLE_EQ(options.ProbeSecondsFor(2'000'000), 90.0);
  options.probe_seconds_per_megabyte = -1;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("probe_seconds_per_megabyte"), std::string::npos);
}

}  // namespace
}  // namespace cablefit
