// `cablefit` starts without the CAD, mesh, scan and 3-D rendering libraries: simulate, section and
// diagnose run in it, every other command in cablefit-full, with the same results either way;
// OSMesa is opened by the first 3-D picture, in either executable.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using testing::Q;

std::string Output(const std::string& command) {
  std::string text;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return text;
  std::array<char, 4096> buf;
  while (const size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) text.append(buf.data(), n);
  ::pclose(pipe);
  return text;
}

std::string Slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Startup, TheCommandUsersRunLoadsNoCadMeshOrRenderingLibrary) {
  const std::string needed = Output("ldd " + Q(testing::CablefitBinary()) + " 2>&1");
  ASSERT_NE(needed.find("libc.so"), std::string::npos) << needed;
  // FreeType too: loaded for the first label of a picture (formats/render freetype_api).
  for (const char* heavy : {"libTK", "assimp", "OSMesa", "LLVM", "xml2", "gmp", "GL", "freetype"})
    EXPECT_EQ(needed.find(heavy), std::string::npos) << heavy << " in\n" << needed;
  // The full executable has the CAD libraries: the split is what keeps them out, not a lighter
  // build. Neither links OSMesa (and with it LLVM): it is loaded for the first 3-D picture.
  const fs::path full = fs::path(testing::CablefitBinary()).parent_path() / "cablefit-full";
  const std::string full_needed = Output("ldd " + Q(full) + " 2>&1");
  EXPECT_NE(full_needed.find("libTK"), std::string::npos);
  EXPECT_EQ(full_needed.find("OSMesa"), std::string::npos) << full_needed;
}

TEST(Startup, DiagnoseGivesTheSameResultInEitherExecutable) {
  const auto out = testing::FreshTempDir("startup_diagnose");
  const fs::path cases = testing::SourceDir() / "tests/data/cases/public";
  const std::string inputs =
      Q(cases / "sample-force-stiffness") + " " + Q(cases / "sample-support_contact");
  const auto light = testing::RunCablefit("diagnose " + inputs + " --out " + Q(out / "light"));
  ASSERT_EQ(light.exit_code, 0) << light.err;
  const fs::path full = fs::path(testing::CablefitBinary()).parent_path() / "cablefit-full";
  ASSERT_EQ(std::system((Q(full) + " diagnose " + inputs + " --quiet --out " + Q(out / "full") +
                         " > /dev/null").c_str()),
            0);
  for (const char* file : {"sample-force-stiffness/diagnosis.json",
                           "sample-support_contact/fitted.csv",
                           "sample-support_contact/deviation-views.png",
                           "sample-force-stiffness/force-curve.png"}) {
    // The provenance (command line, date) differs by design; everything before it may not.
    auto result = [](const std::string& text) { return text.substr(0, text.find("\"provenance\"")); };
    const std::string a = result(Slurp(out / "light" / file));
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, result(Slurp(out / "full" / file))) << file;
  }
}

TEST(Startup, SimulateGivesTheSameResultInEitherExecutable) {
  const auto out = testing::FreshTempDir("startup_simulate");
  const fs::path c = testing::SourceDir() / "tests/data/cases/public/sample-none";
  const auto light = testing::RunCablefit("simulate " + Q(c) + " --out " + Q(out / "light"));
  ASSERT_EQ(light.exit_code, 0) << light.err;
  const fs::path full = fs::path(testing::CablefitBinary()).parent_path() / "cablefit-full";
  ASSERT_EQ(std::system((Q(full) + " simulate " + Q(c) + " --out " + Q(out / "full") +
                         " > /dev/null").c_str()),
            0);
  EXPECT_EQ(Slurp(out / "light" / "centerline.csv"), Slurp(out / "full" / "centerline.csv"));
  // And a command the start-up executable hands on still runs (and exits) as before.
  const auto relax = testing::RunCablefit("relax " + Q(out / "missing.step") + " --out " +
                                          Q(out / "r"));
  EXPECT_EQ(relax.exit_code, 2) << relax.err;
  EXPECT_NE(relax.err.find("missing.step"), std::string::npos) << relax.err;
}

TEST(Startup, BenchTimesTheDiagnosisOfEveryCaseUnderAFolder) {
  const fs::path cases = testing::SourceDir() / "tests/data/cases/public";
  const auto run = testing::RunCablefit("bench --diagnose " + Q(cases / "sample-force-none") + " " +
                                        "--repeat 1");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("diagnose_sample-force-none: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(" s (force, none)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("diagnose_force_worst: "), std::string::npos) << run.out;
  // A shape case also gives the split of its time and the fits' work.
  const auto shape = testing::RunCablefit("bench --diagnose " + Q(cases / "sample-support_contact"));
  ASSERT_EQ(shape.exit_code, 0) << shape.err;
  EXPECT_NE(shape.out.find(" s (shape, support_contact)"), std::string::npos) << shape.out;
  for (const char* part : {"observation ", "nominal ", "forward solves", "LM iterations",
                           "final solves ", "pictures and report "})
    EXPECT_NE(shape.out.find(part), std::string::npos) << part << "\n" << shape.out;
  const auto none = testing::RunCablefit("bench --diagnose " + Q(cases / "no-such-folder"));
  EXPECT_EQ(none.exit_code, 2) << none.err;
}

}  // namespace
}  // namespace cablefit
