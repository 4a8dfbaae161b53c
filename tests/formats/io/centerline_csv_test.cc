#include "cablefit/formats/centerline_csv.h"

#include <gtest/gtest.h>

#include "cablefit/core/base/errors.h"
#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using testing::FreshTempDir;
using testing::MatricesNear;
using testing::WriteText;

TEST(CenterlineCsv, ReadsPublicCenterlines) {
  // Given s runs from the first clamp to the last: 0 .. cable.length of the case.
  const struct {
    const char* name;
    double length;
    int rows;
  } kCases[] = {{"sample-none", 0.7553, 264},
                {"sample-support_contact", 0.6932, 247},
                {"sample-twist_preload", 0.4289, 249}};
  for (const auto& c : kCases) {
    SCOPED_TRACE(c.name);
    const auto path = testing::PublicCasesDir() / c.name / "centerline.csv";
    const Polyline line = ReadCenterlineCsv(path.string());
    ASSERT_EQ(line.size(), c.rows);
    ASSERT_EQ(line.s.size(), line.points.cols());
    EXPECT_EQ(line.s[0], 0.0);
    EXPECT_DOUBLE_EQ(line.s[line.size() - 1], c.length);
    // Measured points are noisy, so chords may exceed s slightly, but not by much.
    EXPECT_NEAR(line.ChordLength(), c.length, 0.01 * c.length);
  }
}

TEST(CenterlineCsv, GivenSIsKept) {
  const auto dir = FreshTempDir("io");
  WriteText(dir / "c.csv", "s,x,y,z\n0,0,0,0\n0.5,1,0,0\r\n\n2,1,1,0\n");
  const Polyline line = ReadCenterlineCsv((dir / "c.csv").string());
  ASSERT_EQ(line.size(), 3);
  EXPECT_EQ(line.s, Eigen::Vector3d(0, 0.5, 2));
  EXPECT_EQ(line.points.col(2), Eigen::Vector3d(1, 1, 0));
}

TEST(CenterlineCsv, CarriageReturnAloneEndsALine) {
  const auto dir = FreshTempDir("io");
  WriteText(dir / "mac.csv", "s,x,y,z\r0,0,0,0\r0.5,1,0,0\r2,1,1,0\r");
  const Polyline line = ReadCenterlineCsv((dir / "mac.csv").string());
  ASSERT_EQ(line.size(), 3);
  EXPECT_EQ(line.s, Eigen::Vector3d(0, 0.5, 2));
}

TEST(CenterlineCsv, EmptySOrNoSColumnGivesChordLengths) {
  const auto dir = FreshTempDir("io");
  WriteText(dir / "a.csv", "s,x,y,z\n,0,0,0\n,3,4,0\n,3,4,12\n");
  WriteText(dir / "b.csv", "z,y,x\n0,0,0\n0,4,3\n12,4,3\n");  // columns in any order
  for (const char* f : {"a.csv", "b.csv"}) {
    const Polyline line = ReadCenterlineCsv((dir / f).string());
    EXPECT_EQ(line.s, Eigen::Vector3d(0, 5, 17)) << f;
    EXPECT_EQ(line.points.col(1), Eigen::Vector3d(3, 4, 0)) << f;
  }
}

TEST(CenterlineCsv, WriteReadRoundTripIsExact) {
  const auto dir = FreshTempDir("io");
  Polyline line;
  line.points = Eigen::Matrix3Xd::Random(3, 50) * 0.37;
  line.ParameteriseByChords(0.1 / 3.0);
  const auto path = (dir / "sub" / "out.csv").string();
  WriteCenterlineCsv(path, line);
  EXPECT_EQ(testing::ReadText(path).substr(0, 8), "s,x,y,z\n");
  const Polyline back = ReadCenterlineCsv(path);
  EXPECT_TRUE(MatricesNear(back.points, line.points, 0.0));
  EXPECT_TRUE(MatricesNear(back.s, line.s, 0.0));

  line.s.resize(0);  // unknown s: written empty, read back as chords
  WriteCenterlineCsv(path, line);
  const Polyline chords = ReadCenterlineCsv(path);
  EXPECT_EQ(chords.s[0], 0.0);
  EXPECT_NEAR(chords.s[49], line.ChordLength(), 1e-12);
}

TEST(CenterlineCsv, WriterRejectsBadPolylinesWithoutTouchingTheFile) {
  const auto dir = FreshTempDir("io");
  const auto path = (dir / "out.csv").string();
  WriteText(path, "keep");
  Polyline line;
  line.points = Eigen::Matrix3Xd::Zero(3, 3);
  line.points(1, 1) = std::nan("");
  EXPECT_THROW_WITH(WriteCenterlineCsv(path, line), FileError, "non-finite");
  line.points(1, 1) = 0;
  line.s = Eigen::VectorXd::Zero(2);
  EXPECT_THROW_WITH(WriteCenterlineCsv(path, line), FileError, "2 arc lengths for 3 points");
  EXPECT_EQ(testing::ReadText(path), "keep");
  EXPECT_EQ(testing::ListDir(dir).size(), 1u);
}

struct BadCsv {
  const char* label;
  const char* text;
  const char* message;
};

class CenterlineCsvRejects : public ::testing::TestWithParam<BadCsv> {};

TEST_P(CenterlineCsvRejects, WithMessage) {
  const auto dir = FreshTempDir(std::string("io-") + GetParam().label);
  const auto path = (dir / "c.csv").string();
  WriteText(path, GetParam().text);
  EXPECT_THROW_WITH(ReadCenterlineCsv(path), FileError, GetParam().message);
}

const BadCsv kBadCenterlines[] = {
    {"empty", "", "is empty"},
    {"blank", "\n\n", "is empty"},
    {"no_z", "s,x,y\n0,0,0\n1,1,0\n", "missing column 'z'"},
    {"no_rows", "s,x,y,z\n", "has 0 point(s)"},
    {"one_row", "s,x,y,z\n0,1,2,3\n", "has 1 point(s)"},
    {"text", "s,x,y,z\n0,0,0,0\n1,abc,0,0\n", "line 3, column 'x' is not a number: 'abc'"},
    {"empty_cell", "s,x,y,z\n0,0,0,0\n1,1,,0\n", "line 3, column 'y' is empty"},
    {"nan", "s,x,y,z\n0,0,0,0\n1,1,NaN,0\n", "line 3, column 'y' is NaN"},
    {"inf", "s,x,y,z\n0,0,0,0\n1,1,0,-inf\n", "column 'z' is infinite"},
    {"overflow", "s,x,y,z\n0,0,0,0\n1,1e999,0,0\n", "column 'x' is infinite"},
    {"ragged", "s,x,y,z\n0,0,0,0\n1,1,0\n", "line 3 has 3 cells but the header has 4"},
    {"decreasing", "s,x,y,z\n0,0,0,0\n0.5,1,0,0\n0.4,2,0,0\n", "line 4: s decreases from 0.5 to 0.4"},
    {"partial_s", "s,x,y,z\n0,0,0,0\n,1,0,0\n", "filled in 1 of 2 rows"},
    {"bad_s", "s,x,y,z\n0,0,0,0\nnan,1,0,0\n", "column 's' is NaN"},
};

INSTANTIATE_TEST_SUITE_P(Malformed, CenterlineCsvRejects, ::testing::ValuesIn(kBadCenterlines),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(CenterlineCsv, MissingFile) {
  const auto dir = FreshTempDir("io");
  EXPECT_THROW_WITH(ReadCenterlineCsv((dir / "none.csv").string()), FileError, "no such file");
}

}  // namespace
}  // namespace cablefit
