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

// How many things the skipped lines containing `text` stand for: a line said of several
// instances ends with "(<n> times)".
int CountSkipped(const HarnessDrawing& d, const std::string& text) {
  int count = 0;
  for (const std::string& line : d.skipped) {
    if (line.find(text) == std::string::npos) continue;
    const size_t open = line.rfind(" (");
    const bool repeated = line.size() > 7 && line.compare(line.size() - 7, 7, " times)") == 0;
    count += repeated ? std::stoi(line.substr(open + 2)) : 1;
  }
  return count;
}

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
  // Every cable is slender (at least 10 diameters long). The conductor ends of the 3-core cable
  // (20 mm of 1.4 mm conductor with 2.8 mm insulation over 12 mm of it, 7 diameters) are its
  // stripped core ends, listed as part of it, not cables.
  for (const DrawnCable& c : d.cables) {
    EXPECT_GE(Length(c), 10 * c.diameter) << c.name;
    EXPECT_NE(c.name.rfind("cable_x3#", 0), 0u) << c.name;
  }
  EXPECT_EQ(CountSkipped(d, "out of the end of cable 'cable_x3_Base'"), 6);
  // The single wires' 8 mm bare conductor ends likewise (1.6 mm out of a 3 mm wire).
  EXPECT_EQ(CountSkipped(d, "1.596 mm core 8 mm long out of the end of cable"), 6);
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
  // The three 180 mm ducts are parts, with the reason listed.
  EXPECT_EQ(d.solids.size(), 3u);
  EXPECT_TRUE(std::any_of(d.skipped.begin(), d.skipped.end(), [](const std::string& s) {
    return s.find("diameters long") != std::string::npos;
  }));
}

// FreeCAD's Cables workbench: a 3-core flat cable (its route curve and, 38 mm away in this
// file, its stadium jacket) and a 5-core round one (route curve with the jacket swept along it),
// each with the cores stripped 20 mm at both ends, drawn as tubes and as curves with sweeps.
// Two cables: the flat cable read twice (its jacket and its route are apart), the round one
// too stout.
TEST(CadRecognition, StrippedCoreEndsOfMultiCoreCablesAreNoCables) {
  const HarnessDrawing d = ReadRealCad("cables_example1_visible.step");
  std::set<std::string> names;
  for (const DrawnCable& c : d.cables) names.insert(c.name);
  // The 5-core cable's jacket is 12.95 mm across on 119 mm: 9.2 diameters, a part.
  EXPECT_EQ(names, (std::set<std::string>{"Cable", "Cable_Base"}));
  EXPECT_EQ(CountSkipped(d, "'Cable001_Base': a cable drawn as a curve 9.2 diameters long"), 1);
  for (const DrawnCable& c : d.cables) {
    EXPECT_NEAR(Length(c), 0.1192, 1e-3) << c.name;
    if (c.name == "Cable") {  // the jacket bends flatwise and edgewise in turn
      ASSERT_TRUE(c.flat.has_value());
      EXPECT_TRUE(c.flat->rounded_edges);
      EXPECT_NEAR(c.flat->width, 0.01145, 2e-4);
      EXPECT_NEAR(c.flat->thickness, 0.00568, 2e-4);
    }
  }
  // 3 + 5 cores at both ends of each drawing of the cables, by their tubes or their curves.
  const auto tails = [&](const std::string& cable) {
    return CountSkipped(d, "out of the end of cable '" + cable + "'");
  };
  EXPECT_EQ(tails("Cable_Base"), 6);
  EXPECT_EQ(tails("Cable001_Base"), 10);
  EXPECT_EQ(tails("Cable"), 6);
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
