// Reading relax inputs: mesh parts that are no cables, and sizes that betray a wrong unit.
#include "cablefit/app/input/harness_input.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/mesh_file.h"
#include "test_support.h"

namespace cablefit::addin {
namespace {

Polyline Straight(double length, int n = 30) {
  Polyline p;
  p.points.resize(3, n);
  for (int i = 0; i < n; ++i) p.points.col(i) << length * i / (n - 1), 0, 0;
  p.ParameteriseByChords(0.0);
  return p;
}

DrawnCable Cable(double length, double diameter) {
  DrawnCable c;
  c.name = "c";
  c.centreline = Straight(length);
  c.diameter = diameter;
  return c;
}

// The meshes side by side in one mesh (no shared vertices: one component each).
TriangleMesh Joined(const std::vector<TriangleMesh>& meshes) {
  TriangleMesh all;
  Eigen::Index nv = 0, nf = 0;
  for (const TriangleMesh& m : meshes) nv += m.vertices.cols(), nf += m.faces.cols();
  all.vertices.resize(3, nv);
  all.faces.resize(3, nf);
  nv = nf = 0;
  for (const TriangleMesh& m : meshes) {
    all.vertices.middleCols(nv, m.vertices.cols()) = m.vertices;
    all.faces.middleCols(nf, m.faces.cols()) = m.faces.array() + static_cast<int>(nv);
    nv += m.vertices.cols();
    nf += m.faces.cols();
  }
  return all;
}

// A straight piece from `a` to `b` [m].
Polyline Segment(const Vec3& a, const Vec3& b, int n = 8) {
  Polyline p;
  p.points.resize(3, n);
  for (int i = 0; i < n; ++i) p.points.col(i) = a + (b - a) * i / (n - 1.0);
  p.ParameteriseByChords(0.0);
  return p;
}

TEST(RelaxInput, MetreSizesReadAsMillimetresAreNamedWithTheUnitThatFits) {
  HarnessDrawing d;
  // A 0.6 m, 8 mm cable drawn in metres and read as millimetres.
  d.cables = {Cable(0.6e-3, 8e-6), Cable(0.4e-3, 6e-6)};
  const std::string why = ImplausibleMeshUnit(d, 1e-3);
  EXPECT_NE(why.find("implausible for cables"), std::string::npos) << why;
  EXPECT_NE(why.find("use --unit m "), std::string::npos) << why;
  // Millimetre sizes read as metres: the hint is millimetres.
  d.cables = {Cable(600, 8), Cable(400, 6)};
  EXPECT_NE(ImplausibleMeshUnit(d, 1.0).find("use --unit mm"), std::string::npos);
  // Plausible cables: nothing to say.
  d.cables = {Cable(0.6, 8e-3), Cable(0.05, 0.5e-3)};
  EXPECT_EQ(ImplausibleMeshUnit(d, 1e-3), "");
}

TEST(RelaxInput, AMeshPartThatIsNoTubeIsKeptAsASolidBesideTheCable) {
  const auto dir = testing::FreshTempDir("relax_input_parts");
  TriangleMesh tube = SweepTubeMesh(Straight(0.25), 0.008, 16);
  // A 20 mm cube beside it (a bracket).
  TriangleMesh cube;
  cube.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i)
    cube.vertices.col(i) << 0.1 + 0.02 * (i & 1), 0.05 + 0.02 * ((i >> 1) & 1), 0.02 * (i >> 2);
  cube.faces.resize(3, 12);
  cube.faces << 0, 0, 4, 4, 0, 0, 2, 2, 0, 0, 1, 1,
                2, 3, 5, 7, 1, 5, 6, 7, 4, 6, 3, 7,
                3, 1, 7, 6, 5, 4, 7, 3, 6, 2, 7, 5;
  TriangleMesh both;
  both.vertices.resize(3, tube.vertices.cols() + 8);
  both.vertices << tube.vertices, cube.vertices;
  both.faces.resize(3, tube.faces.cols() + 12);
  both.faces << tube.faces, (cube.faces.array() + static_cast<int>(tube.vertices.cols())).matrix();
  const std::string path = (dir / "cable_and_bracket.stl").string();
  WriteMeshFile(path, both, 0.001);

  const HarnessDrawing d = ReadHarnessInput(path, 0.001);
  ASSERT_EQ(d.cables.size(), 1u);
  EXPECT_NEAR(d.cables[0].centreline.ChordLength(), 0.25, 0.003);
  ASSERT_EQ(d.solids.size(), 1u);
  EXPECT_EQ(d.solids[0].mesh.faces.cols(), cube.faces.cols());
  ASSERT_EQ(d.skipped.size(), 1u);
  EXPECT_NE(d.skipped[0].find("not a tube"), std::string::npos) << d.skipped[0];
  EXPECT_TRUE(d.warnings.empty());

  // The bracket alone: no cable at all is an error that says why.
  const std::string alone = (dir / "bracket.stl").string();
  WriteMeshFile(alone, cube, 0.001);
  EXPECT_THROW_WITH(ReadHarnessInput(alone, 0.001), cablefit::FileError, "no tube found in the mesh");
}

TEST(RelaxInput, AShortStoutCylinderIsAPartNotACable) {
  const auto dir = testing::FreshTempDir("relax_input_stout");
  // A screw shank (9.5 x 28.6 mm) beside a 300 mm cable.
  TriangleMesh cable = SweepTubeMesh(Straight(0.3), 0.008, 16);
  Polyline shank_route = Straight(0.0286, 8);
  shank_route.points.row(1).array() += 0.05;
  shank_route.ParameteriseByChords(0.0);
  TriangleMesh shank = SweepTubeMesh(shank_route, 0.0095, 16);
  TriangleMesh both;
  both.vertices.resize(3, cable.vertices.cols() + shank.vertices.cols());
  both.vertices << cable.vertices, shank.vertices;
  both.faces.resize(3, cable.faces.cols() + shank.faces.cols());
  both.faces << cable.faces,
      (shank.faces.array() + static_cast<int>(cable.vertices.cols())).matrix();
  const std::string path = (dir / "cable_and_screw.stl").string();
  WriteMeshFile(path, both, 0.001);
  const MeshContents contents = ReadMeshContents(path, 0.001);
  ASSERT_EQ(contents.tubes.size(), 1u);
  EXPECT_NEAR(contents.tubes[0].diameter, 0.008, 0.0004);
  ASSERT_EQ(contents.parts.size(), 1u);
  EXPECT_NE(contents.parts[0].reason.find("short stout solid"), std::string::npos)
      << contents.parts[0].reason;
}

TEST(RelaxInput, StrippedCoreEndsOfAMeshedCableArePartOfIt) {
  const auto dir = testing::FreshTempDir("relax_input_core_tails");
  // An 8 mm jacket 200 mm long; out of its end face come two 2.5 mm cores (8 of their own
  // diameters: parts by length) and a 1 mm conductor (20 diameters: a tube by length), each
  // 20 mm long, starting 5 mm inside the jacket. A 1 mm wire 40 mm away is a cable of its own.
  std::vector<TriangleMesh> meshes = {SweepTubeMesh(Straight(0.2), 0.008, 24)};
  for (int k = 0; k < 3; ++k) {
    const double angle = 2.0 * M_PI * k / 3.0;
    const Vec3 offset(0.0, 0.0016 * std::cos(angle), 0.0016 * std::sin(angle));
    meshes.push_back(SweepTubeMesh(Segment(Vec3(0.195, 0, 0) + offset, Vec3(0.215, 0, 0) + offset),
                                   k == 2 ? 0.001 : 0.0025, 12));
  }
  meshes.push_back(SweepTubeMesh(Segment(Vec3(0.1, 0.04, 0), Vec3(0.13, 0.04, 0)), 0.001, 12));
  const std::string path = (dir / "jacket_with_cores.stl").string();
  WriteMeshFile(path, Joined(meshes), 0.001);

  const HarnessDrawing d = ReadHarnessInput(path, 0.001);
  ASSERT_EQ(d.cables.size(), 2u);
  int jackets = 0;
  for (const DrawnCable& c : d.cables) jackets += c.diameter > 0.006;
  EXPECT_EQ(jackets, 1);
  EXPECT_TRUE(d.solids.empty());
  int tails = 0;
  for (const std::string& line : d.skipped) tails += line.find("stripped core end") != std::string::npos;
  EXPECT_EQ(tails, 3);
  EXPECT_TRUE(d.junctions.empty());
}

}  // namespace
}  // namespace cablefit::addin
