#include "kkt_ldlt.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

// The leading size x size part (size 1..3) of a symmetric pivot: its inverse
// (the padding stays the identity), how many eigenvalues are negative, and
// bounds for the tolerance tests.
struct PivotFactor {
  Eigen::Matrix3d inverse = Eigen::Matrix3d::Identity();
  int negative = 0;
  double smallest = 0.0;  // [same unit as the pivot] lower bound of |eigenvalue|
  double largest = 0.0;   // about the largest |eigenvalue|
};

template <int N>
PivotFactor FactorPivot(const Eigen::Matrix<double, N, N>& p) {
  using Mat = Eigen::Matrix<double, N, N>;
  PivotFactor f;
  f.largest = p.cwiseAbs().maxCoeff();
  // Definite pivots, the usual case (frames: positive, rows: negative), are
  // told by Cholesky; then 1 / |P^-1|_F bounds the smallest eigenvalue from
  // below.
  for (double sign : {1.0, -1.0}) {
    const Mat sp = sign * p;
    if (Eigen::LLT<Mat>(sp).info() != Eigen::Success) continue;
    const Mat inv = p.inverse();
    f.inverse.template topLeftCorner<N, N>() = inv;
    f.negative = sign > 0 ? 0 : N;
    f.smallest = 1.0 / inv.norm();
    if (!inv.allFinite()) f.smallest = 0.0;
    return f;
  }
  Eigen::SelfAdjointEigenSolver<Mat> eig;
  eig.computeDirect(p, Eigen::EigenvaluesOnly);
  const auto ev = eig.eigenvalues();
  f.smallest = ev.cwiseAbs().minCoeff();
  f.largest = std::max(f.largest, ev.cwiseAbs().maxCoeff());
  for (int k = 0; k < N; ++k) f.negative += ev[k] < 0;
  if (f.smallest > 0) f.inverse.template topLeftCorner<N, N>() = p.inverse();
  return f;
}

PivotFactor FactorLeading(const Eigen::Matrix3d& p, int size) {
  if (size == 3) return FactorPivot<3>(p);
  if (size == 2) return FactorPivot<2>(p.topLeftCorner<2, 2>().eval());
  PivotFactor f;
  f.smallest = f.largest = std::abs(p(0, 0));
  f.negative = p(0, 0) < 0;
  if (p(0, 0) != 0.0) f.inverse(0, 0) = 1.0 / p(0, 0);
  return f;
}

}  // namespace

bool KktLdlt::SamePattern(const internal::SparseJacobian& jacobian,
                          const ConstraintBasis& basis) const {
  const std::vector<ConstraintBasis::Block>& coupling = basis.compliance_coupling();
  if (coupling.size() != coupling_pattern_.size()) return false;
  for (size_t i = 0; i < coupling.size(); ++i)
    if (coupling_pattern_[i] != std::make_pair(coupling[i].a, coupling[i].b)) return false;
  if (static_cast<int>(jac_outer_.size()) != jacobian.outerSize() + 1) return false;
  int t = 0;
  for (int r = 0; r < jacobian.outerSize(); ++r) {
    if (jac_outer_[r] != t) return false;
    for (internal::SparseJacobian::InnerIterator it(jacobian, r); it; ++it, ++t)
      if (t >= static_cast<int>(jac_inner_.size()) || jac_inner_[t] != it.col()) return false;
  }
  return jac_outer_.back() == t;
}

void KktLdlt::Analyze(const RodModel& model, const internal::BlockTree& h,
                      const internal::SparseJacobian& jacobian, const ConstraintBasis& basis) {
  const int ni = h.size();
  num_items_ = ni;
  num_rows_ = static_cast<int>(jacobian.rows());
  row_first_.clear();
  row_count_.clear();
  block_of_row_.assign(num_rows_, -1);
  block_of_support_.assign(model.supports.size(), -1);
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const RodSupport& sp = model.supports[k];
    if (sp.constraint_row < 0 || sp.constraint_rows == 0) continue;
    const int b = ni + static_cast<int>(row_first_.size());
    block_of_support_[k] = b;
    row_first_.push_back(sp.constraint_row);
    row_count_.push_back(sp.constraint_rows);
    for (int r = 0; r < sp.constraint_rows; ++r) block_of_row_[sp.constraint_row + r] = b;
  }
  for (int r = 0; r < num_rows_; ++r)
    CABLEFIT_CHECK(block_of_row_[r] >= 0, "constraint row without a support");
  const int nr = static_cast<int>(row_first_.size());
  const int nb = ni + nr;

  // Which frames each support's rows act on, and the pattern for later
  // comparison.
  std::vector<std::vector<int>> row_items(nr);
  jac_outer_.assign(1, 0);
  jac_inner_.clear();
  for (int r = 0; r < num_rows_; ++r) {
    for (internal::SparseJacobian::InnerIterator it(jacobian, r); it; ++it) {
      row_items[block_of_row_[r] - ni].push_back(static_cast<int>(it.col()) / 3);
      jac_inner_.push_back(static_cast<int>(it.col()));
    }
    jac_outer_.push_back(static_cast<int>(jac_inner_.size()));
  }
  std::vector<int> item_position(ni, -1);
  for (int k = 0; k < ni; ++k) item_position[h.Order()[k]] = k;

  // Elimination order: the frames in the Hessian's order, each row block right
  // after the last frame it acts on (a block acting on none comes first: its
  // pivot is zero, which Factorize reports as rank deficient).
  std::vector<std::vector<int>> rows_after(ni);
  order_.clear();
  for (int b = 0; b < nr; ++b) {
    std::vector<int>& items = row_items[b];
    std::sort(items.begin(), items.end());
    items.erase(std::unique(items.begin(), items.end()), items.end());
    if (items.empty()) {
      order_.push_back(ni + b);
      continue;
    }
    int last = items.front();
    for (int i : items)
      if (item_position[i] > item_position[last]) last = i;
    rows_after[last].push_back(ni + b);
  }
  for (int i : h.Order()) {
    order_.push_back(i);
    for (int b : rows_after[i]) order_.push_back(b);
  }
  std::vector<int> position(nb, -1);
  for (int k = 0; k < nb; ++k) position[order_[k]] = k;

  // Symbolic elimination: a block's column holds its later neighbours and what
  // its children in the elimination tree pass up (their columns minus the
  // parent itself).
  std::vector<std::vector<int>> column(nb);
  for (int i = 0; i < ni; ++i)
    if (h.Parent(i) >= 0) column[i].push_back(h.Parent(i));
  for (int b = 0; b < nr; ++b)
    for (int i : row_items[b]) column[i].push_back(ni + b);
  // Compliance between two supports' rows: an entry in the column of the one eliminated first.
  coupling_pattern_.clear();
  for (const ConstraintBasis::Block& c : basis.compliance_coupling()) {
    coupling_pattern_.emplace_back(c.a, c.b);
    const int u = block_of_support_[static_cast<size_t>(c.a)], v = block_of_support_[static_cast<size_t>(c.b)];
    CABLEFIT_CHECK(u >= 0 && v >= 0, "compliance between supports without rows");
    if (position[u] < position[v]) {
      column[u].push_back(v);
    } else {
      column[v].push_back(u);
    }
  }
  auto by_position = [&position](int a, int b) { return position[a] < position[b]; };
  column_start_.assign(nb + 1, 0);
  std::vector<int> column_begin(nb), column_end(nb);
  entry_block_.clear();
  std::vector<int> sorted_blocks;
  for (int v : order_) {
    std::vector<int>& c = column[v];
    std::sort(c.begin(), c.end(), by_position);
    c.erase(std::unique(c.begin(), c.end()), c.end());
    column_begin[v] = static_cast<int>(entry_block_.size());
    entry_block_.insert(entry_block_.end(), c.begin(), c.end());
    column_end[v] = static_cast<int>(entry_block_.size());
    if (c.size() > 1) column[c.front()].insert(column[c.front()].end(), c.begin() + 1, c.end());
    std::vector<int>().swap(c);
  }
  // Columns stored in elimination order: column_start_ is indexed by position.
  for (int k = 0; k < nb; ++k) column_start_[k] = column_begin[order_[k]];
  column_start_[nb] = static_cast<int>(entry_block_.size());
  auto entry_index = [&](int v, int u) {
    const auto first = entry_block_.begin() + column_begin[v];
    const auto last = entry_block_.begin() + column_end[v];
    const auto it = std::lower_bound(first, last, u, by_position);
    CABLEFIT_CHECK(it != last && *it == u, "KKT elimination: fill entry missing");
    return static_cast<int>(it - entry_block_.begin());
  };
  update_start_.assign(nb + 1, 0);
  update_target_.clear();
  for (int k = 0; k < nb; ++k) {
    const int v = order_[k];
    update_start_[k] = static_cast<int>(update_target_.size());
    for (int i = column_begin[v]; i < column_end[v]; ++i) {
      const int a = entry_block_[i];
      update_target_.push_back(-1 - a);
      for (int j = i + 1; j < column_end[v]; ++j)
        update_target_.push_back(entry_index(a, entry_block_[j]));
    }
  }
  update_start_[nb] = static_cast<int>(update_target_.size());
  h_entry_.assign(ni, -1);
  for (int i = 0; i < ni; ++i)
    if (h.Parent(i) >= 0) h_entry_[i] = entry_index(i, h.Parent(i));
  jac_entry_.clear();
  for (int r = 0; r < num_rows_; ++r)
    for (internal::SparseJacobian::InnerIterator it(jacobian, r); it; ++it)
      jac_entry_.push_back(entry_index(static_cast<int>(it.col()) / 3, block_of_row_[r]));
  coupling_entry_.clear();
  coupling_flip_.clear();
  for (const auto& [a, b] : coupling_pattern_) {
    const int u = block_of_support_[static_cast<size_t>(a)], v = block_of_support_[static_cast<size_t>(b)];
    const bool u_first = position[u] < position[v];
    coupling_entry_.push_back(u_first ? entry_index(u, v) : entry_index(v, u));
    coupling_flip_.push_back(u_first ? 1 : 0);
  }
  entry_.assign(entry_block_.size(), Eigen::Matrix3d::Zero());
  pivot_.assign(nb, Eigen::Matrix3d::Zero());
}

KktLdlt::Status KktLdlt::Factorize(const RodModel& model, const internal::BlockTree& h,
                                   const internal::SparseJacobian& jacobian,
                                   const ConstraintBasis& basis, const std::vector<char>& free,
                                   double shift) {
  if (num_items_ != h.size() || num_rows_ != jacobian.rows() || !SamePattern(jacobian, basis))
    Analyze(model, h, jacobian, basis);
  const int ni = num_items_;
  const int nb = static_cast<int>(order_.size());
  double scale = std::abs(shift);
  for (int i = 0; i < ni; ++i) {
    Eigen::Matrix3d p = h.Diag(i);
    for (int d = 0; d < 3; ++d)
      if (free[3 * i + d]) p(d, d) += shift;
    pivot_[i] = p;
    scale = std::max(scale, h.Diag(i).cwiseAbs().maxCoeff());
  }
  if (!(scale > 0)) scale = 1.0;
  for (int b = ni; b < nb; ++b) pivot_[b] = Eigen::Matrix3d::Identity();
  std::vector<double> row_scale(row_first_.size(),
                                0.0);  // |J_k|^2 / |H|: its pivot's size
  for (int b = ni; b < nb; ++b)
    pivot_[b].topLeftCorner(row_count_[b - ni], row_count_[b - ni]).setZero();
  // A compliant support (an extensible stretch) holds c = C lambda: -C in its rows' blocks.
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const int b = block_of_support_[k];
    if (b < 0) continue;
    const int rows = row_count_[b - ni];
    pivot_[b].topLeftCorner(rows, rows) -= basis.compliance_diagonal()[k].topLeftCorner(rows, rows);
  }
  for (Eigen::Matrix3d& e : entry_) e.setZero();
  const std::vector<ConstraintBasis::Block>& coupling = basis.compliance_coupling();
  for (size_t c = 0; c < coupling.size(); ++c) {
    // The entry holds A(later block, earlier block): rows of the later one.
    entry_[coupling_entry_[c]] = coupling_flip_[c] ? Eigen::Matrix3d(-coupling[c].value.transpose())
                                                   : Eigen::Matrix3d(-coupling[c].value);
  }
  for (int i = 0; i < ni; ++i)
    if (h_entry_[i] >= 0) entry_[h_entry_[i]] = h.Coupling(i).transpose();
  int t = 0;
  for (int r = 0; r < num_rows_; ++r) {
    const int b = block_of_row_[r] - ni;
    for (internal::SparseJacobian::InnerIterator it(jacobian, r); it; ++it, ++t) {
      entry_[jac_entry_[t]](r - row_first_[b], it.col() % 3) = it.value();
      row_scale[b] += it.value() * it.value() / scale;
    }
  }

  const double zero_tol = 1e-13 * scale;
  negative_ = 0;
  std::vector<Eigen::Matrix3d> l;
  for (int k = 0; k < nb; ++k) {
    const int v = order_[k];
    const bool is_row = v >= ni;
    const int size = is_row ? row_count_[v - ni] : 3;
    const Eigen::Matrix3d p = 0.5 * (pivot_[v] + pivot_[v].transpose());
    const PivotFactor f = FactorLeading(p, size);
    const double tol = is_row ? 1e-12 * std::max(f.largest, row_scale[v - ni]) : zero_tol;
    if (!(f.smallest > tol) || !f.inverse.allFinite())
      return is_row ? Status::kRankDeficient : Status::kSingularPivot;
    negative_ += f.negative;
    const Eigen::Matrix3d& inv = f.inverse;
    // L_uv = A_uv P^-1; then every pair (a, b) of the column: A_ba -= L_bv
    // A_av^T.
    const int first = column_start_[k];
    const int count = column_start_[k + 1] - first;
    l.resize(count);
    for (int e = 0; e < count; ++e) l[e].noalias() = entry_[first + e] * inv;
    int u = update_start_[k];
    for (int i = 0; i < count; ++i) {
      for (int j = i; j < count; ++j, ++u) {
        const int target = update_target_[u];
        Eigen::Matrix3d& dst = target < 0 ? pivot_[-1 - target] : entry_[target];
        dst.noalias() -= l[j] * entry_[first + i].transpose();
      }
    }
    for (int e = 0; e < count; ++e) entry_[first + e] = l[e];
    pivot_[v] = inv;
  }
  return Status::kOk;
}

void KktLdlt::Solve(const Eigen::VectorXd& g, const Eigen::VectorXd& c, Eigen::VectorXd* step,
                    Eigen::VectorXd* lambda) const {
  const int ni = num_items_;
  const int nb = static_cast<int>(order_.size());
  std::vector<Eigen::Vector3d> z(nb, Eigen::Vector3d::Zero());
  for (int i = 0; i < ni; ++i) z[i] = -g.segment<3>(3 * i);
  for (int b = ni; b < nb; ++b)
    z[b].head(row_count_[b - ni]) = -c.segment(row_first_[b - ni], row_count_[b - ni]);
  for (int k = 0; k < nb; ++k) {  // L y = rhs
    const Eigen::Vector3d zv = z[order_[k]];
    for (int e = column_start_[k]; e < column_start_[k + 1]; ++e)
      z[entry_block_[e]].noalias() -= entry_[e] * zv;
  }
  for (int v = 0; v < nb; ++v) z[v] = (pivot_[v] * z[v]).eval();  // D^-1
  for (int k = nb - 1; k >= 0; --k) {                             // L^T x = y
    Eigen::Vector3d& zv = z[order_[k]];
    for (int e = column_start_[k]; e < column_start_[k + 1]; ++e)
      zv.noalias() -= entry_[e].transpose() * z[entry_block_[e]];
  }
  step->resize(3 * ni);
  for (int i = 0; i < ni; ++i) step->segment<3>(3 * i) = z[i];
  lambda->resize(num_rows_);
  for (int b = ni; b < nb; ++b)
    lambda->segment(row_first_[b - ni], row_count_[b - ni]) = z[b].head(row_count_[b - ni]);
}

}  // namespace cablefit
