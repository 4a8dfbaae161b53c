// Binary STL: what is written reads back (count, coordinates as floats, facet normal from the
// winding), and a file whose size does not match its count is refused.
#include "cablefit/formats/stl_file.h"

#include <gtest/gtest.h>

#include <cstring>

#include "cablefit/core/base/errors.h"
#include "io_test_files.h"

namespace cablefit {
namespace {

TriangleMesh Tetrahedron() {
  TriangleMesh m;
  m.vertices.resize(3, 4);
  m.vertices << 0, 1, 0, 0,  //
      0, 0, 1, 0,            //
      0, 0, 0, 1;
  m.faces.resize(3, 4);
  m.faces << 0, 0, 0, 1,  //
      2, 1, 3, 2,         //
      1, 3, 2, 3;
  return m;
}

TEST(StlFile, WritesAndReadsBackATetrahedron) {
  const auto dir = testing::FreshTempDir("stl_file");
  const std::string path = (dir / "t.stl").string();
  const TriangleMesh m = Tetrahedron();
  WriteStl(path, m, "cablefit test");
  const std::string bytes = testing::ReadText(path);
  ASSERT_EQ(bytes.size(), 84u + 4 * 50);
  // First facet (0, 2, 1) lies in z = 0 and winds clockwise seen from +z: normal -z.
  float normal[3];
  std::memcpy(normal, bytes.data() + 84, 12);
  EXPECT_FLOAT_EQ(normal[2], -1.0f);
  const TriangleMesh back = ReadBinaryStl(path);
  ASSERT_EQ(back.faces.cols(), 4);
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(back.vertices.col(back.faces(k, f)).isApprox(m.vertices.col(m.faces(k, f))))
          << f << " " << k;
  EXPECT_EQ(testing::ListDir(dir).size(), 1u);  // no temporary file left
}

TEST(StlFile, RefusesASizeThatDoesNotMatchTheCount) {
  const std::string bytes = EncodeStl(Tetrahedron(), "x");
  const std::string path = testing::WriteTempFile("stl_short", "t.stl", bytes.substr(0, 150));
  EXPECT_THROW(ReadBinaryStl(path), FileError);
}

TEST(StlFile, AHeaderStartingWithSolidIsRefused) {
  EXPECT_THROW(EncodeStl(Tetrahedron(), "solid x"), UsageError);
}

}  // namespace
}  // namespace cablefit
