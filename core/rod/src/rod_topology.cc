#include "cablefit/core/rod/internal/rod_topology.h"

#include <deque>

#include "cablefit/core/base/errors.h"

namespace cablefit::internal {

void BuildNodeTree(RodModel* model) {
  const int ne = static_cast<int>(model->element_nodes.size());
  int nn = 0;
  for (const auto& en : model->element_nodes) nn = std::max({nn, en[0] + 1, en[1] + 1});
  nn = std::max(nn, model->anchor_node + 1);
  std::vector<std::vector<int>> incident(nn);
  for (int j = 0; j < ne; ++j) {
    incident[model->element_nodes[j][0]].push_back(j);
    incident[model->element_nodes[j][1]].push_back(j);
  }
  model->node_parent.assign(nn, -2);
  model->node_parent_element.assign(nn, -1);
  model->node_parent_sign.assign(nn, 0);
  model->node_depth.assign(nn, 0);
  model->node_order.clear();
  model->node_order.reserve(nn);
  std::deque<int> queue = {model->anchor_node};
  model->node_parent[model->anchor_node] = -1;
  while (!queue.empty()) {
    const int n = queue.front();
    queue.pop_front();
    model->node_order.push_back(n);
    for (int j : incident[n]) {
      if (j == model->node_parent_element[n]) continue;
      const auto& en = model->element_nodes[j];
      const int other = en[0] == n ? en[1] : en[0];
      CABLEFIT_CHECK(model->node_parent[other] == -2, "rod elements form a closed loop");
      model->node_parent[other] = n;
      model->node_parent_element[other] = j;
      model->node_parent_sign[other] = en[1] == other ? 1 : -1;
      model->node_depth[other] = model->node_depth[n] + 1;
      queue.push_back(other);
    }
  }
  CABLEFIT_CHECK(static_cast<int>(model->node_order.size()) == nn,
                 "some rod nodes are not connected to the anchor");
}

void BuildItemTree(RodModel* model) {
  const int n = static_cast<int>(model->items.size());
  std::vector<std::vector<std::pair<int, int>>> adjacent(n);  // (neighbour, edge)
  for (size_t k = 0; k < model->edges.size(); ++k) {
    const RodEdge& e = model->edges[k];
    adjacent[e.a].emplace_back(e.b, static_cast<int>(k));
    adjacent[e.b].emplace_back(e.a, static_cast<int>(k));
  }
  model->item_parent.assign(n, -2);
  model->item_parent_edge.assign(n, -1);
  std::vector<int> bfs;
  bfs.reserve(n);
  for (int root = n - 1; root >= 0; --root) {
    if (model->item_parent[root] != -2) continue;
    model->item_parent[root] = -1;
    const size_t first = bfs.size();
    bfs.push_back(root);
    for (size_t k = first; k < bfs.size(); ++k) {
      const int i = bfs[k];
      for (const auto& [c, edge] : adjacent[i]) {
        if (edge == model->item_parent_edge[i]) continue;
        CABLEFIT_CHECK(model->item_parent[c] == -2, "frame samples form a closed loop");
        model->item_parent[c] = i;
        model->item_parent_edge[c] = edge;
        bfs.push_back(c);
      }
    }
  }
  model->item_order.assign(bfs.rbegin(), bfs.rend());
}

void ComputeLoadCoefficients(const std::vector<Vec3>& node_force, RodModel* model) {
  const int ne = static_cast<int>(model->element_nodes.size());
  model->load_coefficient.assign(ne, Vec3::Zero());
  std::vector<Vec3> beyond(node_force.begin(), node_force.end());
  for (auto it = model->node_order.rbegin(); it != model->node_order.rend(); ++it) {
    const int node = *it;
    const int parent = model->node_parent[node];
    if (parent < 0) continue;
    const int j = model->node_parent_element[node];
    model->load_coefficient[j] =
        -model->node_parent_sign[node] * model->element_length[j] * beyond[node];
    beyond[parent] += beyond[node];
  }
}

namespace {

// True when support k's row would be compliant: every element between it and the anchor
// stretches (the stretch it is measured over is at least part of that path).
bool Compliant(const RodModel& model, int k) {
  if (model.element_axial_stiffness.size() != model.num_elements || model.supports[k].contact)
    return false;
  bool rigid = false;
  model.ForEachPathElementFrom(-1, model.supports[k].node, [&](int j, int) {
    rigid = rigid || !(model.element_axial_stiffness[j] > 0);
  });
  return !rigid;
}

// Number of elements on the tree path between nodes a and b.
int PathElements(const RodModel& model, int a, int b) {
  int count = 0;
  model.ForEachPathElementFrom(b, a, [&](int, int) { ++count; });
  return count;
}

// Nodes in depth-first preorder from the anchor (children by node index).
std::vector<int> PreorderNodes(const RodModel& model) {
  std::vector<std::vector<int>> children(model.num_nodes());
  for (int n = 0; n < model.num_nodes(); ++n)
    if (model.node_parent[n] >= 0) children[model.node_parent[n]].push_back(n);
  std::vector<int> order, stack = {model.anchor_node};
  order.reserve(model.num_nodes());
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    order.push_back(n);
    for (auto it = children[n].rbegin(); it != children[n].rend(); ++it) stack.push_back(*it);
  }
  return order;
}

// The rows' basis (RodSupport::row_reference, row_chain; RodModel::row_support_order): each
// support with rows measured from the fixed support met last before it in a depth-first walk
// when that one is nearer than its reference. Every such row spans the cable up to where the
// two branches part and down again, and over all supports each element lies on at most two of
// them; measured from the nearest fixed support up the tree instead (the physics' reference),
// every connector of a harness whose trunk is held nowhere else is measured from the anchor,
// their rows all overlap along the trunk and the elimination grows with their number squared.
void AssignRowBasis(RodModel* model, const std::vector<int>& fixed_at) {
  const std::vector<int> preorder = PreorderNodes(*model);
  std::vector<int> previous_fixed(model->num_nodes(), -1);
  int last = -1;
  for (int n : preorder) {
    previous_fixed[n] = last;
    if (fixed_at[n] >= 0 && n != model->anchor_node) last = fixed_at[n];
  }
  std::vector<std::vector<int>> at_node(model->num_nodes());
  for (size_t k = 0; k < model->supports.size(); ++k)
    at_node[model->supports[k].node].push_back(static_cast<int>(k));
  model->row_support_order.clear();
  for (int n : preorder)
    for (int k : at_node[n]) {
      RodSupport& sp = model->supports[k];
      sp.row_reference = sp.reference;
      sp.row_chain.clear();
      if (sp.constraint_row < 0) continue;
      model->row_support_order.push_back(k);
      const int before = previous_fixed[n];
      if (sp.contact || before < 0 || before == k || before == sp.reference) continue;
      const int reference_node = sp.reference >= 0 ? model->supports[sp.reference].node : model->anchor_node;
      if (PathElements(*model, n, model->supports[before].node) >= PathElements(*model, n, reference_node))
        continue;
      // `before` lies below `reference` (preorder), so its chain of references reaches it.
      for (int m = before; m != sp.reference; m = model->supports[m].reference) {
        CABLEFIT_CHECK(m >= 0, "row basis: a support's chain of references misses its own");
        sp.row_chain.push_back(m);
      }
      sp.row_reference = before;
    }
}

}  // namespace

void AssignConstraintReferences(RodModel* model) {
  std::vector<int> fixed_at(model->num_nodes(), -1), contact_at(model->num_nodes(), -1);
  for (size_t k = 0; k < model->supports.size(); ++k) {
    const RodSupport& sp = model->supports[k];
    if (!sp.sliding && !sp.contact && fixed_at[sp.node] < 0) fixed_at[sp.node] = static_cast<int>(k);
    if (sp.contact && contact_at[sp.node] < 0) contact_at[sp.node] = static_cast<int>(k);
  }
  // A contact row may also be measured from a contact up the tree with the same normal (a cable
  // lying along a flat panel): n.(r_k - p_k) - n.(r_j - p_j) = 0 is the same condition once row
  // j holds, and the row then spans only the frames between the two contacts. Measured from the
  // anchor instead, a hundred contacts along a floor make the Jacobian and the elimination dense.
  auto same_normal = [&](const RodSupport& a, int j) {
    return (a.frame.d3.cross(model->supports[j].frame.d3)).norm() < 1e-9 &&
           a.frame.d3.dot(model->supports[j].frame.d3) > 0;
  };
  // Once per support, not per contact looking up the tree (this runs every contact round).
  std::vector<char> compliant(model->supports.size(), 0);
  for (size_t k = 0; k < model->supports.size(); ++k)
    compliant[k] = Compliant(*model, static_cast<int>(k));
  for (size_t k = 0; k < model->supports.size(); ++k) {
    RodSupport& sp = model->supports[k];
    sp.reference = -1;
    if (sp.constraint_row < 0) continue;
    for (int n = sp.node; model->node_parent[n] >= 0;) {
      n = model->node_parent[n];
      if (n == model->anchor_node) break;
      // A contact is never measured from a support that holds its position only up to its
      // stretch (a compliant row): the stretch would shift the contact off the surface.
      if (fixed_at[n] >= 0 && fixed_at[n] != static_cast<int>(k) &&
          !(sp.contact && compliant[fixed_at[n]])) {
        sp.reference = fixed_at[n];
        break;
      }
      if (sp.contact && contact_at[n] >= 0 && contact_at[n] != static_cast<int>(k) &&
          same_normal(sp, contact_at[n])) {
        sp.reference = contact_at[n];
        break;
      }
    }
    // The stretch's axial compliance: sum h / EA from the reference (or the anchor) to the
    // support; rigid when any of its elements is inextensible, and always for a contact.
    sp.compliance = 0.0;
    if (sp.contact || model->element_axial_stiffness.size() != model->num_elements) continue;
    const int from = sp.reference >= 0 ? model->supports[sp.reference].node : -1;
    double compliance = 0.0;
    bool rigid = false;
    model->ForEachPathElementFrom(from, sp.node, [&](int j, int) {
      const double ea = model->element_axial_stiffness[j];
      if (ea > 0) {
        compliance += model->element_length[j] / ea;
      } else {
        rigid = true;
      }
    });
    if (!rigid) sp.compliance = compliance;
  }
  AssignRowBasis(model, fixed_at);
}

}  // namespace cablefit::internal
