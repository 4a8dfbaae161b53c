// Position constraints of the supports: c_k = P_k (r(node_k) - p_k) = 0, where node positions are
// prefix sums of h_j d3_j from the anchor support. P_k is the identity, or the two directions
// across the support's axis for a sliding support. The rows the solver works with are measured
// from RodSupport::row_reference (the rows' basis); the reactions from `reference` (physics).
#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/rod_energy.h"

namespace cablefit::internal {

Eigen::Matrix<double, Eigen::Dynamic, 3> ConstraintProjector(const RodSupport& support,
                                                             const RodState& state, int k) {
  if (support.contact) return support.frame.d3.transpose();
  if (!support.sliding) return Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d r = quat::ToMatrix(state.support_q[k]);
  Eigen::Matrix<double, Eigen::Dynamic, 3> p(2, 3);
  p.row(0) = r.col(0).transpose();
  p.row(1) = r.col(1).transpose();
  return p;
}

void EvaluatePositionConstraints(const RodModel& model, const RodState& state, Eigen::VectorXd* c,
                                 SparseJacobian* jacobian) {
  const int m = model.num_constraints;
  const int n = static_cast<int>(model.items.size());
  c->setZero(m);
  const Eigen::Matrix3Xd r = state.NodePositions(model);
  const Eigen::Matrix3d e3x = quat::Skew(Vec3::UnitZ());
  // d r_node / d theta_item of one element, shared by every support whose path crosses it (a
  // network has a support at every end, each path crossing most of the tree).
  std::vector<Eigen::Matrix3d> element_dr;
  if (jacobian) {
    element_dr.resize(static_cast<size_t>(model.num_elements));
    for (int j = 0; j < model.num_elements; ++j) {
      element_dr[static_cast<size_t>(j)] =
          model.element_length[j] * quat::ToMatrix(state.q[model.element_item[j]]) * e3x;
    }
  }
  // Supports in row order: the Jacobian is written row by row straight into its compressed
  // storage (a network's has hundreds of thousands of entries per Newton iteration; collecting
  // them as triplets first cost more than the rest of the evaluation).
  std::vector<int> by_row;
  for (size_t k = 0; k < model.supports.size(); ++k)
    if (model.supports[k].constraint_row >= 0) by_row.push_back(static_cast<int>(k));
  std::sort(by_row.begin(), by_row.end(), [&](int a, int b) {
    return model.supports[a].constraint_row < model.supports[b].constraint_row;
  });
  if (jacobian) {
    jacobian->resize(m, 3 * n);
    size_t entries = 0;
    for (int k : by_row) {
      const RodSupport& sp = model.supports[k];
      const int from = sp.row_reference >= 0 ? model.supports[sp.row_reference].node : -1;
      size_t path = 0;
      model.ForEachPathElementFrom(from, sp.node, [&](int, int) { ++path; });
      entries += 3 * path * static_cast<size_t>(sp.constraint_rows);
    }
    jacobian->reserve(static_cast<Eigen::Index>(entries));
  }
  int next_row = 0;
  std::vector<std::pair<int, int>> path;      // (item, element), sorted by item
  for (int k : by_row) {
    const RodSupport& sp = model.supports[k];
    const auto p = ConstraintProjector(sp, state, k);
    Vec3 gap = r.col(sp.node) - state.support_position[k];
    int from = -1;
    if (sp.row_reference >= 0) {
      const RodSupport& ref = model.supports[sp.row_reference];
      gap -= r.col(ref.node) - state.support_position[sp.row_reference];
      from = ref.node;
    }
    c->segment(sp.constraint_row, sp.constraint_rows) = p * gap;
    if (!jacobian) continue;
    path.clear();
    model.ForEachPathElementFrom(from, sp.node, [&](int j, int sign) {
      path.emplace_back(model.element_item[j], sign > 0 ? j + 1 : -(j + 1));
    });
    std::sort(path.begin(), path.end());
    for (; next_row < sp.constraint_row; ++next_row) jacobian->startVec(next_row);
    for (int row = 0; row < sp.constraint_rows; ++row, ++next_row) {
      jacobian->startVec(next_row);
      for (size_t a = 0; a < path.size();) {
        // Elements sharing one frame item add up into its three columns.
        const int item = path[a].first;
        Eigen::RowVector3d v = Eigen::RowVector3d::Zero();
        for (; a < path.size() && path[a].first == item; ++a) {
          const int coded = path[a].second;
          const int j = std::abs(coded) - 1;
          const double sign = coded > 0 ? 1.0 : -1.0;
          v -= sign * (p.row(row) * element_dr[static_cast<size_t>(j)]);
        }
        for (int d = 0; d < 3; ++d) jacobian->insertBack(next_row, 3 * item + d) = v[d];
      }
    }
  }
  if (!jacobian) return;
  for (; next_row < m; ++next_row) jacobian->startVec(next_row);
  jacobian->finalize();
}

std::vector<Vec3> SupportReactions(const RodModel& model, const RodState& state) {
  std::vector<Vec3> out(model.supports.size(), Vec3::Zero());
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const RodSupport& sp = model.supports[k];
    if (sp.constraint_row < 0) continue;
    const auto p = ConstraintProjector(sp, state, static_cast<int>(k));
    const Vec3 f = p.transpose() * state.lambda.segment(sp.constraint_row, sp.constraint_rows);
    out[k] -= f;
    if (sp.reference >= 0) out[sp.reference] += f;
  }
  return out;
}

void AddConstraintCurvature(const RodModel& model, const RodState& state,
                            const Eigen::VectorXd& lambda, BlockTree* hessian) {
  if (model.num_constraints == 0) return;
  std::vector<Vec3> a(model.num_elements, Vec3::Zero());
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const RodSupport& sp = model.supports[k];
    if (sp.constraint_row < 0) continue;
    const auto p = ConstraintProjector(sp, state, static_cast<int>(k));
    const Vec3 force = p.transpose() * lambda.segment(sp.constraint_row, sp.constraint_rows);
    const int from = sp.row_reference >= 0 ? model.supports[sp.row_reference].node : -1;
    model.ForEachPathElementFrom(
        from, sp.node, [&](int j, int sign) { a[j] += sign * model.element_length[j] * force; });
  }
  for (int j = 0; j < model.num_elements; ++j) {
    if (a[j].squaredNorm() == 0.0) continue;
    const int item = model.element_item[j];
    const Eigen::Matrix3d r = quat::ToMatrix(state.q[item]);
    const Vec3 at = r.transpose() * a[j];
    Eigen::Matrix3d h = -at[2] * Eigen::Matrix3d::Identity();
    h.col(2) += 0.5 * at;
    h.row(2) += 0.5 * at.transpose();
    hessian->Diag(item) += h;
  }
}

}  // namespace cablefit::internal
