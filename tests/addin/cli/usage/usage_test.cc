// The command line itself: version, help, unknown commands and malformed options each get one
// clear answer and the exit code of cli-v1 (0 done, 2 usage error).
#include <gtest/gtest.h>

#include <string>

#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::Q;
using testing::RunCablefit;

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Usage, VersionPrintsTheNameAndVersion) {
  const auto run = RunCablefit("--version");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out.rfind("cablefit ", 0), 0u) << run.out;
  EXPECT_TRUE(run.err.empty()) << run.err;
}

TEST(Usage, HelpAsACommandPrintsTheHelp) {
  const auto run = RunCablefit("help");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(Has(run.out, "Usage: cablefit")) << run.out;
  for (const char* command : {"diagnose", "relax", "simulate", "section", "bench"})
    EXPECT_TRUE(Has(run.out, command)) << command;
}

TEST(Usage, AnUnknownCommandIsNamedWithTheKnownOnes) {
  const auto run = RunCablefit("frobnicate --out x");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(Has(run.err, "cablefit: unknown command 'frobnicate'")) << run.err;
  EXPECT_TRUE(Has(run.err, "diagnose, relax")) << run.err;
}

TEST(Usage, AMalformedOptionPointsToItsCommandsHelp) {
  for (const std::string& command : {std::string("relax"), std::string("diagnose")}) {
    const auto run = RunCablefit(command + " some-input --out /nonexistent/x --jobs abc");
    EXPECT_EQ(run.exit_code, 2) << command;
    EXPECT_TRUE(Has(run.err, "--jobs: must be a whole number from 0 (one per core) to 1024, got 'abc'"))
        << run.err;
    EXPECT_TRUE(Has(run.err, "run 'cablefit " + command + " --help' for usage")) << run.err;
  }
}

TEST(Usage, HelpNamesTheProgramNotItsPath) {
  const auto run = RunCablefit("relax --help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_TRUE(Has(run.out, "Usage: cablefit relax")) << run.out;
  EXPECT_FALSE(Has(run.out, "{false}")) << run.out;
}

// A file given to the wrong command says what it is and where it belongs.
TEST(Usage, AFileForAnotherCommandSaysWhereItBelongs) {
  const auto src = testing::SourceDir();
  const std::string step = Q(src / "samples/harness/legacy_harness.step");
  const std::string case_dir = "tests/data/cases/public/sample-none/";
  const auto out = testing::FreshTempDir("usage_wrong_command");

  auto diagnose = RunCablefit("diagnose " + step + " --out " + Q(out / "d"));
  EXPECT_EQ(diagnose.exit_code, 2);
  EXPECT_TRUE(Has(diagnose.err, "it is a STEP file; CAD, KBL files and meshes go to 'cablefit relax'"))
      << diagnose.err;

  auto relax = RunCablefit("relax " + Q(src / (case_dir + "scan.ply")) + " " +
                           Q(src / (case_dir + "case.json")) + " --out " + Q(out / "r"));
  EXPECT_EQ(relax.exit_code, 2);
  EXPECT_TRUE(Has(relax.err, "is a PLY point cloud (no faces), not a mesh")) << relax.err;
  EXPECT_TRUE(Has(relax.err, "is a JSON file, not CAD or a mesh")) << relax.err;

  auto config = RunCablefit("relax " + step + " --config " + Q(src / (case_dir + "case.json")) +
                            " --out " + Q(out / "c"));
  EXPECT_EQ(config.exit_code, 2);
  EXPECT_TRUE(Has(config.err, "is a recording case (case.json), not a harness.json")) << config.err;
}

}  // namespace
}  // namespace cablefit
