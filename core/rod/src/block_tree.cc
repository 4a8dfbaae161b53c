#include "cablefit/core/rod/internal/block_tree.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <numeric>

#include "cablefit/core/base/errors.h"

namespace cablefit::internal {

void BlockTree::ResizeChain(int n) {
  std::vector<int> parent(n), order(n);
  for (int i = 0; i < n; ++i) parent[i] = i + 1 < n ? i + 1 : -1;
  std::iota(order.begin(), order.end(), 0);
  ResizeTree(std::move(parent), std::move(order));
}

void BlockTree::ResizeTree(std::vector<int> parent, std::vector<int> order) {
  const int n = static_cast<int>(parent.size());
  CABLEFIT_CHECK(static_cast<int>(order.size()) == n, "elimination order must list every block");
  std::vector<int> position(n, -1);
  for (int k = 0; k < n; ++k) {
    CABLEFIT_CHECK(order[k] >= 0 && order[k] < n && position[order[k]] < 0,
                   "elimination order is not a permutation");
    position[order[k]] = k;
  }
  for (int i = 0; i < n; ++i)
    CABLEFIT_CHECK(parent[i] < 0 || position[parent[i]] > position[i],
                   "elimination order must list every block before its parent");
  parent_ = std::move(parent);
  order_ = std::move(order);
  diag_.assign(n, Block::Zero());
  coupling_.assign(n, Block::Zero());
}

void BlockTree::SetZero() {
  for (auto& b : diag_) b.setZero();
  for (auto& b : coupling_) b.setZero();
}

void BlockTree::AddOffDiagonal(int a, int c, const Block& b) {
  if (parent_[a] == c) {
    coupling_[a] += b;
  } else {
    CABLEFIT_CHECK(parent_[c] == a, "off-diagonal block between blocks that are not tree neighbours");
    coupling_[c] += b.transpose();
  }
}

Eigen::VectorXd BlockTree::Multiply(const Eigen::VectorXd& x) const {
  const int n = size();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * n);
  for (int i = 0; i < n; ++i) {
    y.segment<3>(3 * i) += diag_[i] * x.segment<3>(3 * i);
    const int p = parent_[i];
    if (p < 0) continue;
    y.segment<3>(3 * i) += coupling_[i] * x.segment<3>(3 * p);
    y.segment<3>(3 * p) += coupling_[i].transpose() * x.segment<3>(3 * i);
  }
  return y;
}

bool BlockTreeLdlt::Factorize(const BlockTree& a, double shift) {
  a_ = &a;
  const int n = a.size();
  pivot_inv_.resize(n);
  negative_ = 0;
  zero_ = 0;
  double scale = 0.0;
  for (int i = 0; i < n; ++i) scale = std::max(scale, a.Diag(i).cwiseAbs().maxCoeff());
  scale = std::max(scale, std::abs(shift));
  const double zero_tol = 1e-13 * (scale > 0 ? scale : 1.0);
  // Schur updates U_c^T P_c^{-1} U_c received from the already eliminated children.
  std::vector<Eigen::Matrix3d> carry(n, Eigen::Matrix3d::Zero());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  for (int i : a.Order()) {
    Eigen::Matrix3d p = a.Diag(i) - carry[i];
    p.diagonal().array() += shift;
    p = 0.5 * (p + p.transpose()).eval();
    eig.computeDirect(p, Eigen::EigenvaluesOnly);
    for (int k = 0; k < 3; ++k) {
      const double ev = eig.eigenvalues()[k];
      if (std::abs(ev) <= zero_tol)
        ++zero_;
      else if (ev < 0)
        ++negative_;
    }
    Eigen::FullPivLU<Eigen::Matrix3d> lu(p);
    if (!lu.isInvertible() || zero_ > 0) return false;
    pivot_inv_[i] = lu.inverse();
    const int par = a.Parent(i);
    if (par >= 0) carry[par] += a.Coupling(i).transpose() * pivot_inv_[i] * a.Coupling(i);
  }
  return true;
}

void BlockTreeLdlt::SolveInPlace(Eigen::Ref<Eigen::MatrixXd> b) const { Solve(b); }
void BlockTreeLdlt::SolveInPlace(Eigen::Ref<RowMajorMatrix> b) const { Solve(b); }

template <class M>
void BlockTreeLdlt::Solve(M& b) const {
  const BlockTree& a = *a_;
  const std::vector<int>& order = a.Order();
  // Forward, leaves first: y_parent -= U_i^T P_i^{-1} y_i.
  for (int i : order) {
    const int par = a.Parent(i);
    if (par >= 0)
      b.template middleRows<3>(3 * par) -= a.Coupling(i).transpose() * (pivot_inv_[i] * b.template middleRows<3>(3 * i));
  }
  // Backward, roots first: x_i = P_i^{-1} (y_i - U_i x_parent).
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const int i = *it;
    const int par = a.Parent(i);
    if (par >= 0) b.template middleRows<3>(3 * i) -= a.Coupling(i) * b.template middleRows<3>(3 * par);
    b.template middleRows<3>(3 * i) = (pivot_inv_[i] * b.template middleRows<3>(3 * i)).eval();
  }
}

}  // namespace cablefit::internal
