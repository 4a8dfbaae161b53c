// Damaged PLY files must give a FileError or a valid cloud, never a crash or a huge allocation
// (run under ASan/UBSan with -DCABLEFIT_SANITIZE=ON to make this bite).
#include <gtest/gtest.h>

#include <random>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/ply_reader.h"
#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

std::string SmallPly(bool binary) {
  const auto dir = testing::FreshTempDir("io-src");
  PointCloud cloud;
  cloud.points = Eigen::Matrix3Xd::Random(3, 5);
  const auto path = dir / "p.ply";
  WritePly(path.string(), cloud, binary);
  std::string text = testing::ReadText(path);
  // Add a face element with a list after the vertices so list parsing is damaged too.
  const std::string marker = "end_header\n";
  text.insert(text.find(marker), "element face 1\nproperty list uchar int vertex_indices\n");
  text += binary ? std::string("\x03\0\0\0\0\x01\0\0\0\x02\0\0\0", 13) : std::string("3 0 1 2\n");
  return text;
}

// Returns true when read; false on FileError. Anything else fails the test.
bool ReadsOrRejects(const std::filesystem::path& path) {
  try {
    const PointCloud cloud = ReadPly(path.string());
    EXPECT_TRUE(cloud.points.allFinite());
    return true;
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return false;
  }
}

TEST(PlyRobustness, EveryTruncation) {
  const auto dir = testing::FreshTempDir("io");
  for (bool binary : {true, false}) {
    const std::string full = SmallPly(binary);
    ASSERT_TRUE(ReadsOrRejects((testing::WriteText(dir / "full.ply", full), dir / "full.ply")));
    int rejected = 0;
    for (std::size_t n = 0; n < full.size(); ++n) {
      testing::WriteText(dir / "t.ply", full.substr(0, n));
      rejected += ReadsOrRejects(dir / "t.ply") ? 0 : 1;
    }
    // Cutting inside the header or the vertex data must always be noticed.
    EXPECT_GE(rejected, static_cast<int>(full.find("element face")) + (binary ? 5 * 24 : 10));
  }
}

TEST(PlyRobustness, RandomByteCorruption) {
  const auto dir = testing::FreshTempDir("io");
  std::mt19937 rng(12345);
  for (bool binary : {true, false}) {
    const std::string full = SmallPly(binary);
    for (int trial = 0; trial < 400; ++trial) {
      std::string damaged = full;
      const int flips = 1 + static_cast<int>(rng() % 4);
      for (int f = 0; f < flips; ++f)
        damaged[rng() % damaged.size()] = static_cast<char>(rng() % 256);
      testing::WriteText(dir / "c.ply", damaged);
      ReadsOrRejects(dir / "c.ply");
    }
  }
}

// A batch item's --timeout covers reading its scan: with the deadline passed, reading a large
// cloud ends with DeadlineExceeded instead of running to the end; without one it reads.
TEST(PlyRobustness, ReadingHonoursTheItemDeadline) {
  const auto dir = testing::FreshTempDir("io-deadline");
  PointCloud cloud;
  cloud.points = Eigen::Matrix3Xd::Random(3, 200000);
  for (bool binary : {false, true}) {
    const auto path = dir / (binary ? "big-binary.ply" : "big-ascii.ply");
    WritePly(path.string(), cloud, binary);
    EXPECT_EQ(ReadPly(path.string()).size(), 200000);
    const CancellationScope deadline(1e-9);
    EXPECT_THROW(ReadPly(path.string()), DeadlineExceeded) << path;
  }
}

}  // namespace
}  // namespace cablefit
