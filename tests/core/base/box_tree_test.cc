// BoxTree: best-first nearest queries and range queries give exactly what a scan of every
// primitive gives, and measure only a small part of a large set.
#include "cablefit/core/base/box_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

namespace cablefit {
namespace {

std::vector<Eigen::AlignedBox3d> RandomPointBoxes(int n, std::mt19937* rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d p(u(*rng), u(*rng), u(*rng));
    boxes.emplace_back(p, p);
  }
  return boxes;
}

TEST(BoxTree, NearestIsTheScansAnswerAndMeasuresFew) {
  std::mt19937 rng(7);
  const std::vector<Eigen::AlignedBox3d> boxes = RandomPointBoxes(5000, &rng);
  const BoxTree tree(boxes, 4);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int q = 0; q < 50; ++q) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    int scan = -1;
    double scan_d = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < boxes.size(); ++k) {
      const double d = (boxes[k].min() - p).norm();
      if (d < scan_d) {
        scan_d = d;
        scan = static_cast<int>(k);
      }
    }
    int found = -1, measured = 0;
    const double d = tree.Nearest(
        [&](const Eigen::AlignedBox3d& box) { return box.exteriorDistance(p); },
        [&](int k, double best) {
          ++measured;
          const double dk = (boxes[static_cast<size_t>(k)].min() - p).norm();
          if (dk < best) found = k;
          return std::min(dk, best);
        },
        std::numeric_limits<double>::infinity());
    EXPECT_EQ(found, scan);
    EXPECT_EQ(d, scan_d);
    EXPECT_LT(measured, 200) << "a best-first search measures a few leaves, not the set";
  }
}

TEST(BoxTree, ForEachVisitsExactlyTheOverlappingBoxes) {
  std::mt19937 rng(11);
  const std::vector<Eigen::AlignedBox3d> boxes = RandomPointBoxes(2000, &rng);
  const BoxTree tree(boxes, 3);
  const Eigen::AlignedBox3d query(Eigen::Vector3d(-0.3, -0.2, -0.1), Eigen::Vector3d(0.4, 0.1, 0.5));
  std::vector<int> visited;
  tree.ForEach([&](const Eigen::AlignedBox3d& box) { return box.intersects(query); },
               [&](int k) {
                 if (boxes[static_cast<size_t>(k)].intersects(query)) visited.push_back(k);
               });
  std::vector<int> scan;
  for (size_t k = 0; k < boxes.size(); ++k)
    if (boxes[k].intersects(query)) scan.push_back(static_cast<int>(k));
  std::sort(visited.begin(), visited.end());
  EXPECT_EQ(visited, scan);
  EXPECT_FALSE(scan.empty());
}

TEST(BoxTree, EmptyTreeAnswersNothing) {
  const BoxTree tree(std::vector<Eigen::AlignedBox3d>{}, 4);
  EXPECT_TRUE(tree.empty());
  EXPECT_EQ(tree.Nearest([](const Eigen::AlignedBox3d&) { return 0.0; },
                         [](int, double best) { return best; }, 5.0),
            5.0);
}

}  // namespace
}  // namespace cablefit
