// A rod network compiled into one RodModel (so one Newton system and one stability verdict for
// the whole harness), plus the bookkeeping that maps it back to branches and junctions. It is
// laid out by the same compiler as a single rod (internal/model_compiler.h).
//
// How junctions are modelled (why): a breakout with three or more branches is a rigid body
// carrying its own frame sample (an item of zero length) at the shared node; every branch end is
// tied to it by a bending edge whose rest rotation is the drawn relative angle, with the branch's
// own stiffness over half an element in series with the attachment compliance. A junction of
// two branches is a splice: the two end elements are joined directly by such an edge, so a
// network that only splices collinear branches is exactly the rod it represents.
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/network/network_spec.h"
#include "cablefit/core/rod/internal/model_compiler.h"
#include "cablefit/core/rod/rod_model.h"

namespace cablefit {

struct NetworkModel {
  NetworkSpec spec;
  RodModel rod;
  std::vector<internal::BranchLayout> branches;
  std::vector<internal::JunctionLayout> junctions;
  std::vector<int> support_branch;  // per model support: its branch
  int num_spec_supports = 0;        // model supports beyond these are contacts
  double total_length = 0.0;        // [m]
};

/// Validates the network (throws InvalidInput naming the branch or junction) and compiles it
/// with elements of about `element_length` [m] (every span at least one element), times
/// 2^refinement.
NetworkModel CompileNetworkModel(const NetworkSpec& spec, double element_length,
                                 int refinement = 0);

/// Validation only (CompileNetworkModel calls it).
void ValidateNetworkSpec(const NetworkSpec& spec);

}  // namespace cablefit
