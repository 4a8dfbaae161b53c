// `cablefit relax` with cables joined by a junction declared in harness.json: two collinear
// cables spliced end to end sag like the one beam they form; a junction naming an unknown cable
// is a one-line error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/json_util.h"
#include "cli_runner.h"
#include "relax_test_util.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using json::Json;
using testing::CableNamed;
using testing::Q;
using testing::RunCablefit;

Polyline Line(const Vec3& a, const Vec3& b) {
  Polyline p;
  p.points.resize(3, 2);
  p.points.col(0) = a;
  p.points.col(1) = b;
  return p;
}

// Two straight cables drawn end to end along x: "left" 0.2 m, "right" 0.3 m, diameter 5 mm.
fs::path WriteSplicedPair(const fs::path& path) {
  HarnessDrawing drawing;
  std::vector<RelaxedCable> out;
  const Vec3 a(0.1, 0.2, 0.05), m(0.3, 0.2, 0.05), b(0.6, 0.2, 0.05);
  int k = 0;
  for (const auto& [name, line] : {std::pair{"left", Line(a, m)}, std::pair{"right", Line(m, b)}}) {
    DrawnCable c;
    c.name = name;
    c.diameter = 0.005;
    c.centreline = line;
    drawing.cables.push_back(c);
    out.push_back(RelaxedCable{k++, line, 0.005});
  }
  WriteRelaxedStep(path.string(), drawing, out);
  return path;
}

// The clamped-clamped beam of relax_cli_test (far end sliding axially), cut in two and spliced
// rigidly: w_max = q L^4 / (384 EI) at mid-span, which lies on the right cable.
TEST(RelaxNetwork, DeclaredSpliceSagsLikeTheWholeBeam) {
  const double length = 0.5, ei = 0.05, q = 0.05 * 9.81;
  const double expected = q * std::pow(length, 4) / (384 * ei);
  const fs::path dir = testing::FreshTempDir("relax_splice");
  WriteSplicedPair(dir / "pair.step");
  std::ofstream(dir / "harness.json") << R"({"gravity": [0, 0, -9.81],
    "default": {"material": {"bending_stiffness": 0.05, "torsional_stiffness": 0.04,
                             "linear_density": 0.05}},
    "cables": {"right": {"end": {"kind": "clamp", "sliding": true}}},
    "junctions": [{"name": "splice", "ends": [{"cable": "left", "end": "end"},
                                             {"cable": "right", "end": "start"}]}]})";
  const auto run = RunCablefit("relax " + Q(dir / "pair.step") + " --out " + Q(dir / "out") +
                               " --config " + Q(dir / "harness.json") + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const Json j = json::ReadJsonFile((dir / "out/pair.json").string());
  const Json& right = CableNamed(j, "right");
  const Json& left = CableNamed(j, "left");
  EXPECT_TRUE(right.at("solver").at("converged").get<bool>());
  EXPECT_EQ(right.at("supports").size(), 1u);  // the spliced end has no support
  const double sag = std::max(right.at("deviation").at("max").get<double>(),
                              left.at("deviation").at("max").get<double>());
  std::printf("spliced beam sag %.6e m, closed form %.6e m (rel. %.2e)\n", sag, expected,
              sag / expected - 1);
  EXPECT_NEAR(sag, expected, 0.01 * expected);
  // Mid-span (0.25 m from the left clamp) is 0.05 m into the right cable.
  EXPECT_NEAR(right.at("deviation").at("max_at").at("s").get<double>(), 0.05, 0.02 * length);
  ASSERT_EQ(j.at("networks").size(), 1u);
  const Json& splice = j.at("networks")[0].at("junctions")[0];
  EXPECT_EQ(splice.at("name"), "splice");
  EXPECT_TRUE(splice.at("declared").get<bool>());
  EXPECT_EQ(splice.at("branch_loads").size(), 2u);
}

TEST(RelaxNetwork, JunctionNamingAnUnknownCableIsAnError) {
  const fs::path dir = testing::FreshTempDir("relax_bad_junction");
  WriteSplicedPair(dir / "pair.step");
  std::ofstream(dir / "harness.json") << R"({"junctions": [{"name": "j", "ends": [
      {"cable": "left", "end": "end"}, {"cable": "nowhere", "end": "start"}]}]})";
  const auto run = RunCablefit("relax " + Q(dir / "pair.step") + " --out " + Q(dir / "out") +
                               " --config " + Q(dir / "harness.json") + " --no-pictures");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("junction 'j' names cable 'nowhere'"), std::string::npos) << run.err;
  std::ofstream(dir / "one.json") << R"({"junctions": [{"ends": [{"cable": "left", "end": "end"}]}]})";
  const auto one = RunCablefit("relax " + Q(dir / "pair.step") + " --out " + Q(dir / "out2") +
                               " --config " + Q(dir / "one.json") + " --no-pictures");
  EXPECT_EQ(one.exit_code, 2) << one.err;
  EXPECT_NE(one.err.find("two or more cable ends"), std::string::npos) << one.err;
}

// A straight cable (clamped, far clamp sliding axially) over a 2 mm wide block under its
// mid-span whose top lies half the free sag below it (data/beam_on_block.step, made by
// data/beam_on_block.py). Linear beam theory: a mid-span point force R lifts the mid-span by
// R L^3 / (192 EI), so the block carries R = 192 EI (w_free - w_block) / L^3 and the cable's
// deepest point is w_block.
TEST(RelaxNetwork, CableSaggingOntoABlockCarriesTheBeamTheoryForce) {
  const double length = 0.5, ei = 0.05, q = 0.05 * 9.81, d = 0.005;
  const double w_free = q * std::pow(length, 4) / (384 * ei), w_block = 0.5 * w_free;
  const double expected = 192 * ei * (w_free - w_block) / std::pow(length, 3);
  const fs::path dir = testing::FreshTempDir("relax_block");
  std::ofstream(dir / "harness.json") << R"({"gravity": [0, 0, -9.81],
    "default": {"material": {"bending_stiffness": 0.05, "torsional_stiffness": 0.04,
                             "linear_density": 0.05},
                "end": {"kind": "clamp", "sliding": true}}})";
  const fs::path step = testing::SourceDir() / "tests/addin/cli/relax/data/beam_on_block.step";
  const auto run = RunCablefit("relax " + Q(step) + " --out " + Q(dir / "out") + " --config " +
                               Q(dir / "harness.json") + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json file = json::ReadJsonFile((dir / "out/beam_on_block.json").string());
  ASSERT_EQ(file.at("networks").size(), 1u);
  const Json& net = file.at("networks")[0];
  EXPECT_TRUE(net.at("converged").get<bool>());
  EXPECT_LE(net.at("max_penetration").get<double>(), 0.01 * d);
  ASSERT_FALSE(net.at("contacts").empty());
  double total = 0.0;
  for (const Json& c : net.at("contacts")) {
    EXPECT_EQ(c.at("solid").get<std::string>(), "block");
    EXPECT_EQ(c.at("cable").get<std::string>(), "cable");
    EXPECT_GE(c.at("force")[2].get<double>(), 0.0);
    total += c.at("force")[2].get<double>();
  }
  const double sag = CableNamed(file, "cable").at("deviation").at("max").get<double>();
  std::printf("block: force %.6f N vs beam %.6f N, deepest %.4f mm vs %.4f mm\n", total, expected,
              sag * 1e3, w_block * 1e3);
  EXPECT_NEAR(total, expected, 0.01 * expected);
  EXPECT_NEAR(sag, w_block, 0.02 * w_block);
}

// A soft cable (EI 0.002 N m^2, 0.1 kg/m) clamped on a block's top and free past its edge
// (data/drape_over_edge.step, made by data/drape_over_edge.py): it drapes over the edge, and
// the clamp and the contacts carry exactly its weight. The 15 m version hangs from the edge
// with 5 mm elements, where the stretch between two nodes cuts the corner: said in a note.
Json RelaxDrape(const std::string& stem) {
  const fs::path dir = testing::FreshTempDir("relax_" + stem);
  std::ofstream(dir / "harness.json") << R"({"gravity": [0, 0, -9.81],
    "default": {"material": {"bending_stiffness": 0.002, "torsional_stiffness": 0.0015,
                             "linear_density": 0.1},
                "end": "free"}})";
  const fs::path step = testing::SourceDir() / ("tests/addin/cli/relax/data/" + stem + ".step");
  const auto run = RunCablefit("relax " + Q(step) + " --out " + Q(dir / "out") + " --config " +
                               Q(dir / "harness.json") + " --no-pictures");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return json::ReadJsonFile((dir / "out" / (stem + ".json")).string());
}

TEST(RelaxNetwork, CableDrapedOverAnEdgeBalancesItsWeight) {
  const Json file = RelaxDrape("drape_over_edge");
  ASSERT_EQ(file.at("networks").size(), 1u);
  const Json& net = file.at("networks")[0];
  EXPECT_TRUE(net.at("converged").get<bool>());
  EXPECT_LE(net.at("max_penetration").get<double>(), 0.01 * 0.005);
  ASSERT_FALSE(net.at("contacts").empty());
  const Json& cable = CableNamed(file, "cable");
  Vec3 total = Vec3::Zero();
  for (const Json& sp : cable.at("supports"))
    for (int k = 0; k < 3; ++k) total[k] += sp.at("reaction").at("force")[k].get<double>();
  for (const Json& c : net.at("contacts")) {
    EXPECT_EQ(c.at("solid").get<std::string>(), "block");
    for (int k = 0; k < 3; ++k) total[k] += c.at("force")[k].get<double>();
  }
  const double weight = 0.5 * 0.1 * 9.81;
  EXPECT_NEAR(total.z(), weight, 1e-6 * weight);
  EXPECT_NEAR(total.x(), 0.0, 1e-6 * weight);
  // With 2.5 mm elements no stretch between nodes cuts the corner (the 15 m version's note).
  for (const Json& n : cable.at("notes"))
    EXPECT_EQ(n.get<std::string>().find("contact is held at nodes"), std::string::npos) << n;
}

TEST(RelaxNetwork, CuttingACornerBetweenNodesIsSaidInANote) {
  const Json file = RelaxDrape("drape_long");
  ASSERT_EQ(file.at("networks").size(), 1u);
  const Json& net = file.at("networks")[0];
  EXPECT_TRUE(net.at("converged").get<bool>());
  ASSERT_GT(net.at("max_penetration").get<double>(), 0.01 * 0.005);
  bool said = false;
  for (const Json& n : CableNamed(file, "cable").at("notes"))
    said = said || n.get<std::string>().find("contact is held at nodes") != std::string::npos;
  EXPECT_TRUE(said);
}

}  // namespace
}  // namespace cablefit
