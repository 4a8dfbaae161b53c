// Symmetric block matrices with 3x3 blocks whose off-diagonal pattern is a tree (forest): the
// Hessian of a rod or rod network whose unknowns are one rotation per frame sample, where bending
// couples a frame only with its neighbours along the cable and at junctions. A chain is the
// special case parent(i) = i + 1. Factorised by block LDL^T in an elimination order where every
// block comes before its parent (leaves first), which creates no fill-in: O(n) like the
// tridiagonal case. The inertia of the pivot blocks is the inertia of the matrix (Sylvester),
// which the solver uses for its stability verdict and inertia correction.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace cablefit::internal {

class BlockTree {
 public:
  using Block = Eigen::Matrix3d;

  /// A chain of n blocks: parent(i) = i + 1.
  void ResizeChain(int n);
  /// `parent[i]`: the block coupled with i towards the root (-1 for a root); `order`: an
  /// elimination order listing every block before its parent. Throws if `order` is not one.
  void ResizeTree(std::vector<int> parent, std::vector<int> order);
  int size() const { return static_cast<int>(diag_.size()); }
  int Parent(int i) const { return parent_[i]; }
  const std::vector<int>& Order() const { return order_; }
  void SetZero();
  Block& Diag(int i) { return diag_[i]; }
  const Block& Diag(int i) const { return diag_[i]; }
  /// Block (i, parent(i)); block (parent(i), i) is its transpose.
  Block& Coupling(int i) { return coupling_[i]; }
  const Block& Coupling(int i) const { return coupling_[i]; }
  /// Adds `b` to block (a, c) (and b^T to (c, a)); a and c must be tree neighbours.
  void AddOffDiagonal(int a, int c, const Block& b);
  /// True when blocks a and c are tree neighbours (either is the other's parent).
  bool AreNeighbours(int a, int c) const { return parent_[a] == c || parent_[c] == a; }

  /// y = A x for x, y of length 3n.
  Eigen::VectorXd Multiply(const Eigen::VectorXd& x) const;

 private:
  std::vector<Block> diag_;
  std::vector<Block> coupling_;
  std::vector<int> parent_;
  std::vector<int> order_;
};

/// Block LDL^T of A + shift * I.
class BlockTreeLdlt {
 public:
  /// Returns false when a pivot block is (numerically) singular.
  bool Factorize(const BlockTree& a, double shift);
  /// Number of negative / (numerically) zero eigenvalues of A + shift I.
  int NegativeCount() const { return negative_; }
  int ZeroCount() const { return zero_; }
  /// Solves (A + shift I) x = b in place; b is 3n x k. Row-major keeps each block's rows
  /// contiguous when k is large (many right-hand sides, as in the KKT Schur complement).
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  void SolveInPlace(Eigen::Ref<Eigen::MatrixXd> b) const;
  void SolveInPlace(Eigen::Ref<RowMajorMatrix> b) const;

 private:
  template <class M>
  void Solve(M& b) const;
  const BlockTree* a_ = nullptr;
  std::vector<Eigen::Matrix3d> pivot_inv_;  // P_i^{-1}
  int negative_ = 0;
  int zero_ = 0;
};

}  // namespace cablefit::internal
