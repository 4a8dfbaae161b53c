// The output folder of relax, simulate and diagnose: an input is never overwritten, an earlier
// run's output is never read as input, two cases never share an output folder, and option values
// that only look like numbers are refused. Each refusal is exit 2 with one line naming --out.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using testing::Q;
using testing::RunCablefit;

fs::path Sample(const std::string& name) { return testing::SourceDir() / "samples/harness" / name; }

std::string Bytes(const fs::path& p) { return testing::ReadTextFile(p); }

// A copy of the sample STL in a fresh folder, so that a wrong write would be seen.
fs::path InputFolder(const std::string& tag) {
  const fs::path dir = testing::FreshTempDir(tag);
  fs::copy_file(Sample("bent_tubes.stl"), dir / "bent_tubes.stl");
  return dir;
}

TEST(OutputFolder, RelaxRefusesToWriteOverItsInput) {
  const fs::path in = testing::FreshTempDir("out_over_input");
  fs::copy_file(Sample("legacy_harness.step"), in / "legacy_harness.step");
  const std::string before = Bytes(in / "legacy_harness.step");
  const auto run = RunCablefit("relax " + Q(in / "legacy_harness.step") + " --out " + Q(in));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("would replace the input"), std::string::npos) << run.err;
  EXPECT_EQ(Bytes(in / "legacy_harness.step"), before);
  EXPECT_FALSE(fs::exists(in / "legacy_harness.json"));  // refused before anything was written
}

TEST(OutputFolder, RelaxRefusesAnInputFolderAsOutput) {
  const fs::path in = InputFolder("out_is_input_folder");
  const auto run = RunCablefit("relax " + Q(in) + " --out " + Q(in));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("is the input"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(in / "report.html"));
}

TEST(OutputFolder, TheLongestInputNameStillGetsItsOutputs) {
  const fs::path in = testing::FreshTempDir("out_long_name");
  const std::string stem(250, 'a');  // 250 + ".stl" = 254 bytes, within the 255 allowed
  fs::copy_file(Sample("bent_tubes.stl"), in / (stem + ".stl"));
  const auto run = RunCablefit("relax " + Q(in / (stem + ".stl")) + " --out " + Q(in / "out"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const std::string cut = stem.substr(0, 150);
  for (const char* suffix : {".json", ".step", "-deviation.png"})
    EXPECT_TRUE(fs::exists(in / "out" / (cut + suffix))) << suffix << "\n" << run.err;
}

TEST(OutputFolder, AnOutputThatCannotBeWrittenIsNamedNotTheInput) {
  const fs::path in = InputFolder("out_unwritable");
  // The JSON's name is taken by a folder: the write fails on the output, not on the input.
  fs::create_directories(in / "out/bent_tubes.json/blocked");
  const auto run = RunCablefit("relax " + Q(in / "bent_tubes.stl") + " --out " + Q(in / "out") +
                               " --no-pictures");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("could not be written: " + (in / "out/bent_tubes.json").string()),
            std::string::npos)
      << run.err;
}

TEST(OutputFolder, EmptyOrFileOutIsAUsageError) {
  const fs::path in = InputFolder("out_empty");
  const auto empty = RunCablefit("relax " + Q(in / "bent_tubes.stl") + " --out ''");
  EXPECT_EQ(empty.exit_code, 2) << empty.err;
  EXPECT_NE(empty.err.find("--out"), std::string::npos) << empty.err;
  std::ofstream(in / "a_file") << "x";
  const auto file = RunCablefit("relax " + Q(in / "bent_tubes.stl") + " --out " + Q(in / "a_file"));
  EXPECT_EQ(file.exit_code, 2) << file.err;
  EXPECT_NE(file.err.find("not a folder"), std::string::npos) << file.err;
}

TEST(OutputFolder, SimulateRefusesToReplaceTheRecordedCentreline) {
  const fs::path dir = testing::FreshTempDir("simulate_over_recording");
  fs::copy(testing::PublicCasesDir() / "sample-none", dir / "case");
  const fs::path recorded = dir / "case/centerline.csv";
  ASSERT_TRUE(fs::exists(recorded));
  const std::string before = Bytes(recorded);
  const auto run = RunCablefit("simulate " + Q(dir / "case/case.json") + " --out " + Q(dir / "case"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("would replace the input"), std::string::npos) << run.err;
  EXPECT_EQ(Bytes(recorded), before);
}

TEST(OutputFolder, CasesWhoseNamesSanitiseAlikeGetTheirOwnFolders) {
  const fs::path dir = testing::FreshTempDir("diagnose_name_collision");
  // Force cases: fast, and enough to see where the outputs go.
  const fs::path source = testing::PublicCasesDir() / "sample-force-none";
  const char* names[] = {"left cable", "left_cable", "report.html"};
  for (int k = 0; k < 3; ++k) {
    const fs::path c = dir / "in" / ("c" + std::to_string(k));
    fs::create_directories(c.parent_path());
    fs::copy(source, c);
    std::string text = Bytes(c / "case.json");
    const auto at = text.find("\"name\"");
    ASSERT_NE(at, std::string::npos);
    const auto open = text.find('"', text.find(':', at));
    const auto close = text.find('"', open + 1);
    text.replace(open, close - open + 1, std::string("\"") + names[k] + "\"");
    std::ofstream(c / "case.json", std::ios::trunc) << text;
  }
  const auto run = RunCablefit("diagnose " + Q(dir / "in") + " --out " + Q(dir / "out"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "out/left_cable/diagnosis.json"));
  EXPECT_TRUE(fs::is_regular_file(dir / "out/left_cable-2/diagnosis.json"));
  EXPECT_TRUE(fs::is_regular_file(dir / "out/report.html-2/diagnosis.json"));
  EXPECT_TRUE(fs::is_regular_file(dir / "out/report.html"));  // the run summary, not a folder
}

TEST(OutputFolder, TimeoutMustBeAFiniteNumberOfSeconds) {
  const fs::path in = InputFolder("timeout_values");
  for (const char* bad : {"nan", "inf", "-1", "1e309", "5s"}) {
    const auto run = RunCablefit("relax " + Q(in / "bent_tubes.stl") + " --out " + Q(in / "out") +
                                 " --timeout " + bad);
    EXPECT_EQ(run.exit_code, 2) << bad << ": " << run.err;
    EXPECT_NE(run.err.find("--timeout"), std::string::npos) << bad << ": " << run.err;
  }
  EXPECT_FALSE(fs::exists(in / "out"));
}

TEST(OutputFolder, UnwritableStandardOutputIsAFailure) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path section = testing::SourceDir() / "samples/materials/examples/conduit-loose.json";
  // RunCablefit redirects stdout itself, so the shell line is written here.
  const fs::path err = testing::FreshTempDir("stdout_full") / "err.txt";
  const int status = std::system((Q(testing::CablefitBinary()) + " section " + Q(section) +
                                  " > /dev/full 2> " + Q(err)).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_NE(Bytes(err).find("standard output"), std::string::npos) << Bytes(err);
}

// simulate runs in the start-up executable, which registers only some commands: asking it
// about a command it does not have once aborted the process here.
TEST(OutputFolder, UnwritableStandardOutputOfSimulateIsAFailureNotACrash) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path dir = testing::FreshTempDir("simulate_stdout_full");
  const fs::path err = dir / "err.txt";
  const std::string case_dir = (testing::SourceDir() / "tests/data/cases/public/sample-none").string();
  const int status = std::system((Q(testing::CablefitBinary()) + " simulate " + Q(case_dir) +
                                  " --out " + Q(dir / "out") + " > /dev/full 2> " + Q(err)).c_str());
  ASSERT_TRUE(WIFEXITED(status)) << Bytes(err);
  EXPECT_EQ(WEXITSTATUS(status), 1) << Bytes(err);
  EXPECT_NE(Bytes(err).find("standard output"), std::string::npos) << Bytes(err);
}

}  // namespace
}  // namespace cablefit
