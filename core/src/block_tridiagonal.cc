#include "block_tridiagonal.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace cablefit {

void BlockTridiagonal::Resize(int n) {
  diag_.assign(n, Block::Zero());
  upper_.assign(n > 0 ? n - 1 : 0, Block::Zero());
}

void BlockTridiagonal::SetZero() {
  for (auto& b : diag_) b.setZero();
  for (auto& b : upper_) b.setZero();
}

Eigen::VectorXd BlockTridiagonal::Multiply(const Eigen::VectorXd& x) const {
  const int n = size();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * n);
  for (int i = 0; i < n; ++i) {
    y.segment<3>(3 * i) += diag_[i] * x.segment<3>(3 * i);
    if (i + 1 < n) {
      y.segment<3>(3 * i) += upper_[i] * x.segment<3>(3 * i + 3);
      y.segment<3>(3 * i + 3) += upper_[i].transpose() * x.segment<3>(3 * i);
    }
  }
  return y;
}

bool BlockTridiagonalLdlt::Factorize(const BlockTridiagonal& a, double shift) {
  const int n = a.size();
  pivot_inv_.resize(n);
  upper_.resize(n > 0 ? n - 1 : 0);
  negative_ = 0;
  zero_ = 0;
  min_pivot_ = std::numeric_limits<double>::infinity();
  double scale = 0.0;
  for (int i = 0; i < n; ++i) scale = std::max(scale, a.Diag(i).cwiseAbs().maxCoeff());
  scale = std::max(scale, std::abs(shift));
  const double zero_tol = 1e-13 * (scale > 0 ? scale : 1.0);
  Eigen::Matrix3d carry = Eigen::Matrix3d::Zero();  // U_{i-1}^T P_{i-1}^{-1} U_{i-1}
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  for (int i = 0; i < n; ++i) {
    Eigen::Matrix3d p = a.Diag(i) - carry;
    p.diagonal().array() += shift;
    p = 0.5 * (p + p.transpose()).eval();
    eig.computeDirect(p, Eigen::EigenvaluesOnly);
    for (int k = 0; k < 3; ++k) {
      const double ev = eig.eigenvalues()[k];
      min_pivot_ = std::min(min_pivot_, ev);
      if (std::abs(ev) <= zero_tol)
        ++zero_;
      else if (ev < 0)
        ++negative_;
    }
    Eigen::FullPivLU<Eigen::Matrix3d> lu(p);
    if (!lu.isInvertible() || zero_ > 0) return false;
    pivot_inv_[i] = lu.inverse();
    if (i + 1 < n) {
      upper_[i] = a.Upper(i);
      carry = upper_[i].transpose() * pivot_inv_[i] * upper_[i];
    }
  }
  return true;
}

void BlockTridiagonalLdlt::SolveInPlace(Eigen::Ref<Eigen::MatrixXd> b) const {
  const int n = static_cast<int>(pivot_inv_.size());
  // Forward: y_i = b_i - U_{i-1}^T P_{i-1}^{-1} y_{i-1}.
  for (int i = 1; i < n; ++i)
    b.middleRows<3>(3 * i) -= upper_[i - 1].transpose() * (pivot_inv_[i - 1] * b.middleRows<3>(3 * i - 3));
  // Backward: x_i = P_i^{-1} (y_i - U_i x_{i+1}).
  for (int i = n - 1; i >= 0; --i) {
    if (i + 1 < n) b.middleRows<3>(3 * i) -= upper_[i] * b.middleRows<3>(3 * i + 3);
    b.middleRows<3>(3 * i) = (pivot_inv_[i] * b.middleRows<3>(3 * i)).eval();
  }
}

}  // namespace cablefit
