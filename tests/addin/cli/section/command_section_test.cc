// `cablefit section` end to end, in-process: library wires, result JSON, --out, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <vector>

#include "cablefit/cli/commands.h"
#include "test_support.h"

namespace cablefit {
namespace {

constexpr double kPi = std::numbers::pi;

struct CliRun {
  int code = 0;
  std::string out, err;
};

CliRun RunCli(std::vector<std::string> args) {
  args.insert(args.begin(), "cablefit");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  CliRun r;
  r.code = addin::RunCommandLine(static_cast<int>(argv.size()), argv.data());
  r.out = ::testing::internal::GetCapturedStdout();
  r.err = ::testing::internal::GetCapturedStderr();
  return r;
}

std::string Write(const std::filesystem::path& dir, const std::string& name,
                  const std::string& text) {
  const auto p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

std::string Library() {
  return (testing::SourceDir() / "samples/materials/automotive.json").string();
}

TEST(SectionCommandTest, LibraryWireMatchesHandComputedCoaxialForms) {
  const auto dir = testing::FreshTempDir("section");
  const std::string file = Write(dir, "s.json", R"({"library": ")" + Library() + R"(",
      "components": [{"name": "w", "wire": "FLRY-B 1", "position": [0.01, 0]}],
      "torsion": {"finest_cells": 128}})");
  const std::string out_file = (dir / "sub" / "r.json").string();
  const CliRun r = RunCli({"section", file, "--out", out_file});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(out_file)), j);
  // Hand computation from the library entry (free-slip conductor).
  const auto lib = nlohmann::json::parse(std::ifstream(Library()));
  const auto& w = lib["wires"]["FLRY-B 1"];
  const auto& cu = lib["materials"]["copper"];
  const auto& pvc = lib["materials"]["PVC-insulation"];
  const double dc = w["conductor_diameter"], od = w["outer_diameter"], d = w["strand_diameter"];
  const double n = w["strands"];
  const double e_cond = double(cu["E"]) * n * std::pow(d / dc, 4);
  const double rc = dc / 2, ro = od / 2;
  const double eq4 = 0.25 * kPi * (e_cond * std::pow(rc, 4) +
                                   double(pvc["E"]) * (std::pow(ro, 4) - std::pow(rc, 4)));
  EXPECT_NEAR(j["coaxial"]["bending_stiffness_eq4"].get<double>() / eq4, 1.0, 1e-12);
  EXPECT_NEAR(j["material"]["bending_stiffness"].get<double>() / eq4, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(j["material"]["bending_ratio"].get<double>(), 1.0);
  const double mass = double(cu["density"]) * n * kPi * d * d / 4 +
                      double(pvc["density"]) * kPi * (ro * ro - rc * rc);
  EXPECT_NEAR(j["linear_density"].get<double>() / mass, 1.0, 1e-12);
  EXPECT_NEAR(j["material"]["diameter"].get<double>(), od, 1e-12);
  const double eq9 = j["coaxial"]["torsional_stiffness_eq9"];
  EXPECT_LT(std::abs(j["torsion"]["stiffness"].get<double>() / eq9 - 1.0), 0.005);
  EXPECT_EQ(j["torsion"]["grids"].size(), 3u);
  EXPECT_FALSE(j["notes"].empty());
}

TEST(SectionCommandTest, TapeWrapsTheBundleAndEveryLibraryWireLoads) {
  const auto dir = testing::FreshTempDir("section");
  const auto lib = nlohmann::json::parse(std::ifstream(Library()));
  for (auto it = lib["wires"].begin(); it != lib["wires"].end(); ++it) {
    const double od = it.value()["outer_diameter"];
    const std::string pos = std::to_string(od / 2);
    const std::string file = Write(dir, "s.json", R"({"library": ")" + Library() + R"(",
        "components": [{"wire": ")" + it.key() + R"(", "position": [)" + pos + R"(, 0]},
                       {"wire": ")" + it.key() + R"(", "position": [-)" + pos + R"(, 0]}],
        "layers": [{"name": "tape", "layer": "PVC-tape-0.13"}],
        "torsion": {"finest_cells": 64, "levels": 2}})");
    const CliRun r = RunCli({"section", file});
    ASSERT_EQ(r.code, 0) << it.key() << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    // Side by side along x: stiff axis is y (90 degrees); the tape adds 2 x 0.13 mm.
    EXPECT_NEAR(j["bending"]["principal_angle_deg"].get<double>(), 90.0, 1e-6) << it.key();
    EXPECT_NEAR(j["outer_diameter"].get<double>(), 2 * od + 2 * 0.13e-3, 1e-6 * od) << it.key();
    EXPECT_GT(j["bending"]["max"].get<double>(), j["bending"]["min"].get<double>());
  }
}

struct BadCase {
  const char* text;
  const char* problem;
};

TEST(SectionCommandTest, BadInputIsOneLineNamingFileExit2) {
  const auto dir = testing::FreshTempDir("section");
  const std::string disc = R"({"E": 1e9, "nu": 0.3, "density": 1000})";
  const std::vector<BadCase> cases = {
      {R"({"components": [{"name": "a", "position": [0, 0], "outer_radius": 1e-3, "material": M},
                          {"name": "b", "position": [1e-3, 0], "outer_radius": 1e-3, "material": M}]})",
       "part 'a' and part 'b' overlap"},
      {R"({"components": [{"position": [0, 0], "outer_radius": 1e-3,
                           "material": {"E": 0, "nu": 0.3, "density": 1}}]})",
       "components[0].material.E"},
      {R"({"components": [{"position": [0, 0], "outer_radius": -1e-3, "material": M}]})",
       "outer_radius"},
      {R"({"components": [{"position": [0, 0], "material": M}]})", "outer_radius"},
      {R"({"components": [{"outer_radius": 1e-3, "material": M}]})", "position"},
      {R"({"components": [{"position": [0, "NaN"], "outer_radius": 1e-3, "material": M}]})",
       "position[1]"},
      {R"({"components": [{"position": [0, 0], "outer_radius": 1e-3, "material": "steel"}]})",
       "unknown material 'steel'"},
      {R"({"components": [{"position": [0, 0], "outer_raduis": 1e-3, "material": M}]})",
       "outer_raduis"},
      {R"({"components": [{"position": [0, 0], "outer_radius": 1e-3,
                           "material": {"E": 1e9, "G": 1e9, "nu": 0.3, "density": 1}}]})",
       "exactly one of G or nu"},
      {R"({"components": [{"position": [0, 0], "outer_radius": 1e-3, "material": M}],
           "torsion": {"levels": 9}})",
       "levels"},
      {R"({"components": [)", "parse"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    std::string text = cases[i].text;
    for (size_t p; (p = text.find(" M}")) != std::string::npos;) text.replace(p + 1, 1, disc);
    for (size_t p; (p = text.find(" M,")) != std::string::npos;) text.replace(p + 1, 1, disc);
    const std::string file = Write(dir, "bad" + std::to_string(i) + ".json", text);
    const CliRun r = RunCli({"section", file});
    EXPECT_EQ(r.code, 2) << text;
    EXPECT_EQ(r.err.rfind("cablefit: " + file + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(cases[i].problem), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

// --format text: the figures with their units for a person; the JSON (stdout when piped, as
// cli-v1 says, and --out) is unchanged and carries the provenance.
TEST(SectionCommandTest, TextFormatSummarisesWithUnitsAndJsonStaysTheDefaultWhenPiped) {
  const auto dir = testing::FreshTempDir("section_text");
  const std::string file = Write(dir, "s.json", R"({"library": ")" + Library() + R"(",
      "components": [{"name": "w", "wire": "FLRY-B 1", "position": [0, 0]}],
      "torsion": {"finest_cells": 64}})");
  const std::string out_file = (dir / "r.json").string();
  const CliRun text = RunCli({"section", file, "--format", "text", "--out", out_file});
  ASSERT_EQ(text.code, 0) << text.err;
  const auto j = nlohmann::json::parse(std::ifstream(out_file));
  for (const char* unit : {" mm\n", " kg/m\n", " N m^2", " mm^2\n"})
    EXPECT_NE(text.out.find(unit), std::string::npos) << unit << "\n" << text.out;
  EXPECT_NE(text.out.find("all figures as JSON in " + out_file), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find('{'), std::string::npos) << text.out;
  EXPECT_EQ(j.at("provenance").at("inputs")[0].at("path"), file);
  // Captured (not a terminal): JSON, as before.
  const CliRun piped = RunCli({"section", file});
  ASSERT_EQ(piped.code, 0) << piped.err;
  EXPECT_TRUE(nlohmann::json::parse(piped.out).contains("provenance"));
  EXPECT_EQ(RunCli({"section", file, "--format", "yaml"}).code, 2);
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

// An output never replaces an input: --out naming SECTION.json (directly, through another path,
// or as a hard link) or the material library it names is refused with exit 2, and the file is
// left as it was.
TEST(SectionCommandTest, OutThatIsAnInputIsRefusedAndTheInputKept) {
  const auto dir = testing::FreshTempDir("section_out_input");
  const std::filesystem::path lib = dir / "lib.json";
  std::filesystem::copy_file(Library(), lib);
  const std::string text = R"({"library": ")" + lib.string() + R"(",
      "components": [{"name": "w", "wire": "FLRY-B 1", "position": [0, 0]}],
      "torsion": {"finest_cells": 32, "levels": 2}})";
  const std::string file = Write(dir, "s.json", text);
  std::filesystem::create_directory(dir / "sub");
  std::filesystem::create_hard_link(file, dir / "sub" / "link.json");
  const std::string lib_text = testing::ReadTextFile(lib);
  for (const std::string& out : {file, (dir / "sub" / ".." / "s.json").string(),
                                 (dir / "sub" / "link.json").string(), lib.string()}) {
    const CliRun r = RunCli({"section", file, "--out", out});
    EXPECT_EQ(r.code, 2) << out;
    EXPECT_EQ(r.err.rfind("cablefit: --out " + out + ": is the input ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(testing::ReadTextFile(file), text);
    EXPECT_EQ(testing::ReadTextFile(lib), lib_text);
  }
  const CliRun folder = RunCli({"section", file, "--out", (dir / "sub").string()});
  EXPECT_EQ(folder.code, 2);
  EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
  const CliRun empty = RunCli({"section", file, "--out", ""});
  EXPECT_EQ(empty.code, 2);
  EXPECT_NE(empty.err.find("empty"), std::string::npos) << empty.err;
  // A new file beside the input is fine.
  const CliRun ok = RunCli({"section", file, "--out", (dir / "r.json").string()});
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "r.json"));
}

}  // namespace
}  // namespace cablefit
