// The picture's thinning of centre lines: what it keeps must still trace every skipped point.
#include "tube_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace cablefit::render {
namespace {

// Distance of p from the segment a-b.
double ToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double w = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + w * ab - p).norm();
}

TEST(ThinnedIndices, EverySkippedPointStaysWithinToleranceOfItsChord) {
  // A helix of 10 000 nodes (0.3 mm apart), as a finely refined relax gives them.
  const int n = 10000;
  Eigen::Matrix3Xd p(3, n);
  for (int i = 0; i < n; ++i) {
    const double t = 6 * std::numbers::pi * i / (n - 1);
    p.col(i) = Eigen::Vector3d(0.05 * std::cos(t), 0.05 * std::sin(t), 0.02 * t);
  }
  const double tolerance = 1e-4, max_length = 0.02;
  const std::vector<Eigen::Index> kept = ThinnedIndices(p, tolerance, max_length);
  ASSERT_GE(kept.size(), 2u);
  EXPECT_EQ(kept.front(), 0);
  EXPECT_EQ(kept.back(), n - 1);
  // Far fewer, but not too few: a chord of length h on radius ~0.058 m deviates by h^2 / (8 r),
  // so 1e-4 m allows h of about 7 mm; the helix is 1.05 m long.
  EXPECT_LT(kept.size(), 400u);
  EXPECT_GT(kept.size(), 100u);
  for (size_t k = 0; k + 1 < kept.size(); ++k) {
    ASSERT_LT(kept[k], kept[k + 1]);
    const Eigen::Vector3d a = p.col(kept[k]), b = p.col(kept[k + 1]);
    EXPECT_LE((b - a).norm(), max_length);
    for (Eigen::Index j = kept[k] + 1; j < kept[k + 1]; ++j)
      ASSERT_LE(ToSegment(p.col(j), a, b), tolerance) << j;
  }
}

TEST(ThinnedIndices, AStraightLineKeepsOnlyWhatTheLongestChordNeeds) {
  Eigen::Matrix3Xd p(3, 1001);
  for (int i = 0; i <= 1000; ++i) p.col(i) = Eigen::Vector3d(1e-3 * i, 0, 0);  // 1 m
  EXPECT_EQ(ThinnedIndices(p, 1e-6, 10.0).size(), 2u);
  const std::vector<Eigen::Index> chunks = ThinnedIndices(p, 1e-6, 0.1 + 1e-9);
  EXPECT_EQ(chunks.size(), 11u);  // chords of 0.1 m
  EXPECT_EQ(ThinnedIndices(p.leftCols(1), 1e-6, 0.1).size(), 1u);
}

}  // namespace
}  // namespace cablefit::render
