// Potential of gravity and dead point loads. With positions as prefix sums of h_j d3_j it is
// linear in the element tangents (coefficients precomputed by CompileRodModel), so every element
// contributes independently: a block-diagonal Hessian.
#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/rod_energy.h"

namespace cablefit::internal {

void AddLinearTangentTerm(const Eigen::Vector4d& q, const Vec3& a, int item, EnergyAccumulator* acc) {
  // f(theta) = a . R exp([theta]) e3; with a~ = R^T a:
  // f = a~.e3 + theta.(e3 x a~) + 1/2 theta^T (a~ e3^T + e3 a~^T - 2 (a~.e3) I) theta / 1.
  const Eigen::Matrix3d r = quat::ToMatrix(q);
  const Vec3 at = r.transpose() * a;
  acc->value += at[2];
  acc->gradient.segment<3>(3 * item) += Vec3::UnitZ().cross(at);
  if (!acc->hessian) return;
  Eigen::Matrix3d h = -at[2] * Eigen::Matrix3d::Identity();
  h.col(2) += 0.5 * at;
  h.row(2) += 0.5 * at.transpose();
  acc->hessian->Diag(item) += h;
}

void AddLoadEnergy(const RodModel& model, const RodState& state, EnergyAccumulator* acc) {
  if (state.load_factor == 0.0) return;
  for (int j = 0; j < model.num_elements; ++j) {
    const Vec3 a = state.load_factor * model.load_coefficient[j];
    if (a.squaredNorm() == 0.0) continue;
    const int item = model.element_item[j];
    AddLinearTangentTerm(state.q[item], a, item, acc);
  }
  // The anchor node's own potential is constant in the unknowns but belongs to the energy.
  const Vec3 p0 = state.support_position[model.anchor_support];
  double fixed = 0.0;
  for (int i = 0; i <= model.num_elements; ++i)
    fixed -= model.node_mass[i] * model.gravity.dot(p0);
  for (const auto& [node, f] : model.node_loads) fixed -= f.dot(p0);
  acc->value += state.load_factor * fixed;
}

}  // namespace cablefit::internal
