#include "cablefit/core/solver/rod_solution.h"

#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/rod_energy.h"

namespace cablefit {

RodSolution ExtractSolution(const RodModel& model, const RodState& state,
                            const StaticsSummary& summary) {
  RodSolution sol;
  sol.summary = summary;
  const int ne = model.num_elements;
  sol.centerline.s = model.node_s;
  sol.centerline.points = state.NodePositions(model);
  sol.frame_s.resize(ne);
  sol.frames.resize(ne);
  for (int j = 0; j < ne; ++j) {
    const int item = model.element_item[j];
    sol.frame_s[j] = model.items[item].s;
    const Eigen::Matrix3d r = internal::quat::ToMatrix(state.q[item]);
    sol.frames[j].d1 = r.col(0);
    sol.frames[j].d2 = r.col(1);
    sol.frames[j].d3 = r.col(2);
  }
  // External node forces: lumped weight, point loads, and support reactions (-lambda).
  std::vector<Vec3> node_force(ne + 1);
  const Vec3 g = state.load_factor * model.gravity;
  for (int i = 0; i <= ne; ++i) node_force[i] = model.node_mass[i] * g;
  for (const auto& [node, f] : model.node_loads) node_force[node] += state.load_factor * f;
  sol.reactions.resize(model.supports.size());
  Vec3 total = Vec3::Zero();
  const std::vector<Vec3> rows = internal::SupportReactions(model, state);
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const RodSupport& sp = model.supports[k];
    sol.reactions[k].kind = sp.kind;
    sol.reactions[k].s = sp.s;
    if (static_cast<int>(k) == model.anchor_support) continue;
    sol.reactions[k].force = rows[k];
    node_force[sp.node] += rows[k];
  }
  for (const Vec3& f : node_force) total += f;
  sol.reactions[model.anchor_support].force = -total;
  node_force[model.anchor_node] -= total;
  // Internal force in element j: everything acting on nodes after it.
  sol.internal_force.resize(3, ne);
  Vec3 suffix = Vec3::Zero();
  for (int j = ne - 1; j >= 0; --j) {
    suffix += node_force[j + 1];
    sol.internal_force.col(j) = suffix;
  }
  // Internal moments from the constitutive law on each edge, in world coordinates.
  const int nedge = static_cast<int>(model.edges.size());
  sol.moment_s.resize(nedge);
  sol.internal_moment.resize(3, nedge);
  double elastic = 0.0, twist = 0.0;
  for (int e = 0; e < nedge; ++e) {
    const RodEdge& edge = model.edges[e];
    const Eigen::Vector4d& qa = state.q[edge.a];
    const Eigen::Vector4d& qb = state.q[edge.b];
    const Vec3 u = (2.0 / edge.ds) * (internal::quat::LeftStrain(qa) * qb);
    const Vec3 du = u - internal::RestCurvature(edge, e, state);
    const Vec3 m = edge.stiffness * du;
    elastic += 0.5 * edge.ds * du.dot(m);
    twist += edge.ds * u[2];
    // The relative rotation's axis has equal coordinates in both frames: use their mean.
    const Eigen::Matrix3d ra = internal::quat::ToMatrix(qa), rb = internal::quat::ToMatrix(qb);
    sol.internal_moment.col(e) = 0.5 * (ra + rb) * m;
    sol.moment_s[e] = edge.s;
  }
  // Support moments: the generalised force on each support frame's rotation (body frame), as a
  // world moment exerted by the support on the cable.
  internal::EnergyAccumulator acc;
  acc.Reset(model, nullptr);
  internal::AddBendingEnergy(model, state, &acc);
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const RodSupport& sp = model.supports[k];
    if (sp.item < 0) continue;
    const Eigen::Matrix3d r = internal::quat::ToMatrix(state.q[sp.item]);
    sol.reactions[k].moment = r * acc.gradient.segment<3>(3 * sp.item);
  }
  sol.elastic_energy = elastic;
  sol.energy = summary.final_energy;
  sol.twist_angle = twist;
  return sol;
}

}  // namespace cablefit
