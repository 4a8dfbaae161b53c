#include "cablefit/core/rod/rod_state.h"

#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/base/internal/quaternion.h"

namespace cablefit {

Eigen::Matrix3Xd RodState::NodePositions(const RodModel& model) const {
  Eigen::Matrix3Xd r(3, model.num_nodes());
  for (int node : model.node_order) {
    const int parent = model.node_parent[node];
    if (parent < 0) {
      r.col(node) = support_position[model.anchor_support];
      continue;
    }
    const int j = model.node_parent_element[node];
    r.col(node) = r.col(parent) + (model.node_parent_sign[node] * model.element_length[j]) *
                                      internal::quat::D3(q[model.element_item[j]]);
  }
  return r;
}

}  // namespace cablefit
