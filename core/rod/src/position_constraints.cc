// Position constraints of the supports: c_k = P_k (r(node_k) - p_k) = 0, where node positions are
// prefix sums of h_j d3_j from the anchor support. P_k is the identity, or the two directions
// across the support's axis for a sliding support.
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
  std::vector<Eigen::Triplet<double>> triplets;
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
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const RodSupport& sp = model.supports[k];
    if (sp.constraint_row < 0) continue;
    const auto p = ConstraintProjector(sp, state, static_cast<int>(k));
    Vec3 gap = r.col(sp.node) - state.support_position[k];
    int from = -1;
    if (sp.reference >= 0) {
      const RodSupport& ref = model.supports[sp.reference];
      gap -= r.col(ref.node) - state.support_position[sp.reference];
      from = ref.node;
    }
    c->segment(sp.constraint_row, sp.constraint_rows) = p * gap;
    if (!jacobian) continue;
    model.ForEachPathElementFrom(from, sp.node, [&](int j, int sign) {
      const int item = model.element_item[j];
      const Eigen::Matrix3d& dr = element_dr[static_cast<size_t>(j)];
      for (int row = 0; row < sp.constraint_rows; ++row) {
        const Eigen::RowVector3d v = -sign * (p.row(row) * dr);
        for (int d = 0; d < 3; ++d) triplets.emplace_back(sp.constraint_row + row, 3 * item + d, v[d]);
      }
    });
  }
  if (!jacobian) return;
  jacobian->resize(m, 3 * n);
  jacobian->setFromTriplets(triplets.begin(), triplets.end());
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
    const int from = sp.reference >= 0 ? model.supports[sp.reference].node : -1;
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
