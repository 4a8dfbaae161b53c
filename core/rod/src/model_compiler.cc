#include "cablefit/core/rod/internal/model_compiler.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/internal/natural_curvature.h"
#include "cablefit/core/rod/internal/rod_topology.h"

namespace cablefit::internal {
namespace {

// Stiffness of an edge of length ds made of pieces (length_i, K_i) in series with a rotational
// compliance C [rad/(N m)]: ds K^-1 = sum length_i K_i^-1 + C.
Mat3 SeriesStiffness(double ds, const std::vector<std::pair<double, Mat3>>& pieces, double compliance) {
  Mat3 flexibility = compliance * Mat3::Identity();
  for (const auto& [len, k] : pieces) flexibility += len * k.inverse();
  return ds * flexibility.inverse();
}

// The material stiffness at arc length s of a branch: its own, plus every sleeve over s.
Mat3 StiffnessAt(const RodSpec& spec, const Mat3& own, double s) {
  Mat3 k = own;
  for (const SleeveSpec& sl : spec.sleeves)
    if (s > sl.s_begin && s < sl.s_end)
      k += Eigen::Vector3d(sl.bending_stiffness, sl.bending_stiffness, sl.torsional_stiffness)
               .asDiagonal();
  return k;
}

// Stiffness of the edge between frame samples at sa < sb: the pieces between the sleeve ends
// inside it in series (without sleeves, or within one, simply the material there).
Mat3 EdgeStiffness(const RodSpec& spec, const Mat3& own, double sa, double sb) {
  if (spec.sleeves.empty()) return own;
  std::vector<double> cuts = {sa, sb};
  for (const SleeveSpec& sl : spec.sleeves)
    for (const double c : {sl.s_begin, sl.s_end})
      if (c > sa && c < sb) cuts.push_back(c);
  std::sort(cuts.begin(), cuts.end());
  if (cuts.size() == 2) return StiffnessAt(spec, own, 0.5 * (sa + sb));
  std::vector<std::pair<double, Mat3>> pieces;
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
    if (cuts[i + 1] > cuts[i])
      pieces.emplace_back(cuts[i + 1] - cuts[i], StiffnessAt(spec, own, 0.5 * (cuts[i] + cuts[i + 1])));
  return SeriesStiffness(sb - sa, pieces, 0.0);
}

// Mass per length at arc length s of a branch [kg/m]: its own, plus every sleeve over s.
double DensityAt(const RodSpec& spec, double s) {
  double rho = spec.material.linear_density;
  for (const SleeveSpec& sl : spec.sleeves)
    if (s > sl.s_begin && s < sl.s_end) rho += sl.linear_density;
  return rho;
}

int NearestIndex(const Eigen::VectorXd& s, double v) {
  Eigen::Index i;
  (s.array() - v).abs().minCoeff(&i);
  return static_cast<int>(i);
}

// Nodes and elements: junction nodes first, then each branch's own.
void LayOutNodes(const std::vector<ModelBranch>& branches, ModelLayout* out,
                 std::vector<int>* element_branch) {
  RodModel& m = out->model;
  const int nj = static_cast<int>(out->junctions.size());
  int num_nodes = nj;
  std::vector<double> node_s(nj, 0.0);
  for (int j = 0; j < nj; ++j) out->junctions[j].node = j;
  for (size_t b = 0; b < branches.size(); ++b) {
    const ModelBranch& br = branches[b];
    BranchLayout& lay = out->branches[b];
    const int n = static_cast<int>(br.node_s.size());
    if (n < 2) throw InvalidInput("a span needs at least one element");
    lay.node_s = Eigen::Map<const Eigen::VectorXd>(br.node_s.data(), n);
    for (int k = 0; k < n; ++k) {
      int node;
      if (k == 0 && br.start_junction >= 0) {
        node = br.start_junction;
      } else if (k == n - 1 && br.end_junction >= 0) {
        node = br.end_junction;
      } else {
        node = num_nodes++;
        node_s.push_back(br.node_s[k]);
      }
      lay.nodes.push_back(node);
    }
    for (int k = 0; k + 1 < n; ++k) {
      lay.elements.push_back(static_cast<int>(m.element_nodes.size()));
      m.element_nodes.push_back({lay.nodes[k], lay.nodes[k + 1]});
      element_branch->push_back(static_cast<int>(b));
    }
  }
  const int ne = static_cast<int>(m.element_nodes.size());
  m.num_elements = ne;
  m.node_s = Eigen::Map<const Eigen::VectorXd>(node_s.data(), num_nodes);
  m.element_length.resize(ne);
  for (const BranchLayout& lay : out->branches)
    for (size_t k = 0; k < lay.elements.size(); ++k)
      m.element_length[lay.elements[k]] = lay.node_s[k + 1] - lay.node_s[k];
}

// Supports in branch order; the first one that holds position is the anchor, every other one
// gets its constraint rows.
void LayOutSupports(const std::vector<ModelBranch>& branches, ModelLayout* out) {
  RodModel& m = out->model;
  for (size_t b = 0; b < branches.size(); ++b) {
    BranchLayout& lay = out->branches[b];
    const RodSpec& spec = *branches[b].spec;
    for (const SupportSpec& sp : spec.supports) {
      const double s = std::clamp(sp.s, 0.0, spec.length);
      lay.supports.push_back(static_cast<int>(m.supports.size()));
      m.supports.push_back(MakeRodSupport(sp, s, lay.nodes[NearestIndex(lay.node_s, s)]));
      out->support_branch.push_back(static_cast<int>(b));
    }
  }
  if (m.supports.empty()) throw InvalidInput("the cable has no support");
  m.anchor_support = -1;
  for (size_t k = 0; k < m.supports.size() && m.anchor_support < 0; ++k)
    if (!m.supports[k].sliding) m.anchor_support = static_cast<int>(k);
  if (m.anchor_support < 0)
    throw InvalidInput("every support slides: nothing fixes the cable's position along itself");
  m.anchor_node = m.supports[m.anchor_support].node;
  for (size_t k = 0; k < m.supports.size(); ++k) {
    if (static_cast<int>(k) == m.anchor_support) continue;
    m.supports[k].constraint_row = m.num_constraints;
    m.supports[k].constraint_rows = m.supports[k].sliding ? 2 : 3;
    m.num_constraints += m.supports[k].constraint_rows;
  }
}

// Items and edges along each branch: support frames sit at their node, between the
// neighbouring elements.
void LayOutBranchItems(const std::vector<ModelBranch>& branches,
                       const std::vector<Mat3>& branch_k, ModelLayout* out) {
  RodModel& m = out->model;
  m.element_item.assign(m.num_elements, -1);
  for (size_t b = 0; b < branches.size(); ++b) {
    const RodSpec& spec = *branches[b].spec;
    BranchLayout& lay = out->branches[b];
    const double cable = branch_k[b].diagonal().maxCoeff() / spec.length;
    std::vector<int> items;
    auto add_support_items = [&](int local_node) {
      for (size_t i = 0; i < lay.supports.size(); ++i) {
        const int k = lay.supports[i];
        RodSupport& rs = m.supports[k];
        if (rs.node != lay.nodes[local_node] || rs.kind == SupportKind::kPin) continue;
        rs.item = static_cast<int>(m.items.size());
        m.items.push_back(MakeSupportItem(spec.supports[i], k, rs.s, cable));
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
      e.stiffness = EdgeStiffness(spec, branch_k[b], ia.s, ib.s);
      e.natural = AverageNaturalCurvature(spec.natural_curvature, ia.s, ib.s);
      m.edges.push_back(e);
    }
  }
}

// Junctions: a breakout frame tied to every branch end, or a splice edge between two ends.
void LayOutJunctions(const std::vector<ModelBranch>& branches,
                     const std::vector<ModelJunction>& junctions,
                     const std::vector<Mat3>& branch_k, ModelLayout* out) {
  RodModel& m = out->model;
  auto end_item = [&](int b, int end) {
    return end == 0 ? out->branches[b].first_item : out->branches[b].last_item;
  };
  auto half_element = [&](int b, int end) { return 0.5 * m.items[end_item(b, end)].length; };
  // The material of a branch's end element (a sleeve reaching the branch end included).
  auto end_stiffness = [&](int b, int end) {
    return StiffnessAt(*branches[b].spec, branch_k[b], m.items[end_item(b, end)].s);
  };
  for (size_t j = 0; j < junctions.size(); ++j) {
    JunctionLayout& jl = out->junctions[j];
    const double compliance = junctions[j].compliance;
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
      e.stiffness = SeriesStiffness(e.ds, {{h0, end_stiffness(b0, e0)}, {h1, end_stiffness(b1, e1)}},
                                    compliance);
      e.has_rest = true;
      jl.edges = {-1, -1};
      m.edges.push_back(e);
      continue;
    }
    RodItem it;
    it.is_element = false;
    it.junction = static_cast<int>(j);
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
      e.s = end == 0 ? 0.0 : branches[b].spec->length;
      e.stiffness = SeriesStiffness(e.ds, {{e.ds, end_stiffness(b, end)}}, compliance);
      e.has_rest = true;
      jl.edges.push_back(static_cast<int>(m.edges.size()));
      m.edges.push_back(e);
    }
  }
}

}  // namespace

std::vector<double> BranchNodeArcLengths(const RodSpec& spec, const Discretisation& disc) {
  const std::vector<double> bp = SpanBreakpoints(spec);
  const int spans = static_cast<int>(bp.size()) - 1;
  if (!disc.elements_per_span.empty() && static_cast<int>(disc.elements_per_span.size()) != spans)
    throw InvalidInput("discretisation has " + std::to_string(disc.elements_per_span.size()) +
                       " span counts for " + std::to_string(spans) + " spans");
  if (disc.elements_per_span.empty() && !(disc.element_length > 0))
    throw InvalidInput("element length must be positive");
  std::vector<double> s = {0.0};
  for (int k = 0; k < spans; ++k) {
    const double len = bp[k + 1] - bp[k];
    int n = disc.elements_per_span.empty()
                ? std::max(1, static_cast<int>(std::ceil(len / disc.element_length - 1e-9)))
                : disc.elements_per_span[k];
    n <<= disc.refinement;
    if (n < 1) throw InvalidInput("a span needs at least one element");
    for (int i = 1; i <= n; ++i) s.push_back(bp[k] + len * i / n);
    s.back() = bp[k + 1];
  }
  return s;
}

ModelLayout CompileModelLayout(const std::vector<ModelBranch>& branches,
                               const std::vector<ModelJunction>& junctions, const Vec3& gravity,
                               const std::string& name) {
  ModelLayout out;
  RodModel& m = out.model;
  m.name = name;
  m.gravity = gravity;
  const int nb = static_cast<int>(branches.size());
  out.branches.resize(nb);
  out.junctions.resize(junctions.size());
  for (int b = 0; b < nb; ++b) {
    m.length += branches[b].spec->length;
    for (int end : {0, 1}) {
      const int j = end == 0 ? branches[b].start_junction : branches[b].end_junction;
      if (j < 0) continue;
      out.junctions[j].branches.push_back(b);
      out.junctions[j].branch_end.push_back(end);
    }
  }
  std::vector<int> element_branch;
  LayOutNodes(branches, &out, &element_branch);
  LayOutSupports(branches, &out);
  std::vector<Mat3> branch_k(nb);
  for (int b = 0; b < nb; ++b) branch_k[b] = MaterialStiffness(branches[b].spec->material);
  LayOutBranchItems(branches, branch_k, &out);
  LayOutJunctions(branches, junctions, branch_k, &out);

  // Lumped node masses, dead loads, and their per-element potential coefficients.
  const int ne = m.num_elements, num_nodes = static_cast<int>(m.node_s.size());
  m.node_mass = Eigen::VectorXd::Zero(num_nodes);
  for (int e = 0; e < ne; ++e) {
    const double half = 0.5 * DensityAt(*branches[element_branch[e]].spec, m.items[m.element_item[e]].s) *
                        m.element_length[e];
    m.node_mass[m.element_nodes[e][0]] += half;
    m.node_mass[m.element_nodes[e][1]] += half;
  }
  for (size_t j = 0; j < junctions.size(); ++j)
    m.node_mass[out.junctions[j].node] += junctions[j].mass;
  std::vector<Vec3> node_force(num_nodes);
  for (int i = 0; i < num_nodes; ++i) node_force[i] = m.node_mass[i] * gravity;
  double load_sum = 0.0, max_bending = 0.0;
  for (int b = 0; b < nb; ++b) {
    const BranchLayout& lay = out.branches[b];
    const RodSpec& spec = *branches[b].spec;
    max_bending = std::max(max_bending, spec.material.bending_stiffness);
    for (const PointLoadSpec& pl : spec.point_loads) {
      const int node = lay.nodes[NearestIndex(lay.node_s, std::clamp(pl.s, 0.0, spec.length))];
      node_force[node] += pl.force;
      m.node_loads.emplace_back(node, pl.force);
      load_sum += pl.force.norm();
    }
  }
  BuildNodeTree(&m);
  BuildItemTree(&m);
  m.element_axial_stiffness.resize(ne);
  for (int e = 0; e < ne; ++e)
    m.element_axial_stiffness[e] = branches[element_branch[e]].spec->material.axial_stiffness;
  AssignConstraintReferences(&m);
  ComputeLoadCoefficients(node_force, &m);
  // The scale of the forces: the weight, the dead loads, or the bending force of the stiffest
  // branch over the whole length, whichever is largest.
  m.force_scale = std::max({m.node_mass.sum() * gravity.norm(), load_sum,
                            max_bending / (m.length * m.length)});
  return out;
}

}  // namespace cablefit::internal
