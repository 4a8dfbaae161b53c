// The tree structure of a compiled RodModel, shared by the single-rod and network compilers:
// the node tree rooted at the anchor (positions as path sums), the frame-sample tree of the
// Hessian, and the load coefficients that make gravity linear in the element tangents.
#pragma once

#include <vector>

#include "cablefit/core/rod/rod_model.h"

namespace cablefit::internal {

/// Fills node_parent, node_parent_element, node_parent_sign, node_order from element_nodes and
/// anchor_node. Every node must be reachable from the anchor and the elements must form a tree.
void BuildNodeTree(RodModel* model);

/// Fills item_parent and item_order from the edges (rooted at the last item of each connected
/// group, so a chain gets parent(i) = i + 1). The edges must form a forest.
void BuildItemTree(RodModel* model);

/// load_coefficient[j] = -sign h_j * (sum of node forces beyond element j as seen from the
/// anchor), so that -sum_i F_i . r_i = sum_j a_j . d3_j + const.
void ComputeLoadCoefficients(const std::vector<Vec3>& node_force, RodModel* model);  // [N]

/// Sets every support's constraint reference (see RodSupport::reference). Call after
/// BuildNodeTree, and again when supports are added.
void AssignConstraintReferences(RodModel* model);

}  // namespace cablefit::internal
