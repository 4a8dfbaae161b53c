#include "cablefit/core/network/network_model.h"

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/internal/quaternion.h"
#include "network_parts.h"

namespace cablefit {

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
  return net;
}

}  // namespace cablefit
