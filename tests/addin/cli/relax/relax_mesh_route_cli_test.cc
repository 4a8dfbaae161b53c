// A cable relaxes to the same shape whether it is read from STEP (exact tube) or from a mesh
// of the same tube: the mesh reader's route and diameter are what the STEP reader's are.
#include <gtest/gtest.h>

#include <cmath>
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

TEST(RelaxMeshRoute, ASaggingTubeFromStlRelaxesWhereTheSameTubeFromStepDoes) {
  const fs::path dir = testing::FreshTempDir("relax_mesh_route");
  const double diameter = 0.008;
  HarnessDrawing drawing;
  DrawnCable cable;
  cable.name = "sag";
  cable.centreline = testing::SampleCurve(Sag, 401);
  cable.diameter = diameter;
  drawing.cables.push_back(cable);
  WriteRelaxedStep((dir / "sag.step").string(), drawing, {RelaxedCable{0, cable.centreline, diameter}});
  // 24 sides, a ring every 5 mm: a facet's chord sags 0.034 mm inside the surface.
  WriteMeshFile((dir / "sag.stl").string(), SweepTubeMesh(testing::SampleCurve(Sag, 83), diameter, 24),
                0.001);
  const json::Json step = Relaxed(dir / "sag.step"), stl = Relaxed(dir / "sag.stl");
  EXPECT_NEAR(stl.at("diameter").get<double>(), step.at("diameter").get<double>(), 1e-3 * diameter);
  const double apart = std::max(testing::FarthestFromCentreline(step, stl),
                                testing::FarthestFromCentreline(stl, step));
  std::printf("STL vs STEP relaxed route: %.4f mm apart; diameters %.4f / %.4f mm\n", 1e3 * apart,
              1e3 * stl.at("diameter").get<double>(), 1e3 * step.at("diameter").get<double>());
  EXPECT_LT(apart, 1e-4);
}

}  // namespace
}  // namespace cablefit
