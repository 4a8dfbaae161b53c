#include "cablefit/core/rod/internal/support_targets.h"

#include <Eigen/Geometry>
#include <cmath>

#include "cablefit/core/base/internal/quaternion.h"

namespace cablefit::internal {

Eigen::Vector4d SupportTargetQuaternion(const RodSupport& support) {
  return quat::FromMatrix(support.frame.Matrix());
}

void SetSupportTargets(const RodModel& model, double t, const RodState& start, RodState* state) {
  const size_t ns = model.supports.size();
  state->support_position.resize(ns);
  state->support_q.resize(ns);
  for (size_t k = 0; k < ns; ++k) {
    const RodSupport& sp = model.supports[k];
    const Eigen::Vector4d target = SupportTargetQuaternion(sp);
    if (t >= 1.0 || start.support_position.size() != ns) {
      state->support_position[k] = sp.position;
      state->support_q[k] = target;
      continue;
    }
    state->support_position[k] = (1 - t) * start.support_position[k] + t * sp.position;
    const Eigen::Vector4d& a = start.support_q[k];
    Eigen::Quaterniond qa(a[0], a[1], a[2], a[3]), qb(target[0], target[1], target[2], target[3]);
    const Eigen::Quaterniond qs = qa.slerp(t, qb);
    state->support_q[k] = Eigen::Vector4d(qs.w(), qs.x(), qs.y(), qs.z());
  }
}

void ApplySupportTargets(const RodModel& model, RodState* state) {
  for (size_t i = 0; i < model.items.size(); ++i) {
    const RodItem& it = model.items[i];
    if (it.is_element || it.support < 0) continue;
    const Eigen::Vector4d& qt = state->support_q[it.support];
    if (it.masked[0] && it.masked[1] && it.masked[2]) {
      state->q[i] = qt;
    } else if (it.masked[0] && it.masked[1]) {
      // Clip: keep the current rotation about the tangent.
      const Eigen::Vector4d rel = quat::Multiply(quat::Conjugate(qt), state->q[i]);
      const double angle = 2.0 * std::atan2(rel[3], rel[0]);
      state->q[i] = quat::Multiply(qt, quat::Exp(Eigen::Vector3d(0, 0, angle)));
    }
  }
  AlignQuaternionSigns(model, state);
}

void AlignQuaternionSigns(const RodModel& model, RodState* state) {
  // Roots first, so every frame is compared with an already aligned neighbour.
  // Across an edge with a rest rotation, q_b is compared with q_a * rest.
  for (auto it = model.item_order.rbegin(); it != model.item_order.rend(); ++it) {
    const int i = *it, p = model.item_parent[i];
    if (p < 0) continue;
    const RodEdge& e = model.edges[model.item_parent_edge[i]];
    const double dot = !e.has_rest ? state->q[i].dot(state->q[p])
                       : e.b == i  ? state->q[i].dot(quat::Multiply(state->q[p], e.rest))
                                   : quat::Multiply(state->q[i], e.rest).dot(state->q[p]);
    if (dot < 0) state->q[i] = -state->q[i];
  }
}

}  // namespace cablefit::internal
