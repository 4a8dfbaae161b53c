#include "cablefit/core/network/network_model.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/internal/natural_curvature.h"
#include "network_parts.h"
#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/rod_topology.h"

namespace cablefit {
namespace {

// Stiffness of an edge of length ds made of pieces (length_i, K_i) in series with a rotational
// compliance C [rad/(N m)]: ds K^-1 = sum length_i K_i^-1 + C.
Mat3 SeriesStiffness(double ds, const std::vector<std::pair<double, Mat3>>& pieces, double compliance) {
  Mat3 flexibility = compliance * Mat3::Identity();
  for (const auto& [len, k] : pieces) flexibility += len * k.inverse();
  return ds * flexibility.inverse();
}

// Nodes of one branch at its span breakpoints, each span cut into elements of about h.
std::vector<double> BranchNodeS(const RodSpec& rs, double h, int refinement) {
  const std::vector<double> bp = SpanBreakpoints(rs);
  std::vector<double> s = {0.0};
  for (size_t k = 0; k + 1 < bp.size(); ++k) {
    const double len = bp[k + 1] - bp[k];
    const int n = std::max(1, static_cast<int>(std::ceil(len / h - 1e-9))) << refinement;
    for (int i = 1; i <= n; ++i) s.push_back(bp[k] + len * i / n);
    s.back() = bp[k + 1];
  }
  return s;
}

int NearestIndex(const Eigen::VectorXd& s, double v) {
  Eigen::Index i;
  (s.array() - v).abs().minCoeff(&i);
  return static_cast<int>(i);
}

}  // namespace

NetworkModel CompileNetworkModel(const NetworkSpec& spec, double element_length, int refinement) {
  ValidateNetworkSpec(spec);
  if (!(element_length > 0)) throw InvalidInput("element length must be positive");
  NetworkModel net;
  net.spec = spec;
  RodModel& m = net.rod;
  const int nb = static_cast<int>(spec.branches.size());
  const int nj = static_cast<int>(spec.junctions.size());
  net.total_length = TotalLength(spec);
  net.branches.resize(nb);
  net.junctions.resize(nj);
  for (int b = 0; b < nb; ++b) {
    const BranchSpec& br = spec.branches[b];
    if (br.start_junction >= 0) {
      net.junctions[br.start_junction].branches.push_back(b);
      net.junctions[br.start_junction].branch_end.push_back(0);
    }
    if (br.end_junction >= 0) {
      net.junctions[br.end_junction].branches.push_back(b);
      net.junctions[br.end_junction].branch_end.push_back(1);
    }
  }

  // Nodes and elements: junction nodes first, then each branch's own.
  int num_nodes = nj;
  for (int j = 0; j < nj; ++j) net.junctions[j].node = j;
  std::vector<double> node_s(nj, 0.0);
  std::vector<int> element_branch;
  for (int b = 0; b < nb; ++b) {
    const BranchSpec& br = spec.branches[b];
    BranchLayout& lay = net.branches[b];
    const std::vector<double> s = BranchNodeS(BranchRodSpec(spec, b), element_length, refinement);
    const int n = static_cast<int>(s.size());
    lay.node_s = Eigen::Map<const Eigen::VectorXd>(s.data(), n);
    for (int k = 0; k < n; ++k) {
      int node;
      if (k == 0 && br.start_junction >= 0) {
        node = br.start_junction;
      } else if (k == n - 1 && br.end_junction >= 0) {
        node = br.end_junction;
      } else {
        node = num_nodes++;
        node_s.push_back(s[k]);
      }
      lay.nodes.push_back(node);
    }
    for (int k = 0; k + 1 < n; ++k) {
      lay.elements.push_back(static_cast<int>(m.element_nodes.size()));
      m.element_nodes.push_back({lay.nodes[k], lay.nodes[k + 1]});
      element_branch.push_back(b);
    }
  }
  const int ne = static_cast<int>(m.element_nodes.size());
  m.num_elements = ne;
  m.node_s = Eigen::Map<const Eigen::VectorXd>(node_s.data(), num_nodes);
  m.element_length.resize(ne);
  for (int b = 0; b < nb; ++b) {
    const BranchLayout& lay = net.branches[b];
    for (size_t k = 0; k < lay.elements.size(); ++k)
      m.element_length[lay.elements[k]] = lay.node_s[k + 1] - lay.node_s[k];
  }

  // Supports, in branch order; the first one that holds position is the anchor.
  for (int b = 0; b < nb; ++b) {
    BranchLayout& lay = net.branches[b];
    for (const SupportSpec& sp : spec.branches[b].supports) {
      const double s = std::clamp(sp.s, 0.0, spec.branches[b].length);
      lay.supports.push_back(static_cast<int>(m.supports.size()));
      m.supports.push_back(MakeRodSupport(sp, s, lay.nodes[NearestIndex(lay.node_s, s)]));
      net.support_branch.push_back(b);
    }
  }
  net.num_spec_supports = static_cast<int>(m.supports.size());
  m.anchor_support = -1;
  for (size_t k = 0; k < m.supports.size() && m.anchor_support < 0; ++k)
    if (!m.supports[k].sliding) m.anchor_support = static_cast<int>(k);
  m.anchor_node = m.supports[m.anchor_support].node;
  for (size_t k = 0; k < m.supports.size(); ++k) {
    if (static_cast<int>(k) == m.anchor_support) continue;
    m.supports[k].constraint_row = m.num_constraints;
    m.supports[k].constraint_rows = m.supports[k].sliding ? 2 : 3;
    m.num_constraints += m.supports[k].constraint_rows;
  }

  // Items and edges along each branch (support frames between elements, as on a single rod).
  m.element_item.assign(ne, -1);
  std::vector<Mat3> branch_k(nb);
  for (int b = 0; b < nb; ++b) {
    const BranchSpec& br = spec.branches[b];
    BranchLayout& lay = net.branches[b];
    branch_k[b] = MaterialStiffness(br.material);
    const double cable = branch_k[b].diagonal().maxCoeff() / br.length;
    std::vector<int> items;
    auto add_support_items = [&](int local_node) {
      for (int k : lay.supports) {
        RodSupport& rs = m.supports[k];
        if (rs.node != lay.nodes[local_node] || rs.kind == SupportKind::kPin) continue;
        const SupportSpec& sp = br.supports[k - lay.supports.front()];
        rs.item = static_cast<int>(m.items.size());
        m.items.push_back(MakeSupportItem(sp, k, rs.s, cable));
        items.push_back(rs.item);
      }
    };
    for (size_t k = 0; k < lay.elements.size(); ++k) {
      add_support_items(static_cast<int>(k));
      RodItem it;
      it.element = lay.elements[k];
      it.length = m.element_length[it.element];
      it.s = 0.5 * (lay.node_s[k] + lay.node_s[k + 1]);
      m.element_item[it.element] = static_cast<int>(m.items.size());
      items.push_back(static_cast<int>(m.items.size()));
      m.items.push_back(it);
    }
    add_support_items(static_cast<int>(lay.nodes.size()) - 1);
    lay.first_item = items.front();
    lay.last_item = items.back();
    for (size_t k = 0; k + 1 < items.size(); ++k) {
      const RodItem& ia = m.items[items[k]];
      const RodItem& ib = m.items[items[k + 1]];
      RodEdge e;
      e.a = items[k];
      e.b = items[k + 1];
      e.ds = ib.s - ia.s;
      CABLEFIT_CHECK(e.ds > 0, "frame samples must advance along the branch");
      e.s = 0.5 * (ia.s + ib.s);
      e.stiffness = branch_k[b];
      e.natural = AverageNaturalCurvature(br.natural_curvature, ia.s, ib.s);
      m.edges.push_back(e);
    }
  }

  // Junctions: a breakout frame tied to every branch end, or a splice edge between two ends.
  // Rest rotations come from the drawn frames once all items exist.
  auto end_item = [&](int b, int end) {
    return end == 0 ? net.branches[b].first_item : net.branches[b].last_item;
  };
  auto half_element = [&](int b, int end) {
    return 0.5 * m.items[end_item(b, end)].length;
  };
  for (int j = 0; j < nj; ++j) {
    JunctionLayout& jl = net.junctions[j];
    const double compliance = spec.junctions[j].compliance;
    if (jl.branches.size() == 2) {
      // Orient the splice along the first branch's direction into the junction when possible.
      int b0 = jl.branches[0], e0 = jl.branch_end[0], b1 = jl.branches[1], e1 = jl.branch_end[1];
      if (e0 == 0 && e1 == 1) {
        std::swap(b0, b1);
        std::swap(e0, e1);
      }
      RodEdge e;
      e.a = end_item(b0, e0);
      e.b = end_item(b1, e1);
      const double h0 = half_element(b0, e0), h1 = half_element(b1, e1);
      e.ds = h0 + h1;
      e.s = 0.0;
      e.stiffness = SeriesStiffness(e.ds, {{h0, branch_k[b0]}, {h1, branch_k[b1]}}, compliance);
      e.has_rest = true;
      jl.edges = {-1, -1};
      m.edges.push_back(e);
      continue;
    }
    RodItem it;
    it.is_element = false;
    it.junction = j;
    jl.item = static_cast<int>(m.items.size());
    m.items.push_back(it);
    for (size_t k = 0; k < jl.branches.size(); ++k) {
      const int b = jl.branches[k], end = jl.branch_end[k];
      RodEdge e;
      // Always from the breakout to the branch: the strain is then measured in a frame that
      // follows the branch's material frame (q_junction * rest), where its stiffness applies.
      e.a = jl.item;
      e.b = end_item(b, end);
      e.ds = half_element(b, end);
      e.s = end == 0 ? 0.0 : spec.branches[b].length;
      e.stiffness = SeriesStiffness(e.ds, {{e.ds, branch_k[b]}}, compliance);
      e.has_rest = true;
      jl.edges.push_back(static_cast<int>(m.edges.size()));
      m.edges.push_back(e);
    }
  }

  // Masses and loads.
  m.node_mass = Eigen::VectorXd::Zero(num_nodes);
  for (int j = 0; j < ne; ++j) {
    const double half = 0.5 * spec.branches[element_branch[j]].material.linear_density * m.element_length[j];
    m.node_mass[m.element_nodes[j][0]] += half;
    m.node_mass[m.element_nodes[j][1]] += half;
  }
  for (int j = 0; j < nj; ++j) m.node_mass[net.junctions[j].node] += spec.junctions[j].mass;
  std::vector<Vec3> node_force(num_nodes);
  for (int i = 0; i < num_nodes; ++i) node_force[i] = m.node_mass[i] * spec.gravity;
  double load_sum = 0.0, max_bending = 0.0;
  for (int b = 0; b < nb; ++b) {
    const BranchLayout& lay = net.branches[b];
    max_bending = std::max(max_bending, spec.branches[b].material.bending_stiffness);
    for (const PointLoadSpec& pl : spec.branches[b].point_loads) {
      const int node = lay.nodes[NearestIndex(lay.node_s, pl.s)];
      node_force[node] += pl.force;
      m.node_loads.emplace_back(node, pl.force);
      load_sum += pl.force.norm();
    }
  }
  BuildNodeTree(&m);
  BuildItemTree(&m);
  m.element_axial_stiffness.resize(ne);
  for (int j = 0; j < ne; ++j) {
    m.element_axial_stiffness[j] = spec.branches[element_branch[j]].material.axial_stiffness;
  }
  AssignConstraintReferences(&m);
  ComputeLoadCoefficients(node_force, &m);
  m.spec.name = spec.name;
  m.spec.length = net.total_length;
  m.spec.gravity = spec.gravity;
  m.spec.material = spec.branches[0].material;
  m.force_scale = std::max({m.node_mass.sum() * spec.gravity.norm(), load_sum,
                            max_bending / (net.total_length * net.total_length)});

  // Rest rotations of junction edges: the drawn relative frames.
  const std::vector<Eigen::Vector4d> drawn = DrawnFrames(net);
  for (RodEdge& e : m.edges)
    if (e.has_rest) e.rest = quat::Multiply(quat::Conjugate(drawn[e.a]), drawn[e.b]).normalized();
  return net;
}

}  // namespace cablefit
