// Compliant clamps (rotation = C m): a rotational spring 1/2 phi^T K phi, K = C^-1, between
// the clamp's frame and the cable's end frame, with phi = 2 Im(conj(q_clamp) q) — the rotation
// vector to second order, consistent with the bending strain measure.
#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/rod_energy.h"

namespace cablefit::internal {

void AddSupportSpringEnergy(const RodModel& model, const RodState& state, EnergyAccumulator* acc) {
  for (size_t i = 0; i < model.items.size(); ++i) {
    const RodItem& it = model.items[i];
    if (!it.has_spring) continue;
    Eigen::Vector4d qt = state.support_q[it.support];
    if (qt.dot(state.q[i]) < 0) qt = -qt;  // q and -q are the same rotation
    const Eigen::Vector4d& q = state.q[i];
    const Eigen::Matrix<double, 3, 4> l = quat::LeftStrain(qt);
    const Vec3 phi = 2.0 * (l * q);
    const Vec3 mom = it.spring_stiffness * phi;
    acc->value += 0.5 * phi.dot(mom);
    const Eigen::Vector4d g = 2.0 * l.transpose() * mom;
    const Eigen::Matrix<double, 4, 3> j = quat::ChartJacobian(q);
    acc->gradient.segment<3>(3 * i) += j.transpose() * g;
    if (!acc->hessian) continue;
    const Eigen::Matrix4d h = 4.0 * l.transpose() * it.spring_stiffness * l;
    acc->hessian->Diag(i) += j.transpose() * h * j - 0.25 * g.dot(q) * Eigen::Matrix3d::Identity();
  }
}

}  // namespace cablefit::internal
