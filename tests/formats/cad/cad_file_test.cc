#include "cablefit/formats/cad_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "curve_distance.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::MaxDistanceToPolyline;
using testing::SampleCurve;

std::string SampleHarness() {
  return (testing::SourceDir() / "samples/harness/legacy_harness.step").string();
}

// An S-shaped, slightly climbing route 0.4 m long in x.
Vec3 SRoute(double u) {
  return {0.4 * u, 0.04 * std::sin(2 * M_PI * u), 0.01 * u};
}

HarnessDrawing OneDrawnCable(double diameter) {
  HarnessDrawing drawing;
  DrawnCable cable;
  cable.name = "cable_ä";
  cable.has_color = true;
  cable.color = {0.8, 0.25, 0.05};
  cable.diameter = diameter;
  cable.centreline = SampleCurve(SRoute, 2);
  drawing.cables.push_back(cable);
  return drawing;
}

TEST(CadFile, TubeFromKnownCentrelineReadsBackWithinOnePercentOfDiameter) {
  const double diameter = 0.010;
  const Polyline truth = SampleCurve(SRoute, 4001);
  RelaxedCable relaxed{0, SampleCurve(SRoute, 81), 0.0};
  const auto path = (testing::FreshTempDir("cad_tube") / "tube.step").string();
  WriteRelaxedStep(path, OneDrawnCable(diameter), {relaxed});

  const HarnessDrawing back = ReadCadFile(path);
  ASSERT_EQ(back.cables.size(), 1u);
  const DrawnCable& cable = back.cables[0];
  EXPECT_EQ(cable.source, CableSourceKind::kTube);
  EXPECT_NEAR(cable.diameter, diameter, 0.01 * diameter);
  std::printf("STEP tube read-back: centreline max %.2e m, diameter error %.2e m (d = %.3f m)\n",
              MaxDistanceToPolyline(cable.centreline, truth), std::abs(cable.diameter - diameter),
              diameter);
  EXPECT_LT(MaxDistanceToPolyline(cable.centreline, truth), 0.01 * diameter);
  EXPECT_LT(MaxDistanceToPolyline(truth, cable.centreline), 0.01 * diameter);  // ends reached
  EXPECT_NEAR(cable.centreline.s(cable.centreline.size() - 1), truth.ChordLength(), 0.01 * diameter);
  EXPECT_LT(cable.fit_error, 0.01 * diameter);
  EXPECT_EQ(cable.name, "cable_ä");
  ASSERT_TRUE(cable.has_color);
  EXPECT_NEAR(cable.color.r, 0.8, 1.0 / 255);
  EXPECT_NEAR(cable.color.g, 0.25, 1.0 / 255);
  EXPECT_NEAR(cable.color.b, 0.05, 1.0 / 255);
  EXPECT_TRUE(back.solids.empty());
}

// For each drawn cable, a route sagging 50 mm between its ends, like a relaxed cable (curves
// have no drawn diameter: all get `diameter`).
std::vector<RelaxedCable> SaggingRoutes(const HarnessDrawing& input, double diameter) {
  std::vector<RelaxedCable> relaxed;
  for (size_t i = 0; i < input.cables.size(); ++i) {
    const Polyline& drawn = input.cables[i].centreline;
    const Vec3 a = drawn.points.col(0), b = drawn.points.rightCols<1>();
    relaxed.push_back({static_cast<int>(i), SampleCurve([&](double u) -> Vec3 {
      return a + u * (b - a) - Vec3(0, 0, 0.05 * std::sin(M_PI * u));
    }, 200), diameter});
  }
  return relaxed;
}

TEST(CadFile, NamesColoursAndCountSurviveWriteRead) {
  HarnessDrawing input = ReadCadFile(SampleHarness());
  const std::vector<RelaxedCable> relaxed = SaggingRoutes(input, 0.006);
  const auto path = (testing::FreshTempDir("cad_names") / "relaxed.step").string();
  WriteRelaxedStep(path, input, relaxed);
  const HarnessDrawing back = ReadCadFile(path);
  ASSERT_EQ(back.cables.size(), input.cables.size());
  ASSERT_EQ(back.solids.size(), input.solids.size());
  std::map<std::string, const DrawnCable*> by_name;
  for (const auto& c : back.cables) by_name[c.name] = &c;
  for (size_t i = 0; i < input.cables.size(); ++i) {
    const DrawnCable& in = input.cables[i];
    ASSERT_TRUE(by_name.count(in.name)) << in.name;
    const DrawnCable& out = *by_name[in.name];
    EXPECT_EQ(out.source, CableSourceKind::kTube);
    ASSERT_EQ(out.has_color, in.has_color);
    EXPECT_NEAR(out.color.r, in.color.r, 1.0 / 255) << in.name;
    EXPECT_NEAR(out.color.g, in.color.g, 1.0 / 255) << in.name;
    EXPECT_NEAR(out.color.b, in.color.b, 1.0 / 255) << in.name;
    const double d = 0.006;  // the relaxed diameter overrides the drawn one
    EXPECT_NEAR(out.diameter, d, 0.01 * d) << in.name;
    EXPECT_LT(MaxDistanceToPolyline(out.centreline, relaxed[i].centreline), 0.01 * d) << in.name;
  }
  for (size_t i = 0; i < input.solids.size(); ++i) {
    EXPECT_EQ(back.solids[i].name, input.solids[i].name);
    EXPECT_TRUE(testing::MatricesNear(back.solids[i].mesh.vertices.rowwise().maxCoeff(),
                                      input.solids[i].mesh.vertices.rowwise().maxCoeff(), 1e-6));
  }
}

TEST(CadFile, SampleHarnessHasItsCablesSolidsAndJunction) {
  const HarnessDrawing h = ReadCadFile(SampleHarness());
  EXPECT_EQ(h.length_unit, "mm");
  std::map<std::string, const DrawnCable*> cables;
  for (const auto& c : h.cables) cables[c.name] = &c;
  ASSERT_EQ(cables.size(), 5u);
  for (const char* name : {"trunk", "branch_a", "branch_b", "sensor_cable", "hose"}) {
    ASSERT_TRUE(cables.count(name)) << name;
    EXPECT_TRUE(cables[name]->has_color) << name;
  }
  // trunk: 100 mm line + quarter arc of radius 50 mm + 200 mm line, chained into one route.
  const DrawnCable& trunk = *cables["trunk"];
  EXPECT_EQ(trunk.source, CableSourceKind::kCurve);
  EXPECT_NEAR(trunk.centreline.ChordLength(), 0.3 + 0.025 * M_PI, 1e-4);
  EXPECT_NEAR(trunk.color.r, 0.9, 1.0 / 255);
  EXPECT_NEAR(trunk.color.g, 0.1, 1.0 / 255);
  // branch_b: three lines, exactly.
  const double b_length = std::hypot(80, 60) + std::hypot(70, 40, 10) + std::hypot(70, 50, 10);
  EXPECT_NEAR(cables["branch_b"]->centreline.ChordLength(), 1e-3 * b_length, 1e-9);
  const DrawnCable& hose = *cables["hose"];
  EXPECT_EQ(hose.source, CableSourceKind::kTube);
  EXPECT_NEAR(hose.diameter, 0.012, 0.00012);
  EXPECT_NEAR((hose.centreline.points.col(0) - Vec3(0, -0.3, 0)).norm(), 0, 1.2e-4);
  EXPECT_NEAR((hose.centreline.points.rightCols<1>() - Vec3(0.6, -0.25, 0)).norm(), 0, 1.2e-4);
  for (const auto& c : h.cables) {
    const double length = c.centreline.ChordLength();
    EXPECT_GT(length, 0.2) << c.name;
    EXPECT_LT(length, 0.8) << c.name;
  }
  std::vector<std::string> solids;
  for (const auto& s : h.solids) {
    solids.push_back(s.name);
    EXPECT_TRUE(s.has_color);
    EXPECT_GT(s.mesh.faces.cols(), 0);
  }
  std::sort(solids.begin(), solids.end());
  EXPECT_EQ(solids, (std::vector<std::string>{"clip_box", "clip_ring"}));
  // The bundle's three routes meet at (300, 0, 0) mm.
  ASSERT_EQ(h.junctions.size(), 1u);
  EXPECT_EQ(h.junctions[0].ends.size(), 3u);
  EXPECT_NEAR((h.junctions[0].position - Vec3(0.3, 0, 0)).norm(), 0, 1e-6);
}

TEST(CadFile, SampleHarnessAsIgesHasTheSameCablesAndSolids) {
  const HarnessDrawing step = ReadCadFile(SampleHarness());
  const HarnessDrawing iges = ReadCadFile(
      (testing::SourceDir() / "samples/harness/legacy_harness.igs").string());
  EXPECT_EQ(iges.length_unit, "mm");
  ASSERT_EQ(iges.cables.size(), step.cables.size());
  EXPECT_EQ(iges.solids.size(), step.solids.size());
  double step_length = 0, iges_length = 0;
  for (const auto& c : step.cables) step_length += c.centreline.ChordLength();
  for (const auto& c : iges.cables) iges_length += c.centreline.ChordLength();
  EXPECT_NEAR(iges_length, step_length, 1e-4);
  // IGES names (406 name properties) are read as STEP's product names are.
  auto names = [](const HarnessDrawing& h) {
    std::vector<std::string> out;
    for (const auto& c : h.cables) out.push_back(c.name);
    for (const auto& s : h.solids) out.push_back(s.name);
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(names(iges), names(step));
}

TEST(CadFile, HonoursTheFileLengthUnit) {
  const auto dir = testing::FreshTempDir("cad_unit");
  const auto mm_path = (dir / "tube_mm.step").string();
  WriteRelaxedStep(mm_path, OneDrawnCable(0.01), {RelaxedCable{0, SampleCurve(SRoute, 41), 0}});
  std::ifstream in(mm_path);
  std::stringstream text;
  text << in.rdbuf();
  std::string step = text.str();
  const std::string milli = "SI_UNIT(.MILLI.,.METRE.)";
  const size_t at = step.find(milli);
  ASSERT_NE(at, std::string::npos);
  step.replace(at, milli.size(), "SI_UNIT($,.METRE.)");  // same numbers, now in metres
  const auto m_path = (dir / "tube_m.step").string();
  std::ofstream(m_path) << step;
  const HarnessDrawing mm = ReadCadFile(mm_path);
  const HarnessDrawing m = ReadCadFile(m_path);
  EXPECT_EQ(mm.length_unit, "mm");
  EXPECT_EQ(m.length_unit, "m");
  ASSERT_EQ(m.cables.size(), 1u);
  EXPECT_NEAR(m.cables[0].diameter, 1000 * mm.cables[0].diameter, 1e-6);
  EXPECT_NEAR(m.cables[0].centreline.ChordLength() / mm.cables[0].centreline.ChordLength(), 1000, 0.01);
}

TEST(CadFile, BadInputGivesOneLineFileErrors) {
  const auto dir = testing::FreshTempDir("cad_bad");
  auto write = [&](const std::string& name, const std::string& text) {
    const auto p = (dir / name).string();
    std::ofstream(p, std::ios::binary) << text;
    return p;
  };
  EXPECT_THROW_WITH(ReadCadFile((dir / "missing.step").string()), FileError, "no such file");
  EXPECT_THROW_WITH(ReadCadFile(write("empty.step", "")), FileError, "empty");
  EXPECT_THROW_WITH(ReadCadFile(write("garbage.step", "this is not STEP\n\x01\x02 at all")),
                    FileError, "not a readable STEP file");
  EXPECT_THROW_WITH(ReadCadFile(write("harness.dxf", "0\nSECTION\n")), FileError, "extension");
  std::ifstream in(SampleHarness(), std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string whole = text.str();
  try {  // truncated: either unreadable or read with the cut-off entities missing, never a crash
    const HarnessDrawing partial = ReadCadFile(write("truncated.step", whole.substr(0, whole.size() / 2)));
    EXPECT_LT(partial.cables.size() + partial.solids.size(), 7u);
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("truncated.step"), std::string::npos);
  }
  // Only solids, no curves: copy the sample's clips without any cable.
  const HarnessDrawing sample = ReadCadFile(SampleHarness());
  const auto clips = (dir / "clips_only.step").string();
  WriteRelaxedStep(clips, sample, {});
  EXPECT_THROW_WITH(ReadCadFile(clips), FileError, "no cable curves or tube solids found");
  // A writer refusing input it cannot sweep, with the cable named.
  EXPECT_THROW_WITH(WriteRelaxedStep((dir / "x.step").string(), sample, {RelaxedCable{0, {}, 0.005}}),
                    InvalidInput, "trunk");
  EXPECT_THROW_WITH(WriteRelaxedStep((dir / "x.step").string(), sample, {RelaxedCable{99, {}, 0}}),
                    InvalidInput, "input cable 99");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.step"));
}

TEST(CadFile, BenchmarkSampleHarnessReadWrite) {
  const auto t0 = std::chrono::steady_clock::now();
  const HarnessDrawing h = ReadCadFile(SampleHarness());
  const auto t1 = std::chrono::steady_clock::now();
  WriteRelaxedStep((testing::FreshTempDir("cad_bench") / "out.step").string(), h,
                   SaggingRoutes(h, 0.008));
  const auto t2 = std::chrono::steady_clock::now();
  std::printf("sample harness read: %.1f ms, write: %.1f ms (%zu cables, %zu solids)\n",
              std::chrono::duration<double, std::milli>(t1 - t0).count(),
              std::chrono::duration<double, std::milli>(t2 - t1).count(), h.cables.size(),
              h.solids.size());
}

}  // namespace
}  // namespace cablefit
