// The one place a RodModel is laid out, for a single rod and for a rod network alike (a single
// rod is a network of one branch without junctions): nodes and elements, supports with the
// anchor and the constraint rows, frame samples and bending edges (junction edges included),
// lumped masses, dead loads and the force scale. CompileRodModel and CompileNetworkModel only
// validate their spec, choose the nodes and call it.
#pragma once

#include <vector>

#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/rod_spec.h"

namespace cablefit::internal {

/// Where a branch of the compiled model lies.
struct BranchLayout {
  std::vector<int> nodes;     // model nodes in order of increasing s (ends may be junction nodes)
  std::vector<int> elements;  // model elements in order of increasing s
  Eigen::VectorXd node_s;     // nodes.size() [m] arc length along the branch
  std::vector<int> supports;  // model support index of each spec support of the branch
  int first_item = -1, last_item = -1;  // items at the two ends (tied to junctions)
};

/// Where a junction of the compiled model lies.
struct JunctionLayout {
  int node = -1;
  int item = -1;               // the breakout's frame sample, -1 for a two-branch splice
  std::vector<int> branches;   // attached branches
  std::vector<int> branch_end;  // 0: the branch's start is attached, 1: its end
  std::vector<int> edges;      // per attached branch: its edge to the junction frame (-1 for a splice)
};

/// One branch to compile: a validated rod spec (its gravity is not read: the model's applies)
/// and its nodes.
struct ModelBranch {
  const RodSpec* spec = nullptr;
  std::vector<double> node_s;  // [m] from 0 to spec->length, every span breakpoint a node
  int start_junction = -1;     // junction index, -1 = free end
  int end_junction = -1;
};

/// One junction (breakout or splice) joining two or more branch ends.
struct ModelJunction {
  double compliance = 0.0;  // [rad/(N m)] of every branch attachment, 0 = rigid
  double mass = 0.0;        // [kg]
};

struct ModelLayout {
  RodModel model;
  std::vector<BranchLayout> branches;
  std::vector<JunctionLayout> junctions;
  std::vector<int> support_branch;  // per model support: its branch
};

/// Lays out the model. Junction edges get has_rest = true and an identity rest rotation: the
/// caller sets the rest rotations from its drawn shape. Throws InvalidInput when no support
/// holds position (every one slides) or a span has no element.
ModelLayout CompileModelLayout(const std::vector<ModelBranch>& branches,
                               const std::vector<ModelJunction>& junctions, const Vec3& gravity,
                               const std::string& name);

/// Nodes of one branch: its span breakpoints, each span cut as `disc` says.
std::vector<double> BranchNodeArcLengths(const RodSpec& spec, const Discretisation& disc);

}  // namespace cablefit::internal
