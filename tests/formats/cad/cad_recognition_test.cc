// What the CAD reader takes as a cable in files other CAD systems wrote (tests/data/realcad, with
// their origin): FreeCAD's swept tubes of cylinder, torus (one of 600 m major radius), extrusion
// and B-spline faces; hollow conduits; profile sketches beside the sweeps; short stubs; an IGES
// tube made of two loose surfaces; exporter placeholder names.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "test_support.h"

namespace cablefit {
namespace {

HarnessDrawing ReadRealCad(const std::string& name) {
  return ReadCadFile((testing::SourceDir() / "tests/data/realcad" / name).string());
}

double Length(const DrawnCable& c) { return c.centreline.s[c.centreline.size() - 1]; }

void ExpectDistinctNonEmptyNames(const HarnessDrawing& d) {
  std::set<std::string> names;
  for (const DrawnCable& c : d.cables) {
    EXPECT_FALSE(c.name.empty());
    EXPECT_TRUE(names.insert(c.name).second) << "name used twice: " << c.name;
  }
}

TEST(CadRecognition, FreeCadSweptTubesAreFoundWithTheirDiametersAndStubsAreParts) {
  const HarnessDrawing d = ReadRealCad("cables_harness_example_solids.step");
  ExpectDistinctNonEmptyNames(d);
  // Every tube cable is slender (at least 10 diameters long) but the conductor ends of the 3-core
  // cable: 20 mm of 1.4 mm conductor drawn with 2.8 mm insulation over 12 mm of it, one cable
  // with the insulation's diameter.
  int conductor_ends = 0;
  for (const DrawnCable& c : d.cables) {
    if (c.source != CableSourceKind::kTube) continue;
    if (c.name.rfind("cable_x3#", 0) == 0) {
      ++conductor_ends;
      EXPECT_NEAR(Length(c), 0.020, 1e-4) << c.name;
      EXPECT_NEAR(c.diameter, 0.00278, 2e-5) << c.name;
    } else {
      EXPECT_GE(Length(c), 10 * c.diameter) << c.name;
    }
  }
  EXPECT_EQ(conductor_ends, 6);
  // The long cables: three 3 mm wires, two conduits (8 and 6.2 mm, drawn solid) and the 9 mm
  // three-core cable (its base curve with the sheath swept along it), each over half a metre.
  std::vector<double> long_diameters;
  for (const DrawnCable& c : d.cables) {
    if (Length(c) < 0.5) continue;
    long_diameters.push_back(c.diameter);
    if (c.inner_diameter > 0) {
      EXPECT_LT(c.inner_diameter, c.diameter) << c.name;
    }
  }
  std::sort(long_diameters.begin(), long_diameters.end());
  ASSERT_EQ(long_diameters.size(), 6u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(long_diameters[i], 0.003, 1e-4);
  EXPECT_NEAR(long_diameters[3], 0.00618, 2e-4);
  EXPECT_NEAR(long_diameters[4], 0.00798, 2e-4);
  EXPECT_NEAR(long_diameters[5], 0.00901, 2e-4);
  // The 8 mm end stubs and the three 180 mm ducts are parts, with the reason listed.
  EXPECT_GE(d.solids.size(), 3u + 6u);
  EXPECT_TRUE(std::any_of(d.skipped.begin(), d.skipped.end(), [](const std::string& s) {
    return s.find("diameters long") != std::string::npos;
  }));
}

TEST(CadRecognition, ProfileSketchesBesideASweepAreNotCables) {
  const HarnessDrawing d = ReadRealCad("cables_example1_visible.step");
  ExpectDistinctNonEmptyNames(d);
  for (const DrawnCable& c : d.cables) {
    const auto& p = c.centreline.points;
    EXPECT_GT((p.col(0) - p.col(p.cols() - 1)).norm(), 1e-6) << c.name << " is a closed curve";
  }
  EXPECT_TRUE(std::any_of(d.skipped.begin(), d.skipped.end(), [](const std::string& s) {
    return s.find("sketch profile") != std::string::npos;
  }));
}

TEST(CadRecognition, RoutesAndDuctsKeepTheirNames) {
  const HarnessDrawing d = ReadRealCad("cables_harness_example_routes.step");
  std::set<std::string> names;
  for (const DrawnCable& c : d.cables) names.insert(c.name);
  EXPECT_EQ(names, (std::set<std::string>{"black_cond_main_Base", "cable_brown_Base",
                                          "cable_green_Base", "cable_red_Base", "cable_x3_Base"}));
  EXPECT_EQ(d.solids.size(), 3u);
}

TEST(CadRecognition, PlaceholderNamesBecomeDistinctGeometricNames) {
  const HarnessDrawing d = ReadRealCad("occt_ec_exhaust-A.stp");
  ExpectDistinctNonEmptyNames(d);
  for (const DrawnCable& c : d.cables) EXPECT_NE(c.name, "the product name");
  for (const DrawnSolid& s : d.solids) EXPECT_NE(s.name, "the product name");
}

TEST(CadRecognition, AnIgesTubeOfLooseSurfacesIsReadAndJudgedBySlenderness) {
  // Sewn into one shell it is a tube of 187 mm, 7.2 diameters long: a part, not a cable, and
  // the error says so instead of "no shapes".
  EXPECT_THROW_WITH(ReadRealCad("occt_bug23171_tube_surf.igs"), FileError, "diameters long");
}

}  // namespace
}  // namespace cablefit
