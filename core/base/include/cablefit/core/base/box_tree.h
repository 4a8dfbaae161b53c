// A static bounding-volume tree over axis-aligned boxes, for exact nearest queries that never
// measure what lies far away: a primitive is measured only while its box could still hold
// something nearer than the best found so far (best-first search). Built once by median splits
// on the longest axis of the box centres; the tree and its traversal order depend only on the
// boxes, so queries are deterministic.
#pragma once

#include <Eigen/Geometry>
#include <queue>
#include <vector>

namespace cablefit {

class BoxTree {
 public:
  BoxTree() = default;
  /// Indexes `boxes` (one per primitive, primitive k = boxes[k]); `leaf_size` primitives per
  /// leaf at most.
  explicit BoxTree(const std::vector<Eigen::AlignedBox3d>& boxes, int leaf_size = 4);

  bool empty() const { return nodes_.empty(); }

  /// Best-first search. `bound(box)` is a lower bound of the measure of anything inside `box`;
  /// `measure(k, best)` measures primitive k and returns the best measure found so far (its own
  /// if smaller than `best`, else `best`). Nodes whose bound exceeds the best are never opened,
  /// so the result is exact whenever `bound` is a true lower bound. Returns the best.
  template <class Bound, class Measure>
  double Nearest(Bound&& bound, Measure&& measure, double best) const;

  /// Calls `visit(k)` for every primitive whose box `overlaps(box)` says may matter (a range
  /// query), in a fixed order.
  template <class Overlaps, class Visit>
  void ForEach(Overlaps&& overlaps, Visit&& visit) const;

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int left = -1, right = -1;  // children; -1 at a leaf
    int begin = 0, end = 0;     // primitives order_[begin, end) below this node
  };
  int Build(const std::vector<Eigen::AlignedBox3d>& boxes, int begin, int end, int leaf_size);

  std::vector<Node> nodes_;  // nodes_[0] is the root
  std::vector<int> order_;   // primitive indices, leaves' ranges into it
};

template <class Bound, class Measure>
double BoxTree::Nearest(Bound&& bound, Measure&& measure, double best) const {
  if (nodes_.empty()) return best;
  using Entry = std::pair<double, int>;  // (lower bound, node); smallest first, then lower node
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  open.emplace(bound(nodes_[0].box), 0);
  while (!open.empty()) {
    const auto [lower, n] = open.top();
    open.pop();
    if (lower > best) break;
    const Node& node = nodes_[static_cast<size_t>(n)];
    if (node.left < 0) {
      for (int k = node.begin; k < node.end; ++k) best = measure(order_[static_cast<size_t>(k)], best);
      continue;
    }
    for (int child : {node.left, node.right}) {
      const double b = bound(nodes_[static_cast<size_t>(child)].box);
      if (b <= best) open.emplace(b, child);
    }
  }
  return best;
}

template <class Overlaps, class Visit>
void BoxTree::ForEach(Overlaps&& overlaps, Visit&& visit) const {
  if (nodes_.empty()) return;
  std::vector<int> stack = {0};
  while (!stack.empty()) {
    const Node& node = nodes_[static_cast<size_t>(stack.back())];
    stack.pop_back();
    if (!overlaps(node.box)) continue;
    if (node.left < 0) {
      for (int k = node.begin; k < node.end; ++k) visit(order_[static_cast<size_t>(k)]);
      continue;
    }
    stack.push_back(node.right);
    stack.push_back(node.left);
  }
}

}  // namespace cablefit
