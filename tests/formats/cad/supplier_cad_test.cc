// What the CAD reader takes as a cable in files drawn as supplier CAD draws cables
// (tests/data/supplier, with how each was made): tubes drawn only as loose surfaces, pipes swept
// along B-splines, multi-core cables in IGES, pipelines of rigid pipes.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "cablefit/formats/cad_file.h"
#include "test_support.h"

namespace cablefit {
namespace {

HarnessDrawing ReadSupplier(const std::string& name) {
  return ReadCadFile((testing::SourceDir() / "tests/data/supplier" / name).string());
}

double Length(const DrawnCable& c) { return c.centreline.s[c.centreline.size() - 1]; }

bool Says(const HarnessDrawing& d, const std::string& text) {
  return std::any_of(d.skipped.begin(), d.skipped.end(),
                     [&](const std::string& s) { return s.find(text) != std::string::npos; });
}

TEST(SupplierCad, ASlenderTubeDrawnOnlyAsUngroupedSurfacesIsOneCable) {
  // Six polynomial half-surfaces, each an IGES root entity of its own, no end faces: an 8 mm
  // tube 382.8 mm long (120 mm, a quarter bend of 40 mm radius, 200 mm).
  const HarnessDrawing d = ReadSupplier("tube_surfaces.igs");
  ASSERT_EQ(d.cables.size(), 1u);
  EXPECT_TRUE(d.solids.empty());
  EXPECT_NEAR(d.cables[0].diameter, 0.008, 0.002 * 0.008);
  EXPECT_NEAR(Length(d.cables[0]), 0.12 + 0.02 * M_PI + 0.2, 1e-4);
  EXPECT_EQ(d.cables[0].inner_diameter, 0.0);
}

TEST(SupplierCad, APipeSweptAlongABSplineAsOnePolynomialSurfaceIsOneCable) {
  const HarnessDrawing d = ReadSupplier("bspline_pipe.step");
  ASSERT_EQ(d.cables.size(), 1u);
  EXPECT_NEAR(d.cables[0].diameter, 0.006, 0.002 * 0.006);
  EXPECT_NEAR(Length(d.cables[0]), 0.383, 0.001);
}

TEST(SupplierCad, EachCoreOfAMultiCoreCableInIgesIsOneCableOfItsInsulation) {
  // 10 cores, each a 1 mm conductor in its 1.6 mm insulation, every solid's surfaces in one file
  // group: the conductors' surfaces coincide with their insulations' bores.
  const HarnessDrawing d = ReadSupplier("multicore_insulated.igs");
  ASSERT_EQ(d.cables.size(), 10u);
  for (const DrawnCable& c : d.cables) {
    EXPECT_NEAR(c.diameter, 0.0016, 1e-6) << c.name;
    EXPECT_EQ(c.inner_diameter, 0.0) << c.name;
    EXPECT_GT(Length(c), 0.35) << c.name;
  }
}

TEST(SupplierCad, StraightPipesWithFlangesOrElbowsArePartsAndAHoseBetweenFlangesIsACable) {
  const HarnessDrawing d = ReadSupplier("pipeline.step");
  std::set<std::string> cables;
  for (const DrawnCable& c : d.cables) cables.insert(c.name);
  EXPECT_EQ(cables, (std::set<std::string>{"hose", "sensor_cable"}));
  // Every pipe is a part, with the reason; so are the flanges and elbows.
  EXPECT_TRUE(Says(d,
                   "'pipe_A': a straight tube (60.3 mm across, 1200 mm long) flanged at an end "
                   "by 'flange_A': a rigid pipe"));
  EXPECT_TRUE(Says(d,
                   "'pipe_B': a straight tube (60.3 mm across, 900 mm long) joined at an end to "
                   "the pipe elbow"));
  EXPECT_TRUE(Says(d, "'pipe_C': a straight tube"));
  EXPECT_EQ(d.solids.size(), 9u);
}

}  // namespace
}  // namespace cablefit
