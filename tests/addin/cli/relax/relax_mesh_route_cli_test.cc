// A cable relaxes to the same shape whether it is read from STEP (exact tube) or from a mesh
// of the same tube: the mesh reader's route and diameter are what the STEP reader's are.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/formats/mesh_file.h"
#include "cli_runner.h"
#include "curve_distance.h"
#include "relax_test_util.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

// A 0.4 m span sagging 40 mm, drawn as an 8 mm tube.
Vec3 Sag(double u) { return Vec3(0.4 * u, 0.0, -0.04 * std::sin(M_PI * u)); }

json::Json Relaxed(const fs::path& input) {
  const fs::path out = input.parent_path() / ("out-" + input.extension().string().substr(1));
  const auto run = testing::RunCablefit("relax " + testing::Q(input) + " --no-pictures --quiet --out " +
                                        testing::Q(out));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const json::Json j = json::ReadJsonFile((out / (input.stem().string() + ".json")).string());
  EXPECT_EQ(j.at("cables").size(), 1u);
  return j.at("cables").at(0);
}

Vec3 Tangent(const json::Json& cable, size_t support) {
  const json::Json& t = cable.at("supports").at(support).at("tangent");
  return Vec3(t.at(0).get<double>(), t.at(1).get<double>(), t.at(2).get<double>());
}

constexpr double kDiameter = 0.008;

// Writes the exact tube as dir/sag.step, relaxes it and dir/`stl`, and returns how far apart the
// two relaxed routes are [m]; `stl` (the STL cable's JSON) receives the mesh's cable.
double ApartFromStep(const fs::path& dir, const std::string& stl_name, json::Json* stl) {
  HarnessDrawing drawing;
  DrawnCable cable;
  cable.name = "sag";
  cable.centreline = testing::SampleCurve(Sag, 401);
  cable.diameter = kDiameter;
  drawing.cables.push_back(cable);
  WriteRelaxedStep((dir / "sag.step").string(), drawing, {RelaxedCable{0, cable.centreline, kDiameter}});
  const json::Json step = Relaxed(dir / "sag.step");
  *stl = Relaxed(dir / stl_name);
  EXPECT_NEAR(stl->at("diameter").get<double>(), step.at("diameter").get<double>(), 1e-3 * kDiameter);
  for (size_t k = 0; k < 2; ++k) {
    const Vec3 t = Tangent(step, k), u = Tangent(*stl, k);
    EXPECT_LT(std::acos(std::min(1.0, t.dot(u))), 0.5e-3) << "support " << k;
  }
  return std::max(testing::FarthestFromCentreline(step, *stl),
                  testing::FarthestFromCentreline(*stl, step));
}

// The same for `sides`-gon STL rings every `ring` [m] of our own.
double StlApartFromStep(const fs::path& dir, int sides, double ring) {
  const int rings = static_cast<int>(std::lround(0.41 / ring)) + 1;
  WriteMeshFile((dir / "sag.stl").string(),
                SweepTubeMesh(testing::SampleCurve(Sag, rings), kDiameter, sides), 0.001);
  json::Json stl;
  const double apart = ApartFromStep(dir, "sag.stl", &stl);
  std::printf("%d sides (chord sag %.3f mm), rings every %.0f mm: STL vs STEP relaxed route %.4f "
              "mm apart\n",
              sides, 0.5e3 * kDiameter * (1 - std::cos(M_PI / sides)), 1e3 * ring, 1e3 * apart);
  return apart;
}

TEST(RelaxMeshRoute, ASaggingTubeFromStlRelaxesWhereTheSameTubeFromStepDoes) {
  // 24 sides, a ring every 5 mm: a facet's chord sags 0.034 mm inside the surface.
  EXPECT_LT(StlApartFromStep(testing::FreshTempDir("relax_mesh_route"), 24, 0.005), 0.01e-3);
}

TEST(RelaxMeshRoute, AnotherMeshersCoarseExportRelaxesWhereTheExactTubeDoes) {
  // The same tube tessellated by FreeCAD at 0.3 mm chord deflection (tests/data/mesh/README.md):
  // no rings, long thin facets, fan caps. The end tangents come from the caps' normals; taken
  // from the last slice centres they were 3-5 mrad off and the relaxed routes 0.08-0.14 mm apart.
  const fs::path dir = testing::FreshTempDir("relax_mesh_route_occt");
  fs::copy_file(testing::SourceDir() / "tests/data/mesh/sag_tube_0.3mm_deflection.stl",
                dir / "sag_mesh.stl");
  json::Json stl;
  const double apart = ApartFromStep(dir, "sag_mesh.stl", &stl);
  std::printf("FreeCAD 0.3 mm mesh vs STEP relaxed route: %.4f mm apart\n", 1e3 * apart);
  EXPECT_LT(apart, 0.02e-3);
}

TEST(RelaxMeshRoute, ACoarselyTessellatedTubeRelaxesWhereTheExactTubeDoes) {
  // 8 sides, a ring every 10 mm: a facet's chord sags 0.3 mm inside the surface, as an export at
  // a coarse chord tolerance gives.
  EXPECT_LT(StlApartFromStep(testing::FreshTempDir("relax_mesh_route_coarse"), 8, 0.010), 0.02e-3);
}

// 100 mm straight, then 60 degrees of a bend of curvature 11 1/m, to the cap.
Vec3 TightEnd(double u) {
  const double radius = 1.0 / 11, straight = 0.1, s = u * (straight + radius * M_PI / 3);
  if (s <= straight) return {s, 0, 0};
  const double a = (s - straight) / radius;
  return {straight + radius * std::sin(a), 0, radius * (1 - std::cos(a))};
}

TEST(RelaxMeshRoute, ATubeEndingInATightBendIsClampedAlongItsCapNormal) {
  // An 8 mm tube with a ring every 0.5 mm: the route's last points (a blend onto the cap over
  // three radii) gave the bent end's direction 0.8 mrad off its cap's normal, and the relaxed
  // cable 0.05 mm off the same tube read from STEP.
  const fs::path dir = testing::FreshTempDir("relax_mesh_tight_end");
  const Polyline drawn = testing::SampleCurve(TightEnd, 390);
  WriteMeshFile((dir / "tight.stl").string(), SweepTubeMesh(drawn, kDiameter, 24), 0.001);
  const json::Json stl = Relaxed(dir / "tight.stl");
  // SweepTubeMesh squares its caps to the centreline's first and last chords.
  const Eigen::Index n = drawn.points.cols();
  const Vec3 caps[2] = {(drawn.points.col(1) - drawn.points.col(0)).normalized(),
                        (drawn.points.col(n - 1) - drawn.points.col(n - 2)).normalized()};
  for (size_t k = 0; k < 2; ++k) {
    const Vec3 t = Tangent(stl, k);
    std::printf("end %zu: clamp %.4f mrad off the cap's normal\n", k,
                1e3 * std::acos(std::min(1.0, t.dot(caps[k]))));
    EXPECT_LT(std::acos(std::min(1.0, t.dot(caps[k]))), 0.1e-3) << "support " << k;
  }
}

}  // namespace
}  // namespace cablefit
