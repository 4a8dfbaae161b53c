#include "constraint_basis.h"

#include <map>

#include "cablefit/core/rod/internal/rod_energy.h"

namespace cablefit {

ConstraintBasis::ConstraintBasis(const RodModel& model, const RodState& state) : model_(&model) {
  const size_t ns = model.supports.size();
  projector_.assign(ns, Eigen::Matrix3d::Zero());
  diagonal_.assign(ns, Eigen::Matrix3d::Zero());
  for (size_t k = 0; k < ns; ++k) {
    const RodSupport& sp = model.supports[k];
    if (sp.constraint_row < 0) continue;
    projector_[k].topRows(sp.constraint_rows) =
        internal::ConstraintProjector(sp, state, static_cast<int>(k));
    identity_ = identity_ && sp.row_chain.empty();
    diagonal_[k].topLeftCorner(sp.constraint_rows, sp.constraint_rows) =
        sp.compliance * Eigen::MatrixXd::Identity(sp.constraint_rows, sp.constraint_rows);
  }
  if (identity_) return;
  // Physical row m reaches rows-basis support a with coefficient E_am: I for a = m, -P_a for
  // every a whose chain holds m; C_rows(a, b) = sum_m E_am C_m E_bm^T.
  std::vector<std::vector<int>> chained_in(ns);
  for (size_t a = 0; a < ns; ++a)
    for (int m : model.supports[a].row_chain) chained_in[static_cast<size_t>(m)].push_back(static_cast<int>(a));
  std::map<std::pair<int, int>, Eigen::Matrix3d> coupling;
  for (size_t m = 0; m < ns; ++m) {
    const RodSupport& sm = model.supports[m];
    if (sm.constraint_row < 0 || !(sm.compliance > 0) || chained_in[m].empty()) continue;
    std::vector<std::pair<int, Eigen::Matrix3d>> reach = {{static_cast<int>(m), Eigen::Matrix3d::Identity()}};
    for (int a : chained_in[m]) reach.emplace_back(a, -projector_[static_cast<size_t>(a)]);
    for (size_t i = 0; i < reach.size(); ++i) {
      for (size_t j = i; j < reach.size(); ++j) {
        const Eigen::Matrix3d block = sm.compliance * reach[i].second * reach[j].second.transpose();
        const int a = reach[i].first, b = reach[j].first;
        if (i == j) {
          if (a != static_cast<int>(m)) diagonal_[static_cast<size_t>(a)] += block;
        } else {
          // Eigen's default matrix is uninitialised: a new block starts at zero.
          const bool in_order = a < b;
          auto [it, fresh] = coupling.try_emplace(in_order ? std::make_pair(a, b) : std::make_pair(b, a),
                                                  Eigen::Matrix3d::Zero());
          it->second += in_order ? block : Eigen::Matrix3d(block.transpose());
        }
      }
    }
  }
  for (auto& [ab, value] : coupling) coupling_.push_back({ab.first, ab.second, value});
}

Eigen::VectorXd ConstraintBasis::ToPhysical(const Eigen::VectorXd& rows) const {
  if (identity_) return rows;
  Eigen::VectorXd phys = rows;
  for (int k : model_->row_support_order) {
    const RodSupport& sp = model_->supports[static_cast<size_t>(k)];
    if (sp.row_chain.empty()) continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int m : sp.row_chain) sum += phys.segment<3>(model_->supports[static_cast<size_t>(m)].constraint_row);
    phys.segment(sp.constraint_row, sp.constraint_rows) +=
        projector_[static_cast<size_t>(k)].topRows(sp.constraint_rows) * sum;
  }
  return phys;
}

Eigen::VectorXd ConstraintBasis::MultipliersToPhysical(const Eigen::VectorXd& rows) const {
  if (identity_) return rows;
  Eigen::VectorXd phys = rows;
  for (int k : model_->row_support_order) {
    const RodSupport& sp = model_->supports[static_cast<size_t>(k)];
    if (sp.row_chain.empty()) continue;
    const Eigen::Vector3d f = projector_[static_cast<size_t>(k)].topRows(sp.constraint_rows).transpose() *
                              rows.segment(sp.constraint_row, sp.constraint_rows);
    for (int m : sp.row_chain) phys.segment<3>(model_->supports[static_cast<size_t>(m)].constraint_row) -= f;
  }
  return phys;
}

Eigen::VectorXd ConstraintBasis::MultipliersToRows(const Eigen::VectorXd& physical) const {
  if (identity_) return physical;
  // lambda_rows_m = lambda_phys_m + sum over the supports k chained to m (later in the order)
  // of P_k^T lambda_rows_k: from the last support back.
  Eigen::VectorXd rows = physical;
  const std::vector<int>& order = model_->row_support_order;
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const RodSupport& sp = model_->supports[static_cast<size_t>(*it)];
    if (sp.row_chain.empty()) continue;
    const Eigen::Vector3d f = projector_[static_cast<size_t>(*it)].topRows(sp.constraint_rows).transpose() *
                              rows.segment(sp.constraint_row, sp.constraint_rows);
    for (int m : sp.row_chain) rows.segment<3>(model_->supports[static_cast<size_t>(m)].constraint_row) += f;
  }
  return rows;
}

Eigen::MatrixXd ConstraintBasis::DenseCompliance() const {
  const int m = model_->num_constraints;
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(m, m);
  for (size_t k = 0; k < model_->supports.size(); ++k) {
    const RodSupport& sp = model_->supports[k];
    if (sp.constraint_row < 0) continue;
    c.block(sp.constraint_row, sp.constraint_row, sp.constraint_rows, sp.constraint_rows) =
        diagonal_[k].topLeftCorner(sp.constraint_rows, sp.constraint_rows);
  }
  for (const Block& b : coupling_) {
    const RodSupport& sa = model_->supports[static_cast<size_t>(b.a)];
    const RodSupport& sb = model_->supports[static_cast<size_t>(b.b)];
    const Eigen::MatrixXd v = b.value.topLeftCorner(sa.constraint_rows, sb.constraint_rows);
    c.block(sa.constraint_row, sb.constraint_row, sa.constraint_rows, sb.constraint_rows) = v;
    c.block(sb.constraint_row, sa.constraint_row, sb.constraint_rows, sa.constraint_rows) = v.transpose();
  }
  return c;
}

}  // namespace cablefit
