#include "cablefit/core/base/box_tree.h"

#include <algorithm>
#include <numeric>

#include "cablefit/core/base/errors.h"

namespace cablefit {

BoxTree::BoxTree(const std::vector<Eigen::AlignedBox3d>& boxes, int leaf_size) {
  CABLEFIT_REQUIRE(leaf_size >= 1, "BoxTree needs leaves of at least one primitive");
  order_.resize(boxes.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (boxes.empty()) return;
  nodes_.reserve(2 * boxes.size() / static_cast<size_t>(leaf_size) + 1);
  Build(boxes, 0, static_cast<int>(boxes.size()), leaf_size);
}

int BoxTree::Build(const std::vector<Eigen::AlignedBox3d>& boxes, int begin, int end,
                   int leaf_size) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box, centres;
  for (int k = begin; k < end; ++k) {
    const Eigen::AlignedBox3d& b = boxes[static_cast<size_t>(order_[static_cast<size_t>(k)])];
    box.extend(b);
    centres.extend(b.center());
  }
  nodes_[static_cast<size_t>(index)].box = box;
  nodes_[static_cast<size_t>(index)].begin = begin;
  nodes_[static_cast<size_t>(index)].end = end;
  if (end - begin <= leaf_size) return index;
  int axis = 0;
  centres.sizes().maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  // Ties broken by primitive index: the tree depends on the boxes only, not on the sort.
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) {
                     const double ca = boxes[static_cast<size_t>(a)].center()[axis];
                     const double cb = boxes[static_cast<size_t>(b)].center()[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const int left = Build(boxes, begin, mid, leaf_size);
  const int right = Build(boxes, mid, end, leaf_size);
  nodes_[static_cast<size_t>(index)].left = left;
  nodes_[static_cast<size_t>(index)].right = right;
  return index;
}

}  // namespace cablefit
