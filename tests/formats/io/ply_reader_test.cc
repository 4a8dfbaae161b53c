#include "cablefit/formats/ply_reader.h"

#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cstdint>
#include <cstring>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/case_reader.h"
#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using testing::FreshTempDir;
using testing::MatricesNear;
using testing::ReadText;
using testing::WriteText;

// Appends `value` as T in the requested byte order.
template <typename T>
void Put(std::string* out, T value, bool big_endian) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big_endian == (std::endian::native == std::endian::little))
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  out->append(b, sizeof(T));
}

TEST(PlyReader, ReadsEveryPublicScan) {
  int scans = 0;
  for (const auto& e : fs::directory_iterator(testing::PublicCasesDir())) {
    const auto ply = e.path() / "scan.ply";
    if (!fs::exists(ply)) continue;
    SCOPED_TRACE(ply.string());
    ++scans;
    const std::string text = ReadText(ply);
    EXPECT_NE(text.find("format binary_little_endian 1.0"), std::string::npos);
    const std::string tag = "element vertex ";
    const auto at = text.find(tag);
    ASSERT_NE(at, std::string::npos);
    const int declared = std::stoi(text.substr(at + tag.size(), 20));
    const PointCloud cloud = ReadPly(ply.string());
    EXPECT_EQ(cloud.size(), declared);
    ASSERT_TRUE(cloud.points.allFinite());
    // A scan of the cable lies within a cable length of its first clamp.
    const RecordingCase rc = ReadRecordingCase(e.path().string());
    const Vec3 c0 = rc.nominal.supports[0].position;
    const double far = (cloud.points.colwise() - c0).colwise().norm().maxCoeff();
    EXPECT_LT(far, rc.nominal.length + rc.nominal.material.diameter);
    EXPECT_GT(far, 0.2 * rc.nominal.length);
  }
  EXPECT_EQ(scans, 8);
}

TEST(PlyReader, WriteReadRoundTripBinaryAndAscii) {
  const auto dir = FreshTempDir("io");
  PointCloud cloud;
  cloud.points = Eigen::Matrix3Xd::Random(3, 123) * (1.0 / 7.0);
  for (bool binary : {true, false}) {
    const auto path = (dir / (binary ? "b.ply" : "a.ply")).string();
    WritePly(path, cloud, binary);
    EXPECT_TRUE(MatricesNear(ReadPly(path).points, cloud.points, 0.0)) << path;
  }
  cloud.points(2, 7) = std::nan("");
  EXPECT_THROW_WITH(WritePly((dir / "b.ply").string(), cloud), FileError, "non-finite");
  EXPECT_EQ(ReadPly((dir / "b.ply").string()).size(), 123);  // previous file intact
  WritePly((dir / "empty.ply").string(), PointCloud{});
  EXPECT_EQ(ReadPly((dir / "empty.ply").string()).size(), 0);
}

TEST(PlyReader, AsciiWithCommentsExtraPropertiesAndFaces) {
  const auto dir = FreshTempDir("io");
  WriteText(dir / "a.ply",
            "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info none\r\n"
            "element vertex 3\r\nproperty uchar red\r\nproperty float x\r\nproperty float y\r\n"
            "property float z\r\nproperty list uchar int extra\r\n"
            "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
            "255 1 2 3 2 7 8\r\n0 -4.5 5e-1 6 0\r\n12 7 8 9 1 5\r\n3 0 1 2\r\n");
  const PointCloud cloud = ReadPly((dir / "a.ply").string());
  ASSERT_EQ(cloud.size(), 3);
  Eigen::Matrix3Xd expected(3, 3);
  expected << 1, -4.5, 7, 2, 0.5, 8, 3, 6, 9;
  EXPECT_TRUE(MatricesNear(cloud.points, expected, 0.0));
}

std::string BinaryWithFacesFirst(bool big) {
  // A face element before the vertices (lists to skip), and vertex properties of every type.
  std::string ply = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\ncomment test\n"
                    "element face 2\nproperty list uint8 int32 vertex_indices\nproperty short tag\n"
                    "element vertex 2\nproperty char a\nproperty uchar b\nproperty int16 c\n"
                    "property ushort d\nproperty double x\nproperty int e\nproperty uint f\n"
                    "property float32 y\nproperty float64 z\nproperty float g\n"
                    "element extra 1\nproperty int8 q\nend_header\n";
  Put<std::uint8_t>(&ply, 3, big);
  for (int i : {0, 1, 2}) Put<std::int32_t>(&ply, i, big);
  Put<std::int16_t>(&ply, -5, big);
  Put<std::uint8_t>(&ply, 0, big);
  Put<std::int16_t>(&ply, 9, big);
  for (int v = 0; v < 2; ++v) {
    Put<std::int8_t>(&ply, -1, big);
    Put<std::uint8_t>(&ply, 200, big);
    Put<std::int16_t>(&ply, -300, big);
    Put<std::uint16_t>(&ply, 60000, big);
    Put<double>(&ply, 0.1 + v, big);
    Put<std::int32_t>(&ply, -7, big);
    Put<std::uint32_t>(&ply, 7, big);
    Put<float>(&ply, 0.25f * static_cast<float>(v + 1), big);
    Put<double>(&ply, -1.0 / 3.0, big);
    Put<float>(&ply, 1e30f, big);
  }
  Put<std::int8_t>(&ply, 1, big);
  return ply;
}

TEST(PlyReader, BinaryBothEndiannessesAllScalarTypes) {
  const auto dir = FreshTempDir("io");
  for (bool big : {false, true}) {
    const auto path = dir / (big ? "big.ply" : "little.ply");
    WriteText(path, BinaryWithFacesFirst(big));
    const PointCloud cloud = ReadPly(path.string());
    ASSERT_EQ(cloud.size(), 2) << path;
    EXPECT_EQ(cloud.points(0, 1), 1.1);
    EXPECT_EQ(cloud.points(1, 0), 0.25);
    EXPECT_EQ(cloud.points(1, 1), 0.5);
    EXPECT_EQ(cloud.points(2, 0), -1.0 / 3.0);
  }
}

TEST(PlyReader, HugeHeaderCountFailsImmediately) {
  const auto dir = FreshTempDir("io");
  for (const char* format : {"binary_little_endian", "ascii"}) {
    const auto path = (dir / (std::string(format) + ".ply")).string();
    WriteText(path, std::string("ply\nformat ") + format +
                        " 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float y\n"
                        "property float z\nend_header\n0 0 0\n");
    const auto start = std::chrono::steady_clock::now();
    EXPECT_THROW_WITH(ReadPly(path), FileError, "header declares 1000000000000 'vertex' elements");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  }
}

TEST(PlyReader, NonFiniteCoordinatesAreCounted) {
  const auto dir = FreshTempDir("io");
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  const float values[12] = {0, 0, 0, std::nanf(""), 0, 0, 1, 1, 1, 0, HUGE_VALF, std::nanf("")};
  for (float v : values) Put<float>(&ply, v, false);
  WriteText(dir / "n.ply", ply);
  EXPECT_THROW_WITH(ReadPly((dir / "n.ply").string()), FileError,
                    "2 of 4 vertices have non-finite coordinates");
  WriteText(dir / "a.ply",
            "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
            "property double z\nend_header\n1 2 nan\n1 2 3\n");
  EXPECT_THROW_WITH(ReadPly((dir / "a.ply").string()), FileError, "1 of 2 vertices");
}

struct BadPly {
  const char* label;
  std::string text;
  const char* message;
};

class PlyReaderRejects : public ::testing::TestWithParam<BadPly> {};

TEST_P(PlyReaderRejects, WithMessage) {
  const auto dir = FreshTempDir(std::string("io-") + GetParam().label);
  const auto path = (dir / "bad.ply").string();
  WriteText(path, GetParam().text);
  try {
    ReadPly(path);
    ADD_FAILURE() << "accepted";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find(GetParam().message), std::string::npos) << e.what();
  }
}

const std::string kXyzFloat =
    "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n";

std::string TruncatedBinary() {
  std::string ply = "ply\nformat binary_little_endian 1.0\n" + kXyzFloat + "end_header\n";
  for (int i = 0; i < 5; ++i) Put<float>(&ply, 1.0f, false);  // 5 of 6 floats
  return ply;
}

std::string TruncatedList() {
  std::string ply =
      "ply\nformat binary_big_endian 1.0\nelement face 1\nproperty list uchar int idx\n" +
      kXyzFloat + "end_header\n";
  Put<std::uint8_t>(&ply, 200, true);  // claims 200 indices
  for (int i = 0; i < 6; ++i) Put<float>(&ply, 1.0f, true);
  return ply;
}

const BadPly kBadPlys[] = {
    {"empty", "", "not a PLY file"},
    {"magic", "plyx\nformat ascii 1.0\nend_header\n", "not a PLY file"},
    {"no_format", "ply\n" + kXyzFloat + "end_header\n0 0 0\n1 1 1\n", "missing format line"},
    {"bad_format", "ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown format 'binary_middle_endian'"},
    {"version", "ply\nformat ascii 2.0\nend_header\n", "unsupported PLY version '2.0'"},
    {"no_end", "ply\nformat ascii 1.0\n" + kXyzFloat, "missing end_header"},
    {"no_end_data", "ply\nformat ascii 1.0\n" + kXyzFloat + "0 0 0\n1 1 1\n",
     "unexpected keyword '0' (missing end_header?)"},
    {"no_vertex", "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int i\nend_header\n",
     "no 'vertex' element"},
    {"no_z", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
     "vertex has no property 'z'"},
    {"int_x", "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
     "'x' must be float or double"},
    {"bad_type", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
     "unknown property type 'float128'"},
    {"orphan_property", "ply\nformat ascii 1.0\nproperty float x\nend_header\n", "property before any element"},
    {"negative_count", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", "malformed element line"},
    {"float_list_count", "ply\nformat ascii 1.0\nelement f 1\nproperty list float int i\nend_header\n",
     "list count type must be an integer"},
    {"truncated_binary", TruncatedBinary(), "header declares 2 'vertex' elements but only 20 bytes"},
    {"truncated_list", TruncatedList(), "truncated: file ends inside element 'face'"},
    {"truncated_ascii", "ply\nformat ascii 1.0\n" + kXyzFloat + "end_header\n0 0 0\n1 1         \n",
     "truncated: file ends before element 'vertex'"},
    {"ascii_text", "ply\nformat ascii 1.0\n" + kXyzFloat + "end_header\n0 0 0\n1 one 1\n",
     "element 'vertex': 'one' is not a number"},
    {"ascii_list_len", "ply\nformat ascii 1.0\nelement f 1\nproperty list uchar int i\n" + kXyzFloat +
                           "end_header\n-1\n0 0 0\n1 1 1\n",
     "invalid list length -1"},
};

INSTANTIATE_TEST_SUITE_P(Malformed, PlyReaderRejects, ::testing::ValuesIn(kBadPlys),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(PlyReader, MissingFile) {
  const auto dir = FreshTempDir("io");
  EXPECT_THROW_WITH(ReadPly((dir / "none.ply").string()), FileError, "no such file");
}

}  // namespace
}  // namespace cablefit
