#include "cablefit/formats/mesh_file.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/helper_process.h"
#include "curve_distance.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::MaxDistanceToPolyline;
using testing::SampleCurve;

// 100 mm straight, a quarter bend of radius 60 mm, 120 mm straight (in the z = 20 mm plane).
Vec3 BentRoute(double u) {
  const double bend = 0.5 * M_PI * 0.06, total = 0.1 + bend + 0.12, s = u * total;
  if (s <= 0.1) return {s, 0, 0.02};
  if (s <= 0.1 + bend) {
    const double a = (s - 0.1) / 0.06;
    return {0.1 + 0.06 * std::sin(a), 0.06 - 0.06 * std::cos(a), 0.02};
  }
  return {0.16, 0.06 + (s - 0.1 - bend), 0.02};
}

TEST(MeshFile, BentTubeStlReadsBackWithinOnePercentOfDiameter) {
  const double diameter = 0.010;
  const Polyline truth = SampleCurve(BentRoute, 4001);
  const TriangleMesh tube = SweepTubeMesh(SampleCurve(BentRoute, 161), diameter, 32);
  const auto path = (testing::FreshTempDir("mesh_bent") / "tube.stl").string();
  WriteMeshFile(path, tube, 0.001);  // millimetres in the file

  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<MeshTube> tubes = ReadMeshFile(path, 0.001);
  std::printf("bent tube STL (%ld triangles) -> centreline: %.0f ms\n",
              static_cast<long>(tube.faces.cols()),
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  ASSERT_EQ(tubes.size(), 1u);
  EXPECT_NEAR(tubes[0].diameter, diameter, 0.01 * diameter);
  std::printf("STL tube read-back: centreline max %.2e m, diameter error %.2e m (d = %.3f m)\n",
              MaxDistanceToPolyline(tubes[0].centreline, truth),
              std::abs(tubes[0].diameter - diameter), diameter);
  EXPECT_LT(MaxDistanceToPolyline(tubes[0].centreline, truth), 0.01 * diameter);
  EXPECT_LT(MaxDistanceToPolyline(truth, tubes[0].centreline), 0.01 * diameter);  // ends reached
  EXPECT_LT(tubes[0].fit_error, 0.01 * diameter);
  // Deterministic orientation: starts at the lexicographically smaller end (x = 0).
  EXPECT_NEAR(tubes[0].centreline.points(0, 0), 0.0, 0.01 * diameter);
}

// A hose as a mesh: outer wall and bore (both from SweepTubeMesh's rings) joined by flat annuli
// at the ends, so the surface is one closed component of genus one.
TriangleMesh HoseMesh(const Polyline& route, double outer, double bore, int sides) {
  const TriangleMesh o = SweepTubeMesh(route, outer, sides), i = SweepTubeMesh(route, bore, sides);
  const int n = route.size(), ring = n * sides;
  TriangleMesh m;
  m.vertices.resize(3, 2 * ring);
  m.vertices << o.vertices.leftCols(ring), i.vertices.leftCols(ring);
  const int wall = 2 * (n - 1) * sides;
  m.faces.resize(3, 2 * wall + 4 * sides);
  m.faces.leftCols(wall) = o.faces.leftCols(wall);
  for (int f = 0; f < wall; ++f)  // the bore faces the axis: reversed
    m.faces.col(wall + f) << i.faces(0, f) + ring, i.faces(2, f) + ring, i.faces(1, f) + ring;
  int f = 2 * wall;
  for (int k = 0; k < sides; ++k) {
    const int k1 = (k + 1) % sides, last = (n - 1) * sides;
    m.faces.col(f++) << ring + k, k1, k;  // start annulus, facing back along the route
    m.faces.col(f++) << ring + k, ring + k1, k1;
    m.faces.col(f++) << ring + last + k, last + k, last + k1;  // end annulus
    m.faces.col(f++) << ring + last + k, last + k1, ring + last + k1;
  }
  return m;
}

TEST(MeshFile, AHoseWithItsBoreIsOneCableWithBothDiameters) {
  const double outer = 0.010, bore = 0.006;
  const Polyline truth = SampleCurve(BentRoute, 4001);
  const TriangleMesh hose = HoseMesh(SampleCurve(BentRoute, 161), outer, bore, 32);
  const auto path = (testing::FreshTempDir("mesh_hose") / "hose.stl").string();
  WriteMeshFile(path, hose, 0.001);
  const MeshContents contents = ReadMeshContents(path, 0.001);
  EXPECT_TRUE(contents.parts.empty()) << contents.parts.front().reason;
  ASSERT_EQ(contents.tubes.size(), 1u);
  const MeshTube& tube = contents.tubes[0];
  EXPECT_NEAR(tube.diameter, outer, 0.01 * outer);
  EXPECT_NEAR(tube.inner_diameter, bore, 0.01 * bore);
  EXPECT_LT(MaxDistanceToPolyline(tube.centreline, truth), 0.01 * outer);
  EXPECT_LT(MaxDistanceToPolyline(truth, tube.centreline), 0.01 * outer);
  // The same walls without the bore: a solid tube, no inner diameter.
  WriteMeshFile(path, SweepTubeMesh(SampleCurve(BentRoute, 161), outer, 32), 0.001);
  const std::vector<MeshTube> solid = ReadMeshFile(path, 0.001);
  ASSERT_EQ(solid.size(), 1u);
  EXPECT_EQ(solid[0].inner_diameter, 0.0);
}

// A finely tessellated 0.92 m S-shaped tube (64 sides, 60k triangles, a 3 MB STL): one cable,
// not several around the doubled skeleton paths the flow leaves along it (before: three cables
// around a 41 mm spur running beside the axis), on its route within 1 % of the diameter.
TEST(MeshFile, AFinelyTessellatedLongTubeIsOneCableOnItsRoute) {
  const double diameter = 0.010;
  const auto route = [](double t) {
    return Vec3(0.8 * t, 0.1 * std::sin(2 * M_PI * t), 0.05 * std::sin(M_PI * t));
  };
  const Polyline truth = SampleCurve(route, 20001);
  const TriangleMesh tube = SweepTubeMesh(SampleCurve(route, 470), diameter, 64);
  const auto path = (testing::FreshTempDir("mesh_long") / "long_tube.stl").string();
  WriteMeshFile(path, tube, 0.001);
  const std::vector<MeshTube> tubes = ReadMeshFile(path, 0.001);
  ASSERT_EQ(tubes.size(), 1u);
  EXPECT_NEAR(tubes[0].centreline.ChordLength(), truth.ChordLength(), 0.01 * diameter);
  std::printf("long STL tube (%ld triangles): centreline max %.2e m from the route\n",
              static_cast<long>(tube.faces.cols()), MaxDistanceToPolyline(tubes[0].centreline, truth));
  EXPECT_LT(MaxDistanceToPolyline(tubes[0].centreline, truth), 0.01 * diameter);
  EXPECT_LT(MaxDistanceToPolyline(truth, tubes[0].centreline), 0.01 * diameter);
}

// A real export (tests/data/mesh/README.md): a straight 20 mm core end whose curve skeleton
// folds into a Z where the section changes. The route runs straight through, never back.
TEST(MeshFile, ASkeletonThatFoldsBackGivesARouteThatDoesNot) {
  const MeshContents contents = ReadMeshContents(
      (testing::SourceDir() / "tests/data/mesh/freecad_core_end.stl").string(), 0.001, 0.0);
  ASSERT_EQ(contents.tubes.size(), 1u);
  const Polyline& route = contents.tubes[0].centreline;
  const double chord = (route.points.col(route.size() - 1) - route.points.col(0)).norm();
  EXPECT_NEAR(chord, 0.020, 2e-4);
  EXPECT_NEAR(route.ChordLength(), chord, 1e-4);  // straight: no Z of 2 x 2.9 mm
  for (int i = 1; i + 1 < route.size(); ++i) {
    const Vec3 a = route.points.col(i) - route.points.col(i - 1);
    const Vec3 b = route.points.col(i + 1) - route.points.col(i);
    EXPECT_GT(a.dot(b), 0.0) << "turns back at station " << i;
  }
}

TEST(MeshFile, SampleStlHasTwoBentTubes) {
  const auto path = (testing::SourceDir() / "samples/harness/bent_tubes.stl").string();
  std::vector<MeshTube> tubes = ReadMeshFile(path, 0.001);
  ASSERT_EQ(tubes.size(), 2u);
  std::sort(tubes.begin(), tubes.end(), [](auto& a, auto& b) { return a.diameter > b.diameter; });
  // See formats/cad/tools/make_sample_harness.cc: 10 mm along 100 + quarter arc R60 + 140 mm,
  // 8 mm along an S-shaped spline from (0, 100, 50) to (240, 100, 50) mm.
  EXPECT_NEAR(tubes[0].diameter, 0.010, 0.0001);
  EXPECT_NEAR(tubes[1].diameter, 0.008, 0.00008);
  EXPECT_NEAR(tubes[0].centreline.ChordLength(), 0.1 + 0.03 * M_PI + 0.14, 0.001);
  EXPECT_NEAR((tubes[0].centreline.points.col(0) - Vec3(0, 0, 0)).norm(), 0, 0.0001);
  EXPECT_NEAR((tubes[0].centreline.points.rightCols<1>() - Vec3(0.16, 0.2, 0)).norm(), 0, 0.0001);
  EXPECT_NEAR((tubes[1].centreline.points.col(0) - Vec3(0, 0.1, 0.05)).norm(), 0, 0.00008);
  EXPECT_NEAR((tubes[1].centreline.points.rightCols<1>() - Vec3(0.24, 0.1, 0.05)).norm(), 0, 0.00008);
}

TEST(MeshFile, ObjRoundTripKeepsTheMesh) {
  const TriangleMesh tube = SweepTubeMesh(SampleCurve(BentRoute, 21), 0.008, 12);
  const auto path = (testing::FreshTempDir("mesh_obj") / "tube.obj").string();
  WriteMeshFile(path, tube, 0.001);
  const TriangleMesh back = ReadTriangleMesh(path, 0.001);
  EXPECT_EQ(back.vertices.cols(), tube.vertices.cols());
  EXPECT_EQ(back.faces.cols(), tube.faces.cols());
  EXPECT_TRUE(testing::MatricesNear(back.vertices.rowwise().maxCoeff(),
                                    tube.vertices.rowwise().maxCoeff(), 1e-6));
}

TEST(MeshFile, BadInputGivesOneLineFileErrors) {
  const auto dir = testing::FreshTempDir("mesh_bad");
  auto write = [&](const std::string& name, const std::string& text) {
    const auto p = (dir / name).string();
    std::ofstream(p, std::ios::binary) << text;
    return p;
  };
  EXPECT_THROW_WITH(ReadMeshFile((dir / "missing.stl").string(), 0.001), FileError, "no such file");
  EXPECT_THROW_WITH(ReadMeshFile(write("empty.stl", ""), 0.001), FileError, "empty");
  EXPECT_THROW_WITH(ReadMeshFile(write("garbage.ply", "no mesh here\n\x01\x02"), 0.001), FileError,
                    "not a readable mesh");
  // A cube is closed and manifold but not a tube.
  TriangleMesh cube;
  cube.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i) cube.vertices.col(i) << 0.02 * (i & 1), 0.02 * ((i >> 1) & 1), 0.02 * (i >> 2);
  cube.faces.resize(3, 12);
  cube.faces << 0, 0, 4, 4, 0, 0, 2, 2, 0, 0, 1, 1,
                2, 3, 5, 7, 1, 5, 6, 7, 4, 6, 3, 7,
                3, 1, 7, 6, 5, 4, 7, 3, 6, 2, 7, 5;
  const auto cube_path = (dir / "cube.stl").string();
  WriteMeshFile(cube_path, cube, 0.001);
  EXPECT_THROW_WITH(ReadMeshFile(cube_path, 0.001), FileError, "not a tube");
  // An open surface (one triangle) cannot be skeletonised.
  TriangleMesh open;
  open.vertices = Eigen::Matrix3d::Identity();
  open.faces = Eigen::Matrix3Xi(3, 1);
  open.faces << 0, 1, 2;
  const auto open_path = (dir / "open.stl").string();
  WriteMeshFile(open_path, open, 0.001);
  EXPECT_THROW_WITH(ReadMeshFile(open_path, 0.001), FileError, "not a closed surface");
  EXPECT_THROW_WITH(WriteMeshFile((dir / "x.dxf").string(), cube, 0.001), FileError, "extension");
  // A binary STL whose second vertex is NaN: said so, not blamed on the surface.
  std::string stl(80, ' ');
  const auto put = [&](const void* p, std::size_t n) { stl.append(static_cast<const char*>(p), n); };
  const std::uint32_t count = 1;
  put(&count, 4);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float floats[12] = {0, 0, 1, 0, 0, 0, 7, nan, 5, 0, 2, 0};
  put(floats, sizeof floats);
  stl.append(2, '\0');
  EXPECT_THROW_WITH(ReadMeshFile(write("nan.stl", stl), 0.001), FileError, "not a finite number");
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

TEST(MeshFile, BranchedTubesSplitIntoRoutesAtTheBranchPoint) {
  const auto path = (testing::SourceDir() / "samples/harness/branched_tubes.stl").string();
  const std::vector<MeshTube> tubes = ReadMeshFile(path, 0.001);
  // See make_sample_harness.cc: three 10 mm arms fused at the origin.
  ASSERT_EQ(tubes.size(), 3u);
  const std::vector<Vec3> caps{{0.12, 0, 0}, {-0.05, 0.05 * std::sqrt(3.0), 0}, {-0.055, -0.07, 0.05}};
  std::vector<Vec3> near_ends;
  for (const Vec3& cap : caps) {
    int found = 0;
    for (const MeshTube& t : tubes) {
      const Vec3 a = t.centreline.points.col(0), b = t.centreline.points.rightCols<1>();
      const bool at_start = (a - cap).norm() < (b - cap).norm();
      if (((at_start ? a : b) - cap).norm() > 0.0001) continue;  // 1 % of the diameter
      ++found;
      EXPECT_NEAR(t.diameter, 0.010, 0.0001);
      near_ends.push_back(at_start ? b : a);
    }
    EXPECT_EQ(found, 1) << cap.transpose();
  }
  // The arms meet at one point of the skeleton, inside the fused junction.
  ASSERT_EQ(near_ends.size(), 3u);
  EXPECT_LT((near_ends[0] - near_ends[1]).norm(), 1e-12);
  EXPECT_LT((near_ends[0] - near_ends[2]).norm(), 1e-12);
  EXPECT_LT(near_ends[0].norm(), 0.010);
}

// The skeleton runs in a fresh helper process: what this process read before, and a second read
// on another thread at the same time, must not change a route (before, the branched sample's
// arms came out 0.5 mm longer or shorter after another mesh, and again otherwise with 2 threads).
TEST(MeshFile, RoutesDoNotDependOnWhatTheProcessDidBefore) {
  ASSERT_FALSE(HelperPath(kMeshHelper).empty()) << "the mesh helper is not built";
  const auto branched = (testing::SourceDir() / "samples/harness/branched_tubes.stl").string();
  const auto bent = (testing::SourceDir() / "samples/harness/bent_tubes.stl").string();
  const std::vector<MeshTube> first = ReadMeshFile(branched, 0.001);
  (void)ReadMeshFile(bent, 0.001);
  std::vector<MeshTube> again, beside;
  std::thread other([&] { beside = ReadMeshFile(bent, 0.001); });
  again = ReadMeshFile(branched, 0.001);
  other.join();
  ASSERT_EQ(again.size(), first.size());
  for (size_t i = 0; i < first.size(); ++i) {
    ASSERT_EQ(again[i].centreline.points.cols(), first[i].centreline.points.cols()) << i;
    EXPECT_EQ((again[i].centreline.points - first[i].centreline.points).cwiseAbs().maxCoeff(), 0.0)
        << "tube " << i;
    EXPECT_EQ(again[i].diameter, first[i].diameter) << "tube " << i;
  }
  EXPECT_EQ(beside.size(), 2u);
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

// `mesh` written as a millimetre STL and read back.
MeshContents ReadBackAsStl(const TriangleMesh& mesh, const std::string& tag) {
  const auto path = (testing::FreshTempDir(tag) / (tag + ".stl")).string();
  WriteMeshFile(path, mesh, 0.001);
  return ReadMeshContents(path, 0.001);
}

TriangleMesh Concatenated(const std::vector<TriangleMesh>& parts) {
  TriangleMesh m;
  Eigen::Index nv = 0, nf = 0;
  for (const TriangleMesh& p : parts) {
    nv += p.vertices.cols();
    nf += p.faces.cols();
  }
  m.vertices.resize(3, nv);
  m.faces.resize(3, nf);
  Eigen::Index v = 0, f = 0;
  for (const TriangleMesh& p : parts) {
    m.vertices.middleCols(v, p.vertices.cols()) = p.vertices;
    m.faces.middleCols(f, p.faces.cols()) = p.faces.array() + static_cast<int>(v);
    v += p.vertices.cols();
    f += p.faces.cols();
  }
  return m;
}

// A coax cable drawn as concentric closed shells (conductor, dielectric, jacket; each a
// component of its own, nested): one cable of the jacket's diameter with its layers listed,
// not three cables on one axis (which met at both ends as a loop and failed to relax).
TEST(MeshFile, ConcentricShellsAreOneCableOfTheOuterDiameterWithItsLayers) {
  const Polyline route = SampleCurve(BentRoute, 161);
  const TriangleMesh coax = Concatenated(
      {SweepTubeMesh(route, 0.0012, 32), SweepTubeMesh(route, 0.004, 32), SweepTubeMesh(route, 0.0052, 32)});
  const MeshContents contents = ReadBackAsStl(coax, "mesh_coax");
  EXPECT_TRUE(contents.parts.empty()) << contents.parts.front().reason;
  ASSERT_EQ(contents.tubes.size(), 1u);
  const MeshTube& cable = contents.tubes[0];
  EXPECT_NEAR(cable.diameter, 0.0052, 0.01 * 0.0052);
  EXPECT_EQ(cable.inner_diameter, 0.0);
  ASSERT_EQ(cable.layers.size(), 2u);
  EXPECT_NEAR(cable.layers[0], 0.004, 0.01 * 0.004);
  EXPECT_NEAR(cable.layers[1], 0.0012, 0.01 * 0.0012);
  EXPECT_LT(MaxDistanceToPolyline(cable.centreline, SampleCurve(BentRoute, 4001)), 0.01 * 0.0052);
}

// A hose with a core through its bore: one cable, the bore filled; a tube beside the hose (not
// on its axis) stays a cable of its own.
TEST(MeshFile, ACoreInAHoseBoreIsALayerButATubeBesideItIsNot) {
  const Polyline route = SampleCurve(BentRoute, 161);
  Polyline beside = route;
  beside.points.row(2).array() += 0.02;
  const TriangleMesh m = Concatenated({HoseMesh(route, 0.010, 0.006, 32), SweepTubeMesh(route, 0.0058, 32),
                                       SweepTubeMesh(beside, 0.004, 32)});
  const MeshContents contents = ReadBackAsStl(m, "mesh_hose_core");
  ASSERT_EQ(contents.tubes.size(), 2u);
  const MeshTube& hose = contents.tubes[0].diameter > contents.tubes[1].diameter ? contents.tubes[0]
                                                                                 : contents.tubes[1];
  EXPECT_NEAR(hose.diameter, 0.010, 0.01 * 0.010);
  EXPECT_EQ(hose.inner_diameter, 0.0);
  ASSERT_EQ(hose.layers.size(), 1u);
  EXPECT_NEAR(hose.layers[0], 0.0058, 0.01 * 0.0058);
}

// The same layers exported as touching solids (a core, and a hose whose bore is the core's
// surface, each meshed on its own): the shared surface is there twice, facing both ways, and
// welded it made nothing a closed surface. Read as the one body it bounds: one cable.
TEST(MeshFile, LayersExportedAsTouchingSolidsAreOneCable) {
  const Polyline route = SampleCurve(BentRoute, 161);
  const TriangleMesh m = Concatenated({SweepTubeMesh(route, 0.006, 32), HoseMesh(route, 0.010, 0.006, 32)});
  const MeshContents contents = ReadBackAsStl(m, "mesh_touching_layers");
  EXPECT_TRUE(contents.parts.empty()) << contents.parts.front().reason;
  ASSERT_EQ(contents.tubes.size(), 1u);
  EXPECT_NEAR(contents.tubes[0].diameter, 0.010, 0.01 * 0.010);
  EXPECT_EQ(contents.tubes[0].inner_diameter, 0.0);
  EXPECT_LT(MaxDistanceToPolyline(contents.tubes[0].centreline, SampleCurve(BentRoute, 4001)), 0.01 * 0.010);
}

// A coarse tessellation (12 sides): the cuts through its facets lie inside the surface (a 12-gon
// averages 1.1 % inside its circle), its vertices on it. The slice fits on the vertices give
// the diameter and keep the route on the axis.
TEST(MeshFile, ACoarselyTessellatedTubeHasItsTrueDiameterFromItsVertices) {
  const double diameter = 0.010;
  const TriangleMesh tube = SweepTubeMesh(SampleCurve(BentRoute, 81), diameter, 12);
  const std::vector<MeshTube> tubes = ReadBackAsStl(tube, "mesh_coarse").tubes;
  ASSERT_EQ(tubes.size(), 1u);
  std::printf("12-sided tube: diameter %.5f mm (drawn 10), route max %.2e m off\n",
              1e3 * tubes[0].diameter, MaxDistanceToPolyline(tubes[0].centreline, SampleCurve(BentRoute, 4001)));
  EXPECT_NEAR(tubes[0].diameter, diameter, 1e-3 * diameter);
  EXPECT_LT(MaxDistanceToPolyline(tubes[0].centreline, SampleCurve(BentRoute, 4001)), 0.01 * diameter);
}

// A hose drawn as two closed shells, its bore's faces pointing into the hollow: one hollow
// cable, the bore its inner diameter (not a layer).
TEST(MeshFile, ABoreDrawnAsAnInwardShellIsTheHollowOfItsTube) {
  const Polyline route = SampleCurve(BentRoute, 161);
  TriangleMesh bore = SweepTubeMesh(route, 0.006, 32);
  bore.faces.row(1).swap(bore.faces.row(2));
  const MeshContents contents =
      ReadBackAsStl(Concatenated({SweepTubeMesh(route, 0.010, 32), bore}), "mesh_bore_shell");
  ASSERT_EQ(contents.tubes.size(), 1u);
  EXPECT_NEAR(contents.tubes[0].diameter, 0.010, 0.01 * 0.010);
  EXPECT_NEAR(contents.tubes[0].inner_diameter, 0.006, 0.01 * 0.006);
  EXPECT_TRUE(contents.tubes[0].layers.empty());
}

MeshContents ReadSupplierMesh(const std::string& name) {
  return ReadMeshContents((testing::SourceDir() / "tests/data/supplier" / name).string(), 0.001);
}

// A coax whose four layers (a 6 mm jacket, a shield and a dielectric, hollow, each touching the
// next, and the conductor) were meshed one by one with their own numbers of sides: where they
// touch, their vertices coincide only where those numbers agree, and welded, the layers' rims
// and seams are edges of four faces (tests/data/supplier/README.md).
TEST(MeshFile, ACoaxOfTouchingLayersEachTessellatedOnItsOwnIsOneCable) {
  const MeshContents contents = ReadSupplierMesh("coax_layers.stl");
  EXPECT_TRUE(contents.parts.empty()) << contents.parts.front().reason;
  ASSERT_EQ(contents.tubes.size(), 1u);
  const MeshTube& coax = contents.tubes[0];
  EXPECT_NEAR(coax.diameter, 0.006, 0.01 * 0.006);
  EXPECT_EQ(coax.inner_diameter, 0.0);  // the conductor fills the dielectric's bore
  EXPECT_EQ(coax.layers.size(), 3u);
  EXPECT_NEAR(coax.centreline.ChordLength(), 0.12 + 0.025 * M_PI, 0.002);
}

// A stethoscope's ear tube: 3.2 mm with a 2 mm bore, bent, its rims rounded into the bore (no
// sharp edge to tell the outer wall from the bore by).
TEST(MeshFile, AThinBentHoseWithRoundedRimsIsOneHollowCable) {
  const MeshContents contents = ReadSupplierMesh("ear_tube.stl");
  EXPECT_TRUE(contents.parts.empty()) << contents.parts.front().reason;
  ASSERT_EQ(contents.tubes.size(), 1u);
  EXPECT_NEAR(contents.tubes[0].diameter, 0.0032, 0.01 * 0.0032);
  EXPECT_NEAR(contents.tubes[0].inner_diameter, 0.002, 0.02 * 0.002);
  // 60 mm, 100 degrees of a 40 mm radius and 30 mm, and the lips' rounding at both ends.
  EXPECT_NEAR(contents.tubes[0].centreline.ChordLength(), 0.09 + 0.04 * 100 * M_PI / 180, 0.001);
}

// Meshers write the vertices of the edge between two faces of a CAD body once per face, a few
// rounding units apart: the tube is one closed surface all the same.
TEST(MeshFile, AFaceSeamWhoseVerticesDifferByRoundingIsNoCrack) {
  const int sides = 16, rings = 41, seam = 20;
  TriangleMesh tube = SweepTubeMesh(SampleCurve(BentRoute, rings), 0.008, sides);
  const Eigen::Index nv = tube.vertices.cols();
  tube.vertices.conservativeResize(3, nv + sides);
  for (int k = 0; k < sides; ++k)
    tube.vertices.col(nv + k) = tube.vertices.col(seam * sides + k) + Vec3(3e-9, -2e-9, 4e-9);
  // The faces beyond the seam use the copies.
  for (Eigen::Index f = 0; f < 2 * (rings - 1) * sides; ++f)
    if (f / (2 * sides) >= seam)
      for (int c = 0; c < 3; ++c)
        if (tube.faces(c, f) / sides == seam)
          tube.faces(c, f) = static_cast<int>(nv + tube.faces(c, f) % sides);
  const MeshContents contents = RecoverMeshContents(tube);
  EXPECT_TRUE(contents.parts.empty()) << contents.parts.front().reason;
  ASSERT_EQ(contents.tubes.size(), 1u);
  EXPECT_NEAR(contents.tubes[0].centreline.ChordLength(),
              SampleCurve(BentRoute, 4001).ChordLength(), 1e-3);
}

// Where a tube ends in a tight bend (11 1/m at the cap), the route's last points (a blend onto
// the cap over three radii) give its direction to a milliradian only: the cap's normal is the
// end's direction, exactly.
TEST(MeshFile, ATubeEndingInATightBendEndsAlongItsCapNormal) {
  const double radius = 1.0 / 11, straight = 0.1, turn = M_PI / 3;
  const auto route = [&](double u) -> Vec3 {
    const double s = u * (straight + radius * turn);
    if (s <= straight) return {s, 0, 0};
    const double a = (s - straight) / radius;
    return {straight + radius * std::sin(a), 0, radius * (1 - std::cos(a))};
  };
  const Polyline drawn = SampleCurve(route, 390);  // a ring every 0.5 mm
  const std::vector<MeshTube> tubes = RecoverTubes(SweepTubeMesh(drawn, 0.008, 24));
  ASSERT_EQ(tubes.size(), 1u);
  const MeshTube& tube = tubes[0];
  ASSERT_TRUE(tube.start_direction && tube.end_direction);
  // The sweep's caps are square to its centreline's first and last chords.
  const Eigen::Index n = drawn.points.cols();
  const Vec3 start_cap = (drawn.points.col(1) - drawn.points.col(0)).normalized();
  const Vec3 end_cap = (drawn.points.col(n - 1) - drawn.points.col(n - 2)).normalized();
  EXPECT_LT(std::acos(std::min(1.0, tube.start_direction->dot(start_cap))), 1e-4);
  EXPECT_LT(std::acos(std::min(1.0, tube.end_direction->dot(end_cap))), 1e-4);
}

}  // namespace
}  // namespace cablefit
