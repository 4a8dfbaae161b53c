#include "cablefit/core/rod_state.h"

#include "cablefit/core/rod_model.h"
#include "quaternion.h"

namespace cablefit {

Eigen::Matrix3Xd RodState::NodePositions(const RodModel& model) const {
  const int ne = model.num_elements;
  Eigen::Matrix3Xd r(3, ne + 1);
  const int a = model.anchor_node;
  r.col(a) = support_position[model.anchor_support];
  for (int j = a; j < ne; ++j)
    r.col(j + 1) = r.col(j) + model.element_length[j] * quat::D3(q[model.element_item[j]]);
  for (int j = a - 1; j >= 0; --j)
    r.col(j) = r.col(j + 1) - model.element_length[j] * quat::D3(q[model.element_item[j]]);
  return r;
}

}  // namespace cablefit
