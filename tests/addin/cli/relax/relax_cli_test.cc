// `cablefit relax` end to end through the built binary: the sample harness (STEP and STL), a
// cable drawn as its own equilibrium comes back unchanged, the clamped-clamped beam's sag, and
// bad inputs in a batch.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <thread>

#include "cablefit/core/solver/centerline_sampling.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/file_digest.h"
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

fs::path Sample(const std::string& name) { return testing::SourceDir() / "samples/harness" / name; }

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// One cable drawn as a tube along `centreline` (project writer: B-spline spine, swept circle).
fs::path WriteOneCableStep(const fs::path& path, const Polyline& centreline, double diameter) {
  HarnessDrawing drawing;
  DrawnCable cable;
  cable.name = "test_cable";
  cable.has_color = true;
  cable.color = {0.2, 0.4, 0.9};
  cable.diameter = diameter;
  cable.centreline = centreline;
  drawing.cables.push_back(cable);
  WriteRelaxedStep(path.string(), drawing, {RelaxedCable{0, centreline, diameter}});
  return path;
}

TEST(RelaxCli, SampleHarnessStepAndStlWriteEverythingAndTheStepReadsBack) {
  const fs::path out = testing::FreshTempDir("relax_sample");
  const auto run =
      RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " " +
                  Q(Sample("branched_tubes.stl")) + " --out " + Q(out) + " --close-ups");
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  std::printf("%s", run.out.c_str());  // per-cable lines and per-stage times (benchmark figure)
  for (const char* f : {"legacy_harness.step", "legacy_harness.json",
                        "legacy_harness-deviation.png", "branched_tubes.step",
                        "branched_tubes.json", "branched_tubes-deviation.png", "report.html"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
    EXPECT_GT(fs::file_size(out / f), 1000u) << f;
  }
  const HarnessDrawing in = ReadCadFile(Sample("legacy_harness.step").string());
  const HarnessDrawing back = ReadCadFile((out / "legacy_harness.step").string());
  ASSERT_EQ(back.cables.size(), in.cables.size());
  std::map<std::string, SrgbColor> colours;
  for (const DrawnCable& c : back.cables) colours[c.name] = c.color;
  for (const DrawnCable& c : in.cables) {
    ASSERT_TRUE(colours.count(c.name)) << c.name;
    EXPECT_NEAR(colours[c.name].r, c.color.r, 1.0 / 255) << c.name;
    EXPECT_NEAR(colours[c.name].g, c.color.g, 1.0 / 255) << c.name;
    EXPECT_NEAR(colours[c.name].b, c.color.b, 1.0 / 255) << c.name;
  }
  EXPECT_EQ(back.solids.size(), in.solids.size());

  const Json j = json::ReadJsonFile((out / "legacy_harness.json").string());
  EXPECT_EQ(j.at("format"), "cablefit-relax/1");
  ASSERT_EQ(j.at("cables").size(), in.cables.size());
  for (const Json& c : j.at("cables")) {
    const std::string name = c.at("name");
    EXPECT_TRUE(c.at("solver").at("converged").get<bool>()) << name;
    EXPECT_TRUE(c.at("material").at("defaulted").get<bool>()) << name;
    // Two held ends, or one when the other is joined to a breakout.
    EXPECT_GE(c.at("supports").size(), c.contains("junction") ? 1u : 2u) << name;
    // Held ends stay at their drawn positions.
    const Json& rows = c.at("relaxed_centreline").at("rows");
    const Json& first = c.at("supports").front();
    if (first.at("s").get<double>() == 0.0) {
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(rows.front()[k + 1].get<double>(), first.at("position")[k].get<double>(), 1e-9);
    }
    EXPECT_GT(c.at("deviation").at("max").get<double>(), 0.0) << name;
    EXPECT_GE(c.at("deviation").at("max").get<double>(), c.at("deviation").at("rms").get<double>());
    EXPECT_EQ(c.at("supports").front().at("reaction").at("force").size(), 3u);
  }
  // Breakout at (0.3, 0, 0): its three branches are solved as one network, the breakout is free
  // to move (it sags), and the loads the branches put on it balance.
  for (const char* name : {"trunk", "branch_a", "branch_b"}) {
    EXPECT_EQ(CableNamed(j, name).value("junction", ""),
              "solved as one network with the cables it meets at breakout 1")
        << name;
  }
  EXPECT_FALSE(CableNamed(j, "hose").contains("junction"));
  const Json* network = nullptr;
  for (const Json& n : j.at("networks"))
    if (!n.at("junctions").empty()) network = &n;
  ASSERT_NE(network, nullptr);
  const Json& breakout = network->at("junctions")[0];
  EXPECT_EQ(breakout.at("branch_loads").size(), 3u);
  EXPECT_LT(breakout.at("position")[2].get<double>(), -1e-4);  // drawn at z = 0
  double biggest = 0.0;
  for (const Json& l : breakout.at("branch_loads"))
    biggest = std::max(biggest, std::hypot(l.at("force")[0].get<double>(), l.at("force")[1].get<double>(),
                                           l.at("force")[2].get<double>()));
  EXPECT_GT(biggest, 0.0);
  EXPECT_LT(breakout.at("force_residual").get<double>(), 1e-9 * biggest);
  EXPECT_LT(breakout.at("moment_residual").get<double>(), 1e-9);
  // branch_a runs through clip_box: a clip support between its ends.
  const Json& a = CableNamed(j, "branch_a");
  bool clipped = false;
  for (const Json& sp : a.at("supports"))
    clipped = clipped || (sp.at("kind") == "clip" && sp.at("origin") == "clip 'clip_box'");
  EXPECT_TRUE(clipped);

  const Json m = json::ReadJsonFile((out / "branched_tubes.json").string());
  EXPECT_EQ(m.at("cables").size(), 3u);
  const std::string report = [&] {
    std::ifstream f(out / "report.html");
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
  }();
  EXPECT_NE(report.find("branch_a"), std::string::npos);
  EXPECT_NE(report.find("legacy_harness-deviation.png"), std::string::npos);
  EXPECT_EQ(report.find("http"), std::string::npos);  // self-contained
  // --close-ups: one picture per cable, file-safe names ("#" replaced), linked from the report.
  for (const char* f :
       {"legacy_harness-hose-deviation.png", "branched_tubes-branched_tubes_1-deviation.png"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
    EXPECT_NE(report.find(f), std::string::npos) << f;
  }
}

// A rod's own equilibrium, drawn exactly, is already relaxed: the solve must return it.
TEST(RelaxCli, CableDrawnAsItsOwnEquilibriumComesBackUnchanged) {
  // Clamps at the ends of a circular arc of chord 0.4 m and length 0.42 m (sin t / t = 0.4/0.42),
  // which is also the starting shape; gravity then bends the arch.
  const double chord = 0.4, length = 0.42;
  double lo = 1e-3, hi = 1.5;
  for (int k = 0; k < 100; ++k) {
    const double t = 0.5 * (lo + hi);
    (std::sin(t) / t > chord / length ? lo : hi) = t;
  }
  const double theta = 0.5 * (lo + hi), radius = 0.5 * length / theta;
  Polyline arc;
  arc.points.resize(3, 101);
  for (int i = 0; i <= 100; ++i) {
    const double phi = -theta + 2 * theta * i / 100.0;
    arc.points.col(i) =
        Vec3(0.5 * chord + radius * std::sin(phi), 0, radius * (std::cos(phi) - std::cos(theta)));
  }
  RodSpec spec;
  spec.name = "test_cable";
  spec.length = length;
  spec.material = {0.02, 1.0, 0.0, 0.015, 0.08, 0.006};  // EI, ratio, angle, GJ, kg/m, d
  SupportSpec a, b;
  a.position = Vec3(0, 0, 0);
  a.tangent = Vec3(std::cos(theta), 0, std::sin(theta));
  a.normal = Vec3(0, 1, 0);
  b.s = spec.length;
  b.position = Vec3(chord, 0, 0.0);
  b.tangent = Vec3(std::cos(theta), 0, -std::sin(theta));
  b.normal = Vec3(0, 1, 0);
  spec.supports = {a, b};
  RodSimulator sim;
  const SimulationResult truth = sim.Simulate(spec, &arc);
  ASSERT_TRUE(truth.converged) << truth.solution.summary.message;
  ASSERT_TRUE(truth.solution.summary.stable);
  const Polyline drawn =
      SampleCenterline(truth.solution.centerline, UniformArcLengths(spec.length, 226));

  const fs::path dir = testing::FreshTempDir("relax_equilibrium");
  WriteOneCableStep(dir / "equilibrium.step", drawn, spec.material.diameter);
  WriteText(dir / "harness.json", R"({"format": "cablefit-harness/1",
    "cables": {"test_cable": {"material": {"bending_stiffness": 0.02, "torsional_stiffness": 0.015,
                                            "linear_density": 0.08}}}})");
  const auto run = RunCablefit("relax " + Q(dir / "equilibrium.step") + " --out " + Q(dir / "out") +
                               " --config " + Q(dir / "harness.json") + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json j = json::ReadJsonFile((dir / "out/equilibrium.json").string());
  const Json& c = CableNamed(j, "test_cable");
  EXPECT_FALSE(c.at("material").at("defaulted").get<bool>());
  EXPECT_NEAR(c.at("length").get<double>(), spec.length, 1e-5);
  EXPECT_LT(c.at("deviation").at("max").get<double>(), 1e-5);
  // And against the equilibrium itself, point by point at the same arc length fraction.
  double worst = 0.0;
  const double relaxed_length = c.at("length").get<double>();
  for (const Json& row : c.at("relaxed_centreline").at("rows")) {
    const double s = row[0].get<double>() / relaxed_length * spec.length;
    const Polyline p = SampleCenterline(truth.solution.centerline, Eigen::VectorXd::Constant(1, s));
    const Vec3 r(row[1].get<double>(), row[2].get<double>(), row[3].get<double>());
    worst = std::max(worst, (r - p.points.col(0)).norm());
  }
  std::printf("equilibrium drawn -> relaxed: max deviation %.2e m, pointwise %.2e m\n",
              c.at("deviation").at("max").get<double>(), worst);
  EXPECT_LT(worst, 1e-5);
}

// Clamped-clamped beam under its weight (one clamp sliding axially so that no membrane tension
// builds up, as the linear theory assumes): w_max = q L^4 / (384 EI) (e.g. Roark's Formulas for
// Stress and Strain, table 8.1 case 2e).
TEST(RelaxCli, StraightCableSagsByTheClampedClampedBeamFormula) {
  const double length = 0.5, ei = 0.05, mass = 0.05, g = 9.81;
  const double q = mass * g;                     // [N/m]
  ASSERT_LT(q * std::pow(length, 3) / ei, 1.5);  // small load: linear theory holds
  const double expected = q * std::pow(length, 4) / (384 * ei);
  Polyline line;
  line.points.resize(3, 2);
  line.points << 0.1, 0.1 + length, 0.2, 0.2, 0.05, 0.05;
  const fs::path dir = testing::FreshTempDir("relax_sag");
  WriteOneCableStep(dir / "straight.step", line, 0.005);
  WriteText(dir / "harness.json", R"({"gravity": [0, 0, -9.81], "cables": {"test_cable": {
    "material": {"bending_stiffness": 0.05, "torsional_stiffness": 0.04, "linear_density": 0.05},
    "end": {"kind": "clamp", "sliding": true}}}})");
  const auto run = RunCablefit("relax " + Q(dir / "straight.step") + " --out " + Q(dir / "out") +
                               " --config " + Q(dir / "harness.json") + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json file = json::ReadJsonFile((dir / "out/straight.json").string());
  const Json& c = CableNamed(file, "test_cable");
  const double sag = c.at("deviation").at("max").get<double>();
  std::printf("clamped-clamped sag %.6e m, closed form %.6e m (rel. %.2e)\n", sag, expected,
              sag / expected - 1);
  EXPECT_NEAR(sag, expected, 0.01 * expected);
  // Drawn straight, a straight cable has nothing to spring back from: all of it is sag.
  EXPECT_LT(c.at("deviation").at("springback_max").get<double>(), 1e-6);
  EXPECT_NEAR(c.at("deviation").at("sag_max").get<double>(), sag, 1e-6);
  EXPECT_NEAR(c.at("deviation").at("max_at").at("s").get<double>(), 0.5 * length, 0.02 * length);
  const Json& p = c.at("deviation").at("max_at").at("point");
  EXPECT_LT(p[2].get<double>(), 0.05);  // downwards
  // Each clamp carries half the weight.
  for (const Json& sp : c.at("supports")) {
    EXPECT_NEAR(sp.at("reaction").at("force")[2].get<double>(), 0.5 * q * length,
                1e-3 * q * length);
  }
}

// A nearly weightless cable drawn as a sine arch (no equilibrium of a rod clamped at its ends)
// moves only by springing back: the split puts the whole deviation there and none in sag.
TEST(RelaxCli, AWeightlessCableDrawnOutOfEquilibriumOnlySpringsBack) {
  Polyline arch;
  arch.points.resize(3, 201);
  for (int i = 0; i <= 200; ++i) {
    const double x = 0.4 * i / 200.0;
    arch.points.col(i) = Vec3(x, 0, 0.05 * std::sin(M_PI * x / 0.4));
  }
  arch.ParameteriseByChords();
  const fs::path dir = testing::FreshTempDir("relax_springback");
  WriteOneCableStep(dir / "arch.step", arch, 0.006);
  WriteText(dir / "harness.json", R"({"cables": {"test_cable": {"material": {
    "bending_stiffness": 0.02, "torsional_stiffness": 0.015, "linear_density": 1e-6}}}})");
  const auto run = RunCablefit("relax " + Q(dir / "arch.step") + " --out " + Q(dir / "out") +
                               " --config " + Q(dir / "harness.json") + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json file = json::ReadJsonFile((dir / "out/arch.json").string());
  const Json& d = CableNamed(file, "test_cable").at("deviation");
  const double max = d.at("max").get<double>(), springback = d.at("springback_max").get<double>();
  std::printf("sine arch: deviation %.4e m, springback %.4e m, sag %.4e m\n", max, springback,
              d.at("sag_max").get<double>());
  EXPECT_GT(max, 1e-4);
  EXPECT_NEAR(springback, max, 1e-3 * max);
  EXPECT_LT(d.at("sag_max").get<double>(), 1e-3 * max);
}

// The mesh skeleton's Delaunay poles come from a random insertion order whose seed was the
// clock: two runs a second apart gave cables of different lengths. Now every run is the same.
TEST(RelaxCli, TheSameMeshGivesTheSameCablesOnEveryRun) {
  const fs::path dir = testing::FreshTempDir("relax_repeat");
  std::vector<Json> runs;
  for (int k = 0; k < 2; ++k) {
    if (k > 0) std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    const fs::path out = dir / ("out" + std::to_string(k));
    const auto run = RunCablefit("relax " + Q(Sample("branched_tubes.stl")) + " --out " + Q(out) +
                                 " --no-pictures");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    runs.push_back(json::ReadJsonFile((out / "branched_tubes.json").string()));
  }
  ASSERT_EQ(runs[0].at("cables").size(), runs[1].at("cables").size());
  for (size_t i = 0; i < runs[0].at("cables").size(); ++i) {
    const Json& a = runs[0].at("cables")[i];
    const Json& b = runs[1].at("cables")[i];
    EXPECT_EQ(a.at("name"), b.at("name"));
    EXPECT_EQ(a.at("length").get<double>(), b.at("length").get<double>()) << a.at("name");
    EXPECT_EQ(a.at("diameter").get<double>(), b.at("diameter").get<double>()) << a.at("name");
    EXPECT_EQ(a.at("deviation").at("max").get<double>(), b.at("deviation").at("max").get<double>())
        << a.at("name");
  }
}

// A cable cut 10 % longer than its straight drawing, so flexible that it hangs as a catenary:
// its sag is the catenary's of that length between the clamps.
TEST(RelaxCli, OverLengthFromHarnessJsonHangsAsTheCatenaryOfThatLength) {
  const double span = 0.5;
  Polyline line;
  line.points.resize(3, 2);
  line.points << 0.1, 0.1 + span, 0.2, 0.2, 0.05, 0.05;
  const fs::path dir = testing::FreshTempDir("relax_over_length");
  WriteOneCableStep(dir / "straight.step", line, 0.002);
  WriteText(dir / "harness.json", R"({"cables": {"test_cable": {"length": "+10%",
    "material": {"bending_stiffness": 2e-6, "torsional_stiffness": 2e-6, "linear_density": 0.05}}}})");
  const auto run = RunCablefit("relax " + Q(dir / "straight.step") + " --out " + Q(dir / "out") +
                               " --config " + Q(dir / "harness.json") + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json file = json::ReadJsonFile((dir / "out/straight.json").string());
  const Json& c = CableNamed(file, "test_cable");
  const double length = 1.1 * span;
  EXPECT_NEAR(c.at("drawn_length").get<double>(), span, 1e-9);
  EXPECT_NEAR(c.at("length").get<double>(), length, 1e-9);
  // Catenary y = a cosh(x/a): length 2 a sinh(span / 2a), sag a (cosh(span / 2a) - 1).
  double lo = 0.01, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (2 * a * std::sinh(span / (2 * a)) > length ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi);
  const double expected = a * (std::cosh(span / (2 * a)) - 1);
  const double sag = c.at("deviation").at("max").get<double>();
  std::printf("over-length sag %.5f m, catenary %.5f m\n", sag, expected);
  EXPECT_NEAR(sag, expected, 0.01 * expected);  // measured 0.24 % (bending near the clamps)
  EXPECT_FALSE(c.at("stretches")[0].at("taut").get<bool>());
  EXPECT_NEAR(c.at("stretches")[0].at("slack").get<double>(), 0.1, 1e-6);

  // A length the file cannot mean is refused with the field named.
  for (const char* bad : {R"("+ten%")", R"("5%")", R"("-60%")", R"(-0.2)"}) {
    WriteText(dir / "bad.json", std::string(R"({"cables": {"test_cable": {"length": )") + bad + "}}}");
    const auto refused = RunCablefit("relax " + Q(dir / "straight.step") + " --out " +
                                     Q(dir / "bad_out") + " --config " + Q(dir / "bad.json"));
    EXPECT_EQ(refused.exit_code, 2) << bad << "\n" << refused.err;
    EXPECT_NE(refused.err.find("length"), std::string::npos) << refused.err;
  }
}

TEST(RelaxCli, BadInputsGiveOneLineEachAndTheRestOfTheBatchIsDone) {
  const fs::path dir = testing::FreshTempDir("relax_bad");
  WriteText(dir / "empty.step", "");
  {
    std::ifstream in(Sample("legacy_harness.step"), std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(in)), {});
    WriteText(dir / "truncated.step", all.substr(0, all.size() / 3));
  }
  {  // only the sample's clips, no cable
    HarnessDrawing sample = ReadCadFile(Sample("legacy_harness.step").string());
    WriteRelaxedStep((dir / "clips_only.step").string(), sample, {});
  }
  {  // a cube is not a tube
    const char* cube =
        "solid cube\n"
        "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 10 10 0\nvertex 10 0 "
        "0\nendloop\nendfacet\n"
        "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 10 0\nvertex 10 10 "
        "0\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex 0 0 10\nvertex 10 0 10\nvertex 10 10 "
        "10\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex 0 0 10\nvertex 10 10 10\nvertex 0 10 "
        "10\nendloop\nendfacet\n"
        "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 10 0 0\nvertex 10 0 "
        "10\nendloop\nendfacet\n"
        "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 10 0 10\nvertex 0 0 "
        "10\nendloop\nendfacet\n"
        "facet normal 0 1 0\nouter loop\nvertex 0 10 0\nvertex 10 10 10\nvertex 10 10 "
        "0\nendloop\nendfacet\n"
        "facet normal 0 1 0\nouter loop\nvertex 0 10 0\nvertex 0 10 10\nvertex 10 10 "
        "10\nendloop\nendfacet\n"
        "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 10 10\nvertex 0 10 "
        "0\nendloop\nendfacet\n"
        "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 10\nvertex 0 10 "
        "10\nendloop\nendfacet\n"
        "facet normal 1 0 0\nouter loop\nvertex 10 0 0\nvertex 10 10 0\nvertex 10 10 "
        "10\nendloop\nendfacet\n"
        "facet normal 1 0 0\nouter loop\nvertex 10 0 0\nvertex 10 10 10\nvertex 10 0 "
        "10\nendloop\nendfacet\n"
        "endsolid cube\n";
    WriteText(dir / "cube.stl", cube);
  }
  const auto run =
      RunCablefit("relax " + Q(dir / "empty.step") + " " + Q(dir / "truncated.step") + " " +
                  Q(dir / "clips_only.step") + " " + Q(dir / "cube.stl") + " " +
                  Q(Sample("legacy_harness.step")) + " --out " + Q(dir / "out") + " --no-pictures");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  std::printf("%s", run.err.c_str());
  for (const char* bad : {"empty.step", "clips_only.step", "cube.stl"}) {
    const std::string prefix = "cablefit: " + (dir / bad).string() + ": ";
    EXPECT_NE(run.err.find(prefix), std::string::npos) << bad << "\n" << run.err;
    EXPECT_FALSE(fs::exists(dir / "out" / (fs::path(bad).stem().string() + ".json"))) << bad;
  }
  EXPECT_NE(run.err.find("no cable curves or tube solids found"), std::string::npos);
  // A truncated STEP may still hold some complete entities: it either fails with one line or
  // is read in part; it never crashes the batch.
  const bool truncated_failed =
      run.err.find("cablefit: " + (dir / "truncated.step").string() + ": ") != std::string::npos;
  EXPECT_NE(truncated_failed, fs::exists(dir / "out/truncated.json"));
  EXPECT_TRUE(fs::exists(dir / "out/legacy_harness.json"));
  EXPECT_TRUE(fs::exists(dir / "out/legacy_harness.step"));
  EXPECT_TRUE(fs::exists(dir / "out/report.html"));
  EXPECT_NE(run.err.find("failure(s):"), std::string::npos);
}

TEST(RelaxCli, NothingReadableOrBadUsageExitsWithTwo) {
  const fs::path dir = testing::FreshTempDir("relax_usage");
  WriteText(dir / "empty.step", "");
  auto run = RunCablefit("relax " + Q(dir / "empty.step") + " --out " + Q(dir / "out"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("cablefit: " + (dir / "empty.step").string() + ": "), std::string::npos);
  run = RunCablefit("relax " + Q(dir / "missing.step") + " --out " + Q(dir / "out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no such file"), std::string::npos) << run.err;
  run = RunCablefit("relax --out " + Q(dir / "out"));
  EXPECT_EQ(run.exit_code, 2);
  WriteText(dir / "harness.json", R"({"cables": {"x": {"materiall": {}}}})");
  run = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " + Q(dir / "out") +
                    " --config " + Q(dir / "harness.json"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("cables.x.materiall is not a known field"), std::string::npos) << run.err;
}

TEST(RelaxCli, HarnessJsonSupportsAndMaterialAreUsed) {
  const fs::path dir = testing::FreshTempDir("relax_config");
  // An extra pin by point halfway along the hose, the hose's material from a section file.
  WriteText(dir / "section.json",
            R"({"format": "cablefit-section/1", "library": ")" +
                (testing::SourceDir() / "samples/materials/automotive.json").string() +
                R"(", "components": [{"name": "w", "wire": "FLRY-B 0.5", "position": [0, 0]}]})");
  WriteText(dir / "harness.json", R"({"min_bend_radius_factor": 1000, "cables": {
      "hose": {"supports": [{"kind": "pin", "point": [0.3, -0.27, 0.0]}]},
      "trunk": {"material": {"section": "section.json"}}}})");
  const auto run =
      RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " + Q(dir / "out") +
                  " --config " + Q(dir / "harness.json") + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
  const Json j = json::ReadJsonFile((dir / "out/legacy_harness.json").string());
  const Json& hose = CableNamed(j, "hose");
  ASSERT_EQ(hose.at("supports").size(), 3u);
  EXPECT_EQ(hose.at("supports")[1].at("kind"), "pin");
  EXPECT_EQ(hose.at("supports")[1].at("origin"), "harness.json");
  EXPECT_TRUE(hose.at("min_bend_radius").at("flag").get<bool>());  // 1000 diameters: every bend
  const Json& trunk = CableNamed(j, "trunk");
  EXPECT_FALSE(trunk.at("material").at("defaulted").get<bool>());
  EXPECT_NEAR(trunk.at("diameter").get<double>(), 0.0016, 0.0005);  // the wire's outer diameter
}

TEST(RelaxCli, RigidPartsNamedInHarnessJsonAreKeptAsSolidsNotRelaxed) {
  const fs::path dir = testing::FreshTempDir("relax_rigid");
  WriteText(dir / "rigid.json", R"({"rigid": ["ho*"]})");
  const auto run = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " +
                               Q(dir / "out") + " --config " + Q(dir / "rigid.json") +
                               " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json j = json::ReadJsonFile((dir / "out/legacy_harness.json").string());
  for (const Json& c : j.at("cables")) EXPECT_NE(c.at("name"), "hose");
  EXPECT_EQ(j.at("cables").size(), 4u);
  ASSERT_EQ(j.at("not_cables").size(), 1u);
  EXPECT_NE(j.at("not_cables")[0].get<std::string>().find("'hose': a rigid part"), std::string::npos);
  // The hose's solid is copied into the output STEP unchanged: read back without harness.json
  // it is a tube again, exactly where it was drawn (the relaxed cables moved).
  const HarnessDrawing drawn = ReadCadFile(Sample("legacy_harness.step").string());
  const HarnessDrawing back = ReadCadFile((dir / "out/legacy_harness.step").string());
  ASSERT_EQ(back.cables.size(), 5u);
  const auto named = [](const HarnessDrawing& d, const std::string& name) {
    for (const DrawnCable& c : d.cables)
      if (c.name == name) return c.centreline;
    ADD_FAILURE() << "no cable " << name;
    return Polyline{};
  };
  const Polyline hose_drawn = named(drawn, "hose"), hose_back = named(back, "hose");
  ASSERT_GE(hose_back.size(), 2);
  EXPECT_LT((hose_back.points.col(0) - hose_drawn.points.col(0)).norm(), 1e-5);
  EXPECT_LT((hose_back.points.col(hose_back.size() - 1) - hose_drawn.points.col(hose_drawn.size() - 1)).norm(), 1e-5);
  const Polyline trunk_back = named(back, "trunk"), trunk_drawn = named(drawn, "trunk");
  ASSERT_GE(trunk_back.size(), 2);
  const auto middle = [](const Polyline& p) {
    return SampleCenterline(p, Eigen::VectorXd::Constant(1, 0.5 * p.s[p.size() - 1])).points;
  };
  EXPECT_GT((middle(trunk_back) - middle(trunk_drawn)).norm(), 1e-3);

  // "only": what it does not match is rigid; a bare curve has no body and is left out.
  WriteText(dir / "only.json", R"({"only": ["branch_?"]})");
  const auto only = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " +
                                Q(dir / "only") + " --config " + Q(dir / "only.json") +
                                " --no-pictures");
  ASSERT_EQ(only.exit_code, 0) << only.err;
  const Json jo = json::ReadJsonFile((dir / "only/legacy_harness.json").string());
  ASSERT_EQ(jo.at("cables").size(), 2u);
  for (const Json& c : jo.at("cables"))
    EXPECT_EQ(c.at("name").get<std::string>().rfind("branch_", 0), 0u) << c.at("name");
  EXPECT_EQ(jo.at("not_cables").size(), 3u);

  // Nothing left to relax, and an empty list, are one-line errors.
  WriteText(dir / "none.json", R"({"only": ["no_such_cable"]})");
  const auto none = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " +
                                Q(dir / "none") + " --config " + Q(dir / "none.json"));
  EXPECT_NE(none.exit_code, 0);
  EXPECT_NE(none.err.find("no cable left to relax"), std::string::npos) << none.err;
  WriteText(dir / "empty.json", R"({"rigid": []})");
  const auto empty = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " +
                                 Q(dir / "empty") + " --config " + Q(dir / "empty.json"));
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("rigid must list at least one name pattern"), std::string::npos)
      << empty.err;
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

// The sidecar example shipped with the sample harness is valid and is what the output says.
TEST(RelaxCli, SampleSidecarAppliesToTheSampleHarness) {
  const fs::path out = testing::FreshTempDir("relax_sidecar");
  const auto run = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " + Q(out) +
                               " --config " + Q(Sample("harness.json")) + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json j = json::ReadJsonFile((out / "legacy_harness.json").string());
  for (const char* name : {"trunk", "sensor_cable", "hose"}) {
    EXPECT_FALSE(CableNamed(j, name).at("material").at("defaulted").get<bool>()) << name;
  }
  EXPECT_TRUE(CableNamed(j, "branch_a").at("material").at("defaulted").get<bool>());
  EXPECT_FALSE(CableNamed(j, "branch_a").at("diameter_defaulted").get<bool>());  // "default" block
  EXPECT_NEAR(CableNamed(j, "trunk").at("diameter").get<double>(), 0.012, 1e-12);
  EXPECT_NEAR(CableNamed(j, "branch_a").at("diameter").get<double>(), 0.008, 1e-12);
  // The report leads with the verdict: 5 cables, none failed, the worst deviation named.
  const std::string report = testing::ReadTextFile(out / "report.html");
  EXPECT_NE(report.find("<b>5 cables</b> from 1 input: 5 relaxed"), std::string::npos);
  EXPECT_NE(report.find(">0 failed<"), std::string::npos);
  EXPECT_NE(report.find("Largest deviation from the drawing"), std::string::npos);
  // Provenance: the CAD file and the config, each with the SHA-256 of its bytes.
  const Json& inputs = j.at("provenance").at("inputs");
  ASSERT_EQ(inputs.size(), 2u);
  EXPECT_EQ(inputs[0].at("role"), "input");
  EXPECT_EQ(inputs[0].at("sha256"), FileSha256(Sample("legacy_harness.step").string()));
  EXPECT_EQ(inputs[1].at("role"), "config");
  EXPECT_EQ(inputs[1].at("sha256"), FileSha256(Sample("harness.json").string()));
  // The hose is a 12 mm tube solid: the "default" diameter is for bare curves, not for it.
  EXPECT_NEAR(CableNamed(j, "hose").at("diameter").get<double>(), 0.012, 1e-6);
  const Json& end = CableNamed(j, "sensor_cable").at("supports").back();
  EXPECT_EQ(end.at("kind"), "clip");
  EXPECT_TRUE(end.at("sliding").get<bool>());
  EXPECT_EQ(CableNamed(j, "hose").at("supports").size(), 3u);
  // The same sidecar on the STL, whose tubes have other names: warned about, not a failure.
  const auto mesh = RunCablefit("relax " + Q(Sample("branched_tubes.stl")) + " --out " + Q(out) +
                                " --config " + Q(Sample("harness.json")) + " --no-pictures");
  EXPECT_EQ(mesh.exit_code, 0) << mesh.err;
  EXPECT_NE(mesh.err.find("cablefit: warning: " + Sample("harness.json").string() +
                          ": cables.hose matches no cable of the inputs"),
            std::string::npos)
      << mesh.err;
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

TEST(RelaxCli, FreeCadCablesDrawnAsCurvesAndSweepsAllRelax) {
  // Each wire is its route curve, its conductor sweep and its stripped insulation; each bundle
  // a base curve inside its sheath, its cores stripped at the ends. Read as separate parts, the
  // 8 mm default curves lay inside their neighbours' sweeps and 13 of 25 cables failed; read as
  // one cable each, none does, and the stripped core ends are no cables: 2 cables (the 3-core
  // cable's jacket lies 38 mm from its route curve in the file, so it is read twice; the 5-core
  // one is 9.2 diameters long, a part) and 6.
  const auto out = testing::FreshTempDir("relax_freecad_sweeps");
  for (const auto& [name, cables] : std::vector<std::pair<std::string, int>>{
           {"cables_example1_visible.step", 2}, {"cables_harness_example_solids.step", 6}}) {
    const auto run = RunCablefit("relax " + Q(testing::SourceDir() / "tests/data/realcad" / name) +
                                 " --no-pictures --out " + Q(out / name));
    EXPECT_EQ(run.exit_code, 0) << name << "\n" << run.err;
    const std::string stem = fs::path(name).stem().string();
    std::ifstream in(out / name / (stem + ".json"));
    const Json j = Json::parse(in);
    int relaxed = 0;
    for (const Json& c : j["cables"]) {
      EXPECT_FALSE(c.contains("error")) << c["name"] << ": " << c["error"];
      relaxed += c.contains("relaxed_centreline");
    }
    EXPECT_EQ(relaxed, cables) << name;
    EXPECT_EQ(j["cables"].size(), static_cast<size_t>(cables)) << name;
  }
}

// The report's table sorts numbers as numbers (the script reads data-value), says the default
// material once above the table instead of in every row, names a material file by its name
// only, and has a header and the run's provenance; every length is in mm.
TEST(RelaxCli, ReportSortsNumbersAndSaysTheDefaultMaterialOnce) {
  const fs::path dir = testing::FreshTempDir("relax_report_table");
  WriteText(dir / "section.json",
            R"({"format": "cablefit-section/1", "library": ")" +
                (testing::SourceDir() / "samples/materials/automotive.json").string() +
                R"(", "components": [{"name": "w", "wire": "FLRY-B 0.5", "position": [0, 0]}]})");
  WriteText(dir / "harness.json", R"({"cables": {"trunk": {"material": {"section": "section.json"}}}})");
  const auto run = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " +
                               Q(dir / "out") + " --config " + Q(dir / "harness.json") +
                               " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string report = testing::ReadTextFile(dir / "out/report.html");
  EXPECT_EQ(report.find("data-v="), std::string::npos);
  EXPECT_NE(report.find("data-value=\""), std::string::npos);
  EXPECT_NE(report.find("getAttribute('data-value')"), std::string::npos);
  // Four cables have the default material: its note once, not four times.
  const std::string note = "PVC-insulated copper bundle estimated from the diameter";
  const size_t first = report.find(note);
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(report.find(note, first + 1), std::string::npos);
  // The material file by its name; its full path only in the tooltip.
  EXPECT_NE(report.find(">section.json</span>"), std::string::npos);
  EXPECT_NE(report.find("<header class=\"top\">"), std::string::npos);
  EXPECT_NE(report.find("<main>"), std::string::npos);
  EXPECT_NE(report.find("sha256 " + FileSha256(Sample("legacy_harness.step").string())),
            std::string::npos);
  EXPECT_NE(report.find("<small>relaxed "), std::string::npos);
  EXPECT_NE(report.find("max<br>tension"), std::string::npos);
  EXPECT_NE(report.find("<small>clamp "), std::string::npos);  // each support's reaction
  EXPECT_FALSE(std::regex_search(report, std::regex(R"(\d m<)")));  // no length in metres
  EXPECT_EQ(report.find("\u00b5m"), std::string::npos);
}

// --quiet: only the final summary line on the standard output; --summary-json: the same counts
// per input and cable, the failures and the provenance; the final line is printed without it.
TEST(RelaxCli, QuietSummaryJsonAndTheFinalLine) {
  const fs::path dir = testing::FreshTempDir("relax_quiet");
  WriteText(dir / "empty.step", "");
  const fs::path summary = dir / "summary.json";
  const auto run = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " " +
                               Q(dir / "empty.step") + " --out " + Q(dir / "out") +
                               " --no-pictures --quiet --summary-json " + Q(summary));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 1) << run.out;
  EXPECT_EQ(run.out.rfind("relax: 5 cables from 2 inputs: 5 relaxed, 0 failed, ", 0), 0u) << run.out;
  EXPECT_NE(run.out.find("largest deviation "), std::string::npos) << run.out;
  // Failures: one prefixed line when found, the same line in the list at the end.
  const std::string line = "cablefit: " + (dir / "empty.step").string() + ": ";
  const size_t at = run.err.find(line);
  ASSERT_NE(at, std::string::npos) << run.err;
  EXPECT_NE(run.err.find(line, at + 1), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("cablefit: relax: 1 failure(s):\n"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("\n  "), std::string::npos) << run.err;  // no indented lines
  const Json j = json::ReadJsonFile(summary.string());
  EXPECT_EQ(j.at("format"), "cablefit-relax-summary/1");
  EXPECT_EQ(j.at("counts").at("inputs"), 2);
  EXPECT_EQ(j.at("counts").at("cables"), 5);
  EXPECT_EQ(j.at("counts").at("relaxed"), 5);
  EXPECT_EQ(j.at("counts").at("inputs_failed"), 1);
  ASSERT_EQ(j.at("inputs").size(), 2u);
  EXPECT_EQ(j.at("inputs")[0].at("status"), "ok");
  EXPECT_EQ(j.at("inputs")[0].at("cables").size(), 5u);
  EXPECT_EQ(j.at("inputs")[1].at("status"), "unread");
  ASSERT_EQ(j.at("failures").size(), 1u);
  EXPECT_EQ(j.at("failures")[0].get<std::string>().rfind((dir / "empty.step").string(), 0), 0u);
  EXPECT_EQ(j.at("provenance").at("inputs")[0].at("sha256"),
            FileSha256(Sample("legacy_harness.step").string()));
  // The per-input JSON names the command line and the date too, its old fields unchanged.
  const Json per_input = json::ReadJsonFile((dir / "out/legacy_harness.json").string());
  EXPECT_NE(per_input.at("provenance").at("command_line").get<std::string>().find("--quiet"),
            std::string::npos);
  EXPECT_EQ(per_input.at("provenance").at("date").get<std::string>().size(), 20u);
  EXPECT_EQ(per_input.at("format"), "cablefit-relax/1");
}

// --out naming an existing file, or --summary-json naming a folder, is a usage error found
// before any input is read.
TEST(RelaxCli, OutNamingAFileIsRefusedBeforeAnyWork) {
  const fs::path dir = testing::FreshTempDir("relax_out_file");
  WriteText(dir / "taken", "x");
  auto run = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " + Q(dir / "taken"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("exists and is not a folder"), std::string::npos) << run.err;
  EXPECT_EQ(run.out, "");
  run = RunCablefit("relax " + Q(Sample("legacy_harness.step")) + " --out " + Q(dir / "out") +
                    " --summary-json " + Q(dir));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--summary-json"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out/legacy_harness.json"));
}

}  // namespace
}  // namespace cablefit
