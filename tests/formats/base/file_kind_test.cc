#include "cablefit/formats/file_kind.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

std::string Write(const std::string& name, const std::string& bytes) {
  return testing::WriteTempFile("file_kind", name, bytes);
}

TEST(FileKind, TheSamplesAreKnownByTheirContent) {
  const auto dir = testing::SourceDir();
  EXPECT_EQ(SniffFileKind((dir / "samples/harness/legacy_harness.step").string()), FileKind::kStep);
  EXPECT_EQ(SniffFileKind((dir / "samples/harness/legacy_harness.igs").string()), FileKind::kIges);
  EXPECT_EQ(SniffFileKind((dir / "samples/harness/bent_tubes.stl").string()), FileKind::kStl);
  EXPECT_EQ(SniffFileKind((dir / "samples/harness/harness.json").string()), FileKind::kJson);
  EXPECT_EQ(SniffFileKind((dir / "tests/data/cases/public/sample-none/scan.ply").string()),
            FileKind::kPlyPoints);
}

TEST(FileKind, TheNameDoesNotDecide) {
  EXPECT_EQ(SniffFileKind(Write("cloud.stl", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                             "property float x\nend_header\n0\n")),
            FileKind::kPlyPoints);
  EXPECT_EQ(SniffFileKind(Write("mesh.json", "ply\nformat ascii 1.0\nelement vertex 3\n"
                                             "property float x\nelement face 1\n"
                                             "property list uchar int vertex_indices\nend_header\n")),
            FileKind::kPlyMesh);
  EXPECT_EQ(SniffFileKind(Write("a.txt", "\xEF\xBB\xBF  {\"cable\": 1}")), FileKind::kJson);
  EXPECT_EQ(SniffFileKind(Write("b.dat", "# blender\nv 0 0 0\nv 1 0 0\n")), FileKind::kObj);
  EXPECT_EQ(SniffFileKind(Write("c.csv", "s,x,y,z\n0,0,0,0\n")), FileKind::kUnknown);
  EXPECT_EQ(SniffFileKind((testing::SourceDir() / "tests/data/kbl/kblxml_2.3sr-1_000971250_ltgs_getriebe_170718.kbl").string()),
            FileKind::kKbl);
  EXPECT_EQ(SniffFileKind(Write("d.xml", "<?xml version=\"1.0\"?>\n<other/>")), FileKind::kUnknown);
  EXPECT_EQ(SniffFileKind(Write("empty.step", "")), FileKind::kUnknown);
  EXPECT_EQ(SniffFileKind("/nonexistent/file.step"), FileKind::kUnknown);
  // A binary STL is recognised by its size: 80 header bytes, a count, 50 bytes per triangle.
  std::string stl(84 + 50, '\0');
  stl[80] = 1;
  EXPECT_EQ(SniffFileKind(Write("d.bin", stl)), FileKind::kStl);
  stl.push_back('\0');  // one byte too many: not an STL
  EXPECT_EQ(SniffFileKind(Write("e.bin", stl)), FileKind::kUnknown);
}

TEST(FileKind, EveryKindHasAName) {
  for (FileKind k : {FileKind::kStep, FileKind::kIges, FileKind::kJson, FileKind::kPlyMesh,
                     FileKind::kPlyPoints, FileKind::kStl, FileKind::kObj})
    EXPECT_FALSE(DescribeFileKind(k).empty());
  EXPECT_TRUE(DescribeFileKind(FileKind::kUnknown).empty());
}

}  // namespace
}  // namespace cablefit
