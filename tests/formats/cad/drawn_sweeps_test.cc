// A cable drawn as a route curve plus the solids swept along it (conductor, insulation, sheath)
// is one cable: the curve takes the sweep's diameter and the sweeps leave the drawing.
#include "drawn_sweeps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cablefit/formats/cad_file.h"
#include "test_support.h"

namespace cablefit {
namespace {

using internal::DrawnTube;

// A straight route along x from x0 to x1 at height z [m].
Polyline Straight(double x0, double x1, double z, int n = 11) {
  Eigen::Matrix3Xd p(3, n);
  for (int i = 0; i < n; ++i) p.col(i) = Vec3(x0 + (x1 - x0) * i / (n - 1), 0.0, z);
  Polyline line;
  line.points = p;
  line.ParameteriseByChords();
  return line;
}

DrawnCable Curve(const std::string& name, double z) {
  DrawnCable c;
  c.name = name;
  c.centreline = Straight(0.0, 0.02, z);
  c.source = CableSourceKind::kCurve;
  return c;
}

// A solid part recorded as a tube along x in [x0, x1] at height z.
DrawnTube SolidTube(HarnessDrawing* d, const std::string& name, double x0, double x1, double z,
                    double radius, double inner = 0.0) {
  DrawnSolid s;
  s.name = name;
  d->solids.push_back(s);
  d->skipped.push_back("'" + name + "': kept as a solid part");
  DrawnTube t;
  t.index = static_cast<int>(d->solids.size()) - 1;
  t.skipped_note = static_cast<int>(d->skipped.size()) - 1;
  t.centres = Straight(x0, x1, z, 7).points;
  t.radius = radius;
  t.inner_radius = inner;
  return t;
}

TEST(DrawnSweeps, ACurveTakesTheDiameterOfItsInsulationAndItsSweepsLeaveTheDrawing) {
  HarnessDrawing d;
  d.cables = {Curve("L1", 0.0), Curve("L2", 0.003)};
  // L1: a 2.2 mm conductor over all of it, a 3.6 mm insulation over 60 % (stripped end).
  // L2's conductor sits 3 mm away: it must not be taken by L1.
  std::vector<DrawnTube> tubes = {SolidTube(&d, "core1", 0.0, 0.02, 0.0, 0.0011),
                                  SolidTube(&d, "sleeve1", 0.0, 0.012, 0.0, 0.0018, 0.0011),
                                  SolidTube(&d, "core2", 0.0, 0.02, 0.003, 0.0011),
                                  SolidTube(&d, "bracket", 0.0, 0.02, 0.0015, 0.0011)};
  internal::MergeSweepsIntoCurves(tubes, &d);
  ASSERT_EQ(d.cables.size(), 2u);
  EXPECT_DOUBLE_EQ(d.cables[0].diameter, 0.0036);
  EXPECT_DOUBLE_EQ(d.cables[0].inner_diameter, 0.0);
  EXPECT_DOUBLE_EQ(d.cables[1].diameter, 0.0022);
  // The tube 1.5 mm off both routes (more than a fifth of its radius) is some other part.
  ASSERT_EQ(d.solids.size(), 1u);
  EXPECT_EQ(d.solids[0].name, "bracket");
  EXPECT_NE(d.skipped[1].find("drawn along curve 'L1' (60 % of it)"), std::string::npos)
      << d.skipped[1];
  EXPECT_EQ(d.skipped[3], "'bracket': kept as a solid part");
}

TEST(DrawnSweeps, AShortHollowTubeAloneIsADuctButAFullLengthOneIsAHose) {
  HarnessDrawing d;
  d.cables = {Curve("wire", 0.0), Curve("hose", 0.05)};
  std::vector<DrawnTube> tubes = {SolidTube(&d, "grommet", 0.008, 0.012, 0.0, 0.004, 0.003),
                                  SolidTube(&d, "hose body", 0.0, 0.02, 0.05, 0.006, 0.004)};
  internal::MergeSweepsIntoCurves(tubes, &d);
  EXPECT_DOUBLE_EQ(d.cables[0].diameter, 0.0);  // the grommet holds it; it is not its body
  EXPECT_DOUBLE_EQ(d.cables[1].diameter, 0.012);
  EXPECT_DOUBLE_EQ(d.cables[1].inner_diameter, 0.008);
  ASSERT_EQ(d.solids.size(), 1u);
  EXPECT_EQ(d.solids[0].name, "grommet");
}

TEST(DrawnSweeps, InsulationAroundAConductorDrawnAsATubeCableIsPartOfIt) {
  HarnessDrawing d;
  DrawnCable conductor = Curve("conductor", 0.0);
  conductor.source = CableSourceKind::kTube;
  conductor.diameter = 0.0014;
  d.cables = {conductor};
  std::vector<DrawnTube> tubes = {SolidTube(&d, "insulation", 0.0, 0.015, 0.0, 0.0014, 0.0007)};
  internal::MergeSweepsIntoCurves(tubes, &d);
  EXPECT_DOUBLE_EQ(d.cables[0].diameter, 0.0028);
  EXPECT_TRUE(d.solids.empty());
}

TEST(DrawnSweeps, AFreeCadCableDrawnAsCurvesAndSweepsIsReadOnceWithItsDiameters) {
  // FreeCAD's Cables workbench exports each wire as its route curve, its conductor sweep and its
  // insulation sweep (stripped at one end), and the bundle's sheath around its base curve.
  const HarnessDrawing d = ReadCadFile(
      (testing::SourceDir() / "tests/data/realcad/cables_example1_visible.step").string());
  // The cores' curves take their sweeps' 3.657 mm (and, being stripped core ends, then go
  // with the cable); the base curve takes the 12.95 mm sheath, which makes it 9.2 diameters
  // long: too stout for a cable, so it and its sheath are a part, and no sweep is a cable.
  for (const DrawnCable& c : d.cables)
    EXPECT_NE(c.name.rfind("Cable001", 0), 0u) << c.name;
  int cores = 0, base = 0;
  for (const std::string& line : d.skipped) {
    cores += line.find("3.657 mm core ") != std::string::npos &&
             line.find("out of the end of cable 'Cable001_Base'") != std::string::npos;
    base += line.find("'Cable001_Base': a cable drawn as a curve 9.2 diameters long (12.95 mm") !=
            std::string::npos;
  }
  EXPECT_EQ(cores, 10);  // five at each end
  EXPECT_EQ(base, 1);
  EXPECT_EQ(std::count_if(d.solids.begin(), d.solids.end(),
                          [](const DrawnSolid& s) { return s.name == "Cable001"; }),
            1)
      << "the sheath is a part";
}

}  // namespace
}  // namespace cablefit
