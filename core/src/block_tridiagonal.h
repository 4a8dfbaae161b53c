// Symmetric block-tridiagonal matrices with 3x3 blocks: the Hessian of a rod whose unknowns are
// one rotation per frame sample (bending couples only neighbours). Factorised by block LDL^T
// without pivoting in O(n); the inertia of the block pivots gives the inertia of the matrix
// (Sylvester), which the solver uses for its stability verdict and inertia correction.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace cablefit {

class BlockTridiagonal {
 public:
  using Block = Eigen::Matrix3d;

  void Resize(int n);
  int size() const { return static_cast<int>(diag_.size()); }
  void SetZero();
  Block& Diag(int i) { return diag_[i]; }
  const Block& Diag(int i) const { return diag_[i]; }
  /// Block (i, i+1); block (i+1, i) is its transpose.
  Block& Upper(int i) { return upper_[i]; }
  const Block& Upper(int i) const { return upper_[i]; }

  /// y = A x for x, y of length 3n.
  Eigen::VectorXd Multiply(const Eigen::VectorXd& x) const;

 private:
  std::vector<Block> diag_;
  std::vector<Block> upper_;
};

/// Block LDL^T of A + shift * I.
class BlockTridiagonalLdlt {
 public:
  /// Returns false when a pivot block is (numerically) singular.
  bool Factorize(const BlockTridiagonal& a, double shift);
  /// Number of negative / (numerically) zero eigenvalues of A + shift I.
  int NegativeCount() const { return negative_; }
  int ZeroCount() const { return zero_; }
  /// Smallest eigenvalue among the pivot blocks (a cheap conditioning indicator).
  double MinPivotEigenvalue() const { return min_pivot_; }
  /// Solves (A + shift I) x = b in place; b is 3n x k.
  void SolveInPlace(Eigen::Ref<Eigen::MatrixXd> b) const;

 private:
  std::vector<Eigen::Matrix3d> pivot_inv_;  // P_i^{-1}
  std::vector<Eigen::Matrix3d> upper_;      // U_i (copied)
  int negative_ = 0;
  int zero_ = 0;
  double min_pivot_ = 0.0;
};

}  // namespace cablefit
