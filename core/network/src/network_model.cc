#include "cablefit/core/network/network_model.h"

#include <Eigen/Geometry>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/internal/quaternion.h"
#include "network_parts.h"

namespace cablefit {
namespace {

// A pre-formed branch's edges get the drawn shape's own Darboux vectors (the discrete strain
// u = (2/ds) Im(conj(q_a) q_b) of the drawn frames, as the bending energy measures it) as rest
// curvature on top of any natural curvature: at zero load the drawn shape is then its
// equilibrium, whatever the element length of the level. Junction edges keep their rest
// rotations, which hold the drawn angles already.
void AddPreformedCurvature(NetworkModel& net, std::vector<Eigen::Vector4d> drawn) {
  const RodModel& m = net.rod;
  // A clamp or clip holds its frame where it will be held, its tangent the curve's at the
  // support, not along the neighbouring element's chord (which DrawnFrames gives its item):
  // half an element's turning apart, which the clamp would force into the preformed cable
  // (5 mm in the middle of a 625 mm cable clamped where it bends at 20 mm radius). A clamp's
  // item takes the held frame; a clip's, free to turn about its tangent, the element's frame
  // turned the least way onto the held tangent.
  for (size_t i = 0; i < m.items.size(); ++i) {
    const RodItem& it = m.items[i];
    if (it.is_element || it.junction >= 0 || it.support < 0) continue;
    const RodSupport& sp = m.supports[static_cast<size_t>(it.support)];
    if (sp.kind == SupportKind::kClamp) {
      drawn[i] = internal::quat::FromMatrix(sp.frame.Matrix());
    } else {
      const Eigen::Matrix3d r = internal::quat::ToMatrix(drawn[i]);
      const Eigen::Matrix3d turn =
          Eigen::Quaterniond::FromTwoVectors(r.col(2), sp.frame.d3.normalized()).toRotationMatrix();
      drawn[i] = internal::quat::FromMatrix(turn * r);
    }
  }
  std::vector<int> item_branch(m.items.size(), -1);
  for (size_t b = 0; b < net.branches.size(); ++b)
    for (const int element : net.branches[b].elements)
      item_branch[static_cast<size_t>(m.element_item[static_cast<size_t>(element)])] =
          static_cast<int>(b);
  for (size_t i = 0; i < m.items.size(); ++i)
    if (!m.items[i].is_element && m.items[i].junction < 0 && m.items[i].support >= 0)
      item_branch[i] = net.support_branch[static_cast<size_t>(m.items[i].support)];
  for (RodEdge& e : net.rod.edges) {
    const int b = item_branch[static_cast<size_t>(e.a)];
    if (e.has_rest || b < 0 || b != item_branch[static_cast<size_t>(e.b)] ||
        !net.spec.branches[static_cast<size_t>(b)].preformed)
      continue;
    // q and -q are the same frame, but the strain is measured on the representative nearest
    // the neighbour's (as the state aligns its signs): the other one reads a full turn.
    const Eigen::Vector4d& qa = drawn[static_cast<size_t>(e.a)];
    Eigen::Vector4d qb = drawn[static_cast<size_t>(e.b)];
    if (qa.dot(qb) < 0) qb = -qb;
    e.natural += (2.0 / e.ds) * (internal::quat::LeftStrain(qa) * qb);
  }
}

}  // namespace

NetworkModel CompileNetworkModel(const NetworkSpec& spec, double element_length, int refinement) {
  ValidateNetworkSpec(spec);
  if (!(element_length > 0)) throw InvalidInput("element length must be positive");
  const int nb = static_cast<int>(spec.branches.size());
  std::vector<RodSpec> rods;
  for (int b = 0; b < nb; ++b) rods.push_back(BranchRodSpec(spec, b));
  Discretisation disc;
  disc.element_length = element_length;
  disc.refinement = refinement;
  std::vector<internal::ModelBranch> branches(nb);
  for (int b = 0; b < nb; ++b) {
    branches[b].spec = &rods[b];
    branches[b].node_s = internal::BranchNodeArcLengths(rods[b], disc);
    branches[b].start_junction = spec.branches[b].start_junction;
    branches[b].end_junction = spec.branches[b].end_junction;
  }
  std::vector<internal::ModelJunction> junctions;
  for (const JunctionSpec& j : spec.junctions) junctions.push_back({j.compliance, j.mass});
  internal::ModelLayout layout =
      internal::CompileModelLayout(branches, junctions, spec.gravity, spec.name);

  NetworkModel net;
  net.spec = spec;
  net.rod = std::move(layout.model);
  net.branches = std::move(layout.branches);
  net.junctions = std::move(layout.junctions);
  net.support_branch = std::move(layout.support_branch);
  net.num_spec_supports = static_cast<int>(net.rod.supports.size());
  net.total_length = TotalLength(spec);
  // Rest rotations of junction edges: the drawn relative frames.
  const std::vector<Eigen::Vector4d> drawn = DrawnFrames(net);
  for (RodEdge& e : net.rod.edges)
    if (e.has_rest)
      e.rest =
          internal::quat::Multiply(internal::quat::Conjugate(drawn[e.a]), drawn[e.b]).normalized();
  AddPreformedCurvature(net, drawn);
  return net;
}

}  // namespace cablefit
