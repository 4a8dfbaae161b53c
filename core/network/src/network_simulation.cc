#include "cablefit/core/network/network_simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "cablefit/core/rod/initial_shape.h"
#include "network_parts.h"
#include "obstacle_distance.h"
#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/rod_energy.h"
#include "cablefit/core/rod/internal/rod_topology.h"
#include "cablefit/core/rod/internal/support_targets.h"

namespace cablefit {
namespace {

// Samples along one node's path within a solve when looking for a crossed surface.
constexpr int kMaxPathSamples = 1024;

struct Hold {
  int node = -1;
  int obstacle = -1;
  Vec3 point = Vec3::Zero();   // nearest surface point [m]
  Vec3 normal = Vec3::UnitZ();
  double multiplier = 0.0;     // last solve's lambda [N]
};

// Per node: cable radius (the thickest branch meeting there) and one (branch, s) it belongs to.
struct NodeInfo {
  std::vector<double> radius;
  std::vector<int> branch;
  std::vector<double> s;
  std::vector<int> index;   // position in that branch's node list
  std::vector<char> fixed;  // held in position by a support: no contact there
};

NodeInfo NodeTable(const NetworkModel& net) {
  const int nn = net.rod.num_nodes();
  NodeInfo t{std::vector<double>(nn, 0.0), std::vector<int>(nn, -1), std::vector<double>(nn, 0.0),
             std::vector<int>(nn, -1), std::vector<char>(nn, 0)};
  for (size_t b = 0; b < net.branches.size(); ++b) {
    const internal::BranchLayout& lay = net.branches[b];
    const double r = 0.5 * net.spec.branches[b].material.diameter;
    for (size_t k = 0; k < lay.nodes.size(); ++k) {
      const int n = lay.nodes[k];
      t.radius[n] = std::max(t.radius[n], r);
      if (t.branch[n] < 0) {
        t.branch[n] = static_cast<int>(b);
        t.s[n] = lay.node_s[k];
        t.index[n] = static_cast<int>(k);
      }
    }
  }
  for (const RodSupport& sp : net.rod.supports)
    if (!sp.sliding && !sp.contact) t.fixed[sp.node] = 1;
  return t;
}

// The base network with one contact row per hold appended to its supports.
NetworkModel WithHolds(const NetworkModel& base, const std::vector<Hold>& holds, const NodeInfo& info) {
  NetworkModel net = base;
  RodModel& m = net.rod;
  for (const Hold& h : holds) {
    RodSupport sp;
    sp.kind = SupportKind::kPin;
    sp.contact = true;
    sp.node = h.node;
    sp.s = info.s[h.node];
    sp.position = h.point + info.radius[h.node] * h.normal;
    sp.frame = Frame::FromTangentNormal(h.normal, h.normal.unitOrthogonal());
    sp.constraint_row = m.num_constraints;
    sp.constraint_rows = 1;
    m.num_constraints += 1;
    m.supports.push_back(sp);
    net.support_branch.push_back(info.branch[h.node]);
  }
  internal::AssignConstraintReferences(&m);
  return net;
}

// Resizes the state's per-support arrays to `net`: existing supports keep theirs, holds start
// where their node is (the solver moves them onto the surface by continuation if needed).
void FitStateToHolds(const NetworkModel& net, const std::vector<Hold>& holds, RodState* st) {
  const RodModel& m = net.rod;
  const Eigen::Matrix3Xd r = st->NodePositions(m);
  st->support_position.resize(net.num_spec_supports);
  st->support_q.resize(net.num_spec_supports);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m.num_constraints);
  const int base_rows = m.num_constraints - static_cast<int>(holds.size());
  if (st->lambda.size() >= base_rows) lambda.head(base_rows) = st->lambda.head(base_rows);
  for (size_t k = 0; k < holds.size(); ++k) {
    st->support_position.push_back(r.col(holds[k].node));
    st->support_q.emplace_back(1, 0, 0, 0);
    lambda[base_rows + static_cast<int>(k)] = holds[k].multiplier;
  }
  st->lambda = lambda;
}

enum class HoldUpdate { kUnchanged, kChanged, kRevert };

// Holds to release: those that pull, and with `extra` > 0 also up to `extra` held nodes next to
// each of them along its branch. A stretch pinned flat on a surface peels off at its edges one
// node per round; releasing more each round it goes on (the caller doubles `extra`) finds the
// edge in log2 rounds, and nodes released too many fall back in and are held again.
std::vector<char> HoldsToRelease(const NetworkModel& net, const RodState& after, const NodeInfo& info,
                                 const std::vector<Hold>& holds, int extra) {
  const RodModel& m = net.rod;
  // A contact row may be measured from another contact (AssignConstraintReferences), so its
  // multiplier alone is not its force: the reactions sum each row's share.
  const std::vector<Vec3> reaction = internal::SupportReactions(m, after);
  std::vector<int> hold_at(m.num_nodes(), -1);
  for (size_t k = 0; k < holds.size(); ++k) hold_at[holds[k].node] = static_cast<int>(k);
  std::vector<char> release(holds.size(), 0);
  for (size_t k = 0; k < holds.size(); ++k) {
    // The surface can only push (along +normal); a pull means the node wants to leave.
    if (reaction[net.num_spec_supports + k].dot(holds[k].normal) >= -1e-9 * m.force_scale) continue;
    release[k] = 1;
    const int n = holds[k].node, b = info.branch[n];
    if (extra <= 0 || b < 0) continue;
    const std::vector<int>& nodes = net.branches[b].nodes;
    const int size = static_cast<int>(nodes.size());
    for (int dir : {-1, 1}) {
      // At most half of the held run beyond this hold: its middle stays, so a run pulling at
      // both edges (a couple carrying the bending moment where the cable leaves the surface)
      // shrinks towards its middle instead of vanishing and falling back in as a whole.
      int run = 0;
      for (int i = info.index[n] + dir; i >= 0 && i < size && hold_at[nodes[i]] >= 0; i += dir) ++run;
      const int count = std::min(extra, run / 2 - 1);  // if both edges pull, two stay
      for (int c = 0, i = info.index[n] + dir; c < count; ++c, i += dir) release[hold_at[nodes[i]]] = 1;
    }
  }
  return release;
}

// Updates the active set from the state `after` a solve that started from `before`. Holds that
// pull (and, widening, their held neighbours: HoldsToRelease) are released and the others follow
// the nearest surface point. A node that went into a solid, or through it on the way, gets a
// hold on the surface it came from, and the caller restarts from `before` (kRevert).
HoldUpdate UpdateHolds(const NetworkModel& net, const RodState& before, const RodState& after,
                       const ObstacleField& field, const NodeInfo& info, double tolerance,
                       int extra_release, std::vector<Hold>* holds) {
  const RodModel& m = net.rod;
  const Eigen::Matrix3Xd r = after.NodePositions(m);
  const Eigen::Matrix3Xd r0 = before.NodePositions(m);
  const int base_rows = m.num_constraints - static_cast<int>(holds->size());
  HoldUpdate result = HoldUpdate::kUnchanged;
  std::vector<Hold> kept;
  std::vector<char> held(m.num_nodes(), 0);
  const std::vector<char> release = HoldsToRelease(net, after, info, *holds, extra_release);
  for (size_t k = 0; k < holds->size(); ++k) {
    Hold h = (*holds)[k];
    h.multiplier = after.lambda[base_rows + static_cast<int>(k)];
    if (release[k]) {
      result = HoldUpdate::kChanged;
      continue;
    }
    const double radius = info.radius[h.node];
    const ObstacleHit hit = field.Nearest(r.col(h.node), 4 * radius + 1e-3);
    if (hit.obstacle >= 0 && ((hit.point - h.point).norm() > 1e-4 * radius ||
                              (hit.normal - h.normal).norm() > 1e-6)) {
      h.point = hit.point;
      h.normal = hit.normal;
      h.obstacle = hit.obstacle;
      result = HoldUpdate::kChanged;
    }
    held[h.node] = 1;
    kept.push_back(h);
  }
  // How far every free node went into a solid, and the surface it went in through. A node that
  // passed right through a thin part (sheet metal) within one solve is caught on the way: its
  // path from `before` is sampled at half-radius spacing, so the first sample that touches lies
  // within the radius outside the surface it crossed (not already past the middle of a thin
  // part, where the nearest face is the far one). Its depth counts the travel beyond it.
  std::vector<double> depth(m.num_nodes(), 0.0);
  std::vector<ObstacleHit> entry(m.num_nodes());
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (held[n] || info.fixed[n] || info.radius[n] <= 0) continue;
    const double radius = info.radius[n], slack = tolerance * 2 * radius;
    const Vec3 from = r0.col(n), to = r.col(n);
    const double travel = (to - from).norm();
    const int samples = std::min(kMaxPathSamples, std::max(1, static_cast<int>(std::ceil(2 * travel / radius))));
    for (int k = 1; k <= samples; ++k) {
      const double u = static_cast<double>(k) / samples;
      const ObstacleHit hit = field.Nearest(from + u * (to - from), radius);
      if (hit.obstacle < 0 || radius - hit.distance <= slack) continue;
      depth[n] = radius - hit.distance + (1 - u) * travel;
      entry[n] = hit;
      if (k == samples) {
        // Ends inside: push it out on the side it came from (the nearest point to where it
        // was), not through to the far side of a part thinner than the cable.
        const ObstacleHit back = field.Nearest(from, radius + travel + 1e-9);
        if (back.obstacle >= 0 && back.distance >= 0) entry[n] = back;
      }
      break;
    }
  }
  // A span that fell into a surface is held first where it went deepest. Holding every
  // penetrating node would pin the whole stretch flat, and the holds would then peel off its
  // edges one node per round. Per penetrating stretch along a branch, the nodes at least half
  // as deep as its deepest (on the same face) are held; the rest of the stretch, if it still
  // goes in, is halved again next round, so a long contact fills in within about log2(its
  // nodes) rounds.
  std::vector<char> take(m.num_nodes(), 0);
  for (const internal::BranchLayout& lay : net.branches) {
    for (size_t k = 0; k < lay.nodes.size();) {
      if (depth[lay.nodes[k]] <= 0) {
        ++k;
        continue;
      }
      size_t end = k, deepest = k;
      for (; end < lay.nodes.size() && depth[lay.nodes[end]] > 0; ++end)
        if (depth[lay.nodes[end]] > depth[lay.nodes[deepest]]) deepest = end;
      const ObstacleHit& face = entry[lay.nodes[deepest]];
      for (size_t i = k; i < end; ++i) {
        const int n = lay.nodes[i];
        // Only nodes on the deepest one's face: holds on the tilted tangent planes of an edge
        // next to one on its top wedge the cable between them.
        if (depth[n] >= 0.5 * depth[lay.nodes[deepest]] && entry[n].obstacle == face.obstacle &&
            entry[n].normal.dot(face.normal) > 1 - 1e-9)
          take[n] = 1;
      }
      k = end;
    }
  }
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (!take[n]) continue;
    kept.push_back({n, entry[n].obstacle, entry[n].point, entry[n].normal, 0.0});
    result = HoldUpdate::kRevert;
  }
  *holds = kept;
  return result;
}

// Nodes the drawing already puts on a surface (within `gap` diameters) start held: a cable
// drawn lying on a panel stays on it instead of first falling through and being pushed back.
std::vector<Hold> TouchingInDrawing(const NetworkModel& net, const RodState& st,
                                   const ObstacleField& field, const NodeInfo& info, double gap) {
  std::vector<Hold> holds;
  if (field.empty()) return holds;
  const Eigen::Matrix3Xd r = st.NodePositions(net.rod);
  for (int n = 0; n < net.rod.num_nodes(); ++n) {
    if (info.fixed[n] || info.radius[n] <= 0) continue;
    const double reach = info.radius[n] * (1 + 2 * gap);
    const ObstacleHit hit = field.Nearest(r.col(n), reach);
    if (hit.obstacle >= 0 && hit.distance <= reach) holds.push_back({n, hit.obstacle, hit.point, hit.normal, 0.0});
  }
  return holds;
}

// Deepest overlap of the cable surface with the solids, at nodes and element midpoints [m].
double MaxPenetration(const NetworkModel& net, const RodState& st, const ObstacleField& field,
                      const NodeInfo& info) {
  const RodModel& m = net.rod;
  const Eigen::Matrix3Xd r = st.NodePositions(m);
  double worst = 0.0;
  auto probe = [&](const Vec3& p, double radius) {
    const ObstacleHit hit = field.Nearest(p, radius);
    if (hit.obstacle >= 0) worst = std::max(worst, radius - hit.distance);
  };
  for (int n = 0; n < m.num_nodes(); ++n)
    if (!info.fixed[n]) probe(r.col(n), info.radius[n]);
  for (int j = 0; j < m.num_elements; ++j) {
    const auto& en = m.element_nodes[j];
    probe(0.5 * (r.col(en[0]) + r.col(en[1])), std::min(info.radius[en[0]], info.radius[en[1]]));
  }
  return worst;
}

void ExtractLoads(const NetworkModel& net, const RodState& st, const std::vector<Hold>& holds,
                  NetworkSolution* sol) {
  const RodModel& m = net.rod;
  const int nn = m.num_nodes();
  const Eigen::Matrix3Xd r = st.NodePositions(m);
  for (size_t b = 0; b < net.branches.size(); ++b) {
    const internal::BranchLayout& lay = net.branches[b];
    Polyline pl;
    pl.s = lay.node_s;
    pl.points.resize(3, static_cast<int>(lay.nodes.size()));
    for (size_t k = 0; k < lay.nodes.size(); ++k) pl.points.col(k) = r.col(lay.nodes[k]);
    sol->branches.push_back(pl);
    Eigen::Matrix3Xd normals(3, static_cast<int>(lay.elements.size()));
    for (size_t k = 0; k < lay.elements.size(); ++k)
      normals.col(k) = internal::quat::ToMatrix(st.q[m.element_item[lay.elements[k]]]).col(0);
    sol->element_normals.push_back(std::move(normals));
  }
  // External node forces; the anchor takes what balances the rest.
  std::vector<Vec3> ext(nn);
  const Vec3 g = st.load_factor * m.gravity;
  for (int i = 0; i < nn; ++i) ext[i] = m.node_mass[i] * g;
  for (const auto& [node, f] : m.node_loads) ext[node] += st.load_factor * f;
  std::vector<Vec3> reaction = internal::SupportReactions(m, st);
  reaction[m.anchor_support].setZero();
  Vec3 total = Vec3::Zero();
  for (size_t k = 0; k < m.supports.size(); ++k)
    if (static_cast<int>(k) != m.anchor_support) ext[m.supports[k].node] += reaction[k];
  for (const Vec3& f : ext) total += f;
  reaction[m.anchor_support] = -total;
  ext[m.anchor_node] -= total;
  internal::EnergyAccumulator acc;
  acc.Reset(m, nullptr);
  internal::AddBendingEnergy(m, st, &acc);
  internal::AddSupportSpringEnergy(m, st, &acc);
  for (int k = 0; k < net.num_spec_supports; ++k) {
    const RodSupport& sp = m.supports[k];
    SupportReaction rr;
    rr.kind = sp.kind;
    rr.s = sp.s;
    rr.force = reaction[k];
    if (sp.item >= 0)
      rr.moment = internal::quat::ToMatrix(st.q[sp.item]) * acc.gradient.segment<3>(3 * sp.item);
    sol->reactions.push_back(rr);
  }
  for (size_t k = 0; k < holds.size(); ++k) {
    const int idx = net.num_spec_supports + static_cast<int>(k);
    ContactLoad c;
    c.branch = net.support_branch[idx];
    c.s = m.supports[idx].s;
    c.obstacle = holds[k].obstacle;
    c.point = holds[k].point;
    c.force = reaction[idx];
    sol->contacts.push_back(c);
  }
  // Junctions: forces from subtree sums of the external forces, moments from the edge energies.
  std::vector<Vec3> beyond(ext);
  for (auto it = m.node_order.rbegin(); it != m.node_order.rend(); ++it)
    if (m.node_parent[*it] >= 0) beyond[m.node_parent[*it]] += beyond[*it];
  // Element k of a branch joins its nodes k and k+1; the part away from the anchor carries
  // beyond[] of its first node, so the force of the larger-s part on the smaller-s one is that
  // sum when the larger-s node is the child, and its opposite otherwise.
  for (const internal::BranchLayout& lay : net.branches) {
    Eigen::Matrix3Xd force(3, static_cast<int>(lay.nodes.size()) - 1);
    for (int k = 0; k + 1 < static_cast<int>(lay.nodes.size()); ++k) {
      const int a = lay.nodes[k], b = lay.nodes[k + 1];
      force.col(k) = m.node_parent[b] == a ? beyond[b] : Vec3(-beyond[a]);
    }
    sol->internal_force.push_back(std::move(force));
  }
  for (const internal::JunctionLayout& jl : net.junctions) {
    JunctionLoads jload;
    jload.branch = jl.branches;
    jload.branch_end = jl.branch_end;
    Vec3 fsum = ext[jl.node], msum = Vec3::Zero();
    for (size_t k = 0; k < jl.branches.size(); ++k) {
      const internal::BranchLayout& lay = net.branches[jl.branches[k]];
      const int next = jl.branch_end[k] == 0 ? lay.nodes[1] : lay.nodes[lay.nodes.size() - 2];
      const Vec3 f = m.node_parent[next] == jl.node ? beyond[next] : Vec3(-beyond[jl.node]);
      Vec3 mom = Vec3::Zero();
      if (jl.item >= 0) {
        internal::EnergyAccumulator edge;
        edge.Reset(m, nullptr);
        internal::AddEdgeBendingEnergy(m.edges[jl.edges[k]], jl.edges[k], st, &edge);
        mom = -(internal::quat::ToMatrix(st.q[jl.item]) * edge.gradient.segment<3>(3 * jl.item));
      }
      jload.force.push_back(f);
      jload.moment.push_back(mom);
      fsum += f;
      msum += mom;
    }
    jload.force_residual = fsum;
    jload.moment_residual = msum;
    sol->junctions.push_back(jload);
  }
}

// Per obstacle: does the drawn cable go into it deeper than kAttachedDepth of its radius within
// kAttachedReach radii (along the cable) of a support that holds it? That is a cable fitted
// into a part at its held end. Deeper overlap away from supports is a drawing that ignored the
// cable's radius: it stays a contact surface and the cable is pushed out onto it.
constexpr double kAttachedDepth = 0.25;
constexpr double kAttachedReach = 4.0;
std::vector<char> EnteredInDrawing(const NetworkModel& net, const NodeInfo& info,
                                   const std::vector<ObstacleSpec>& obstacles) {
  std::vector<char> entered(obstacles.size(), 0);
  if (obstacles.empty()) return entered;
  const Eigen::Matrix3Xd r = DrawnNetworkState(net, nullptr).NodePositions(net.rod);  // 3 x n [m]
  std::vector<char> near_support(net.rod.num_nodes(), 0);
  for (int n = 0; n < net.rod.num_nodes(); ++n) {
    for (const RodSupport& sp : net.rod.supports) {
      if (sp.sliding || sp.contact || info.branch[n] != info.branch[sp.node]) continue;
      if (std::abs(info.s[n] - info.s[sp.node]) <= kAttachedReach * info.radius[n]) near_support[n] = 1;
    }
  }
  for (size_t k = 0; k < obstacles.size(); ++k) {
    const ObstacleField one({obstacles[k]});
    for (int n = 0; n < net.rod.num_nodes() && !entered[k]; ++n) {
      const double radius = info.radius[n];
      if (radius <= 0 || !near_support[n]) continue;
      const ObstacleHit hit = one.Nearest(r.col(n), radius);
      entered[k] = hit.obstacle >= 0 && radius - hit.distance > kAttachedDepth * radius;
    }
  }
  return entered;
}

}  // namespace

RodState DrawnNetworkState(const NetworkModel& net, const std::vector<Polyline>* routes,
                           const std::vector<Eigen::Matrix3Xd>* normals) {
  const RodModel& m = net.rod;
  RodState st;
  st.q = DrawnFrames(net, routes, normals);
  internal::AlignQuaternionSigns(m, &st);
  const int ns = static_cast<int>(m.supports.size());
  st.support_position.assign(ns, Vec3::Zero());
  st.support_q.assign(ns, Eigen::Vector4d(1, 0, 0, 0));
  const int b = net.support_branch[m.anchor_support];
  const BranchSpec& br = net.spec.branches[b];
  st.support_position[m.anchor_support] =
      PointAt(ReparameteriseToLength(br.route, br.length), m.supports[m.anchor_support].s);
  const Eigen::Matrix3Xd r = st.NodePositions(m);
  for (int k = 0; k < ns; ++k) {
    st.support_position[k] = r.col(m.supports[k].node);
    if (m.supports[k].item >= 0) st.support_q[k] = st.q[m.supports[k].item];
  }
  st.lambda = Eigen::VectorXd::Zero(m.num_constraints);
  return st;
}

bool NetworkOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(element_length > 0 && std::isfinite(element_length)))
    return fail("element_length must be finite and > 0");
  // Each refinement doubles the elements: 2^20 times a coarse mesh is beyond any memory.
  if (refinement < 0 || refinement > 20) return fail("refinement must be in [0, 20]");
  if (!(contact_tolerance > 0 && contact_tolerance < 1))
    return fail("contact_tolerance must be in (0, 1)");
  if (!(contact_gap >= 0 && contact_gap < 1)) return fail("contact_gap must be in [0, 1)");
  if (max_contact_rounds < 1) return fail("max_contact_rounds must be >= 1");
  return statics.IsValid(why);
}

NetworkSolution SolveNetwork(const NetworkSpec& spec, const NetworkOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string why;
  if (!options.IsValid(&why)) {
    NetworkSolution rejected;
    rejected.summary.termination = TerminationType::kInvalidOptions;
    rejected.summary.message = "invalid network options: " + why;
    return rejected;
  }
  const NetworkModel base = CompileNetworkModel(spec, options.element_length, options.refinement);
  const NodeInfo info = NodeTable(base);
  const std::vector<char> attached = EnteredInDrawing(base, info, spec.obstacles);
  const ObstacleField field(spec.obstacles, attached);
  const bool warm = options.initial_routes.size() == spec.branches.size();
  RodState st;
  if (!options.start || !TransferNetworkState(options.start->model, options.start->state, base, &st))
    st = DrawnNetworkState(base, warm ? &options.initial_routes : nullptr,
                           warm ? &options.initial_normals : nullptr);
  std::vector<Hold> holds = TouchingInDrawing(base, st, field, info, options.contact_gap);
  NetworkModel net = base;
  NetworkSolution sol;
  for (size_t k = 0; k < attached.size(); ++k)
    if (attached[k]) sol.attached_obstacles.push_back(static_cast<int>(k));
  int iterations = 0, streak = 0, extra_release = 0, widest = 1 << 20;
  for (int round = 0; round < options.max_contact_rounds; ++round) {
    net = WithHolds(base, holds, info);
    FitStateToHolds(net, holds, &st);
    const RodState before = st;
    sol.summary = SolveStatics(net.rod, &st, options.statics);
    iterations += sol.summary.iterations;
    sol.contact_rounds = round + 1;
    if (!sol.summary.converged() || field.empty()) break;
    const HoldUpdate update =
        UpdateHolds(net, before, st, field, info, options.contact_tolerance, extra_release, &holds);
    if (update == HoldUpdate::kUnchanged) break;
    // Rounds that only release or move holds in a row widen the next release: 0, 1, 3, 7, ...
    // Released too many (nodes fell back in right after a widened release): never widen that
    // far again (but always by one), so the contact set cannot cycle between the same two sets.
    if (update == HoldUpdate::kRevert && extra_release > 0) widest = std::max(1, extra_release / 2);
    streak = update == HoldUpdate::kChanged ? streak + 1 : 0;
    extra_release = std::min(widest, (1 << std::min(streak, 20)) - 1);
    if (update == HoldUpdate::kRevert) {
      // Restart from the last state without penetration, so the new holds start on the side of
      // the surface their nodes came from.
      const std::vector<Eigen::Vector4d> q = before.q;
      st.q = q;
    }
    if (round + 1 == options.max_contact_rounds) {
      sol.summary.termination = TerminationType::kNoConvergence;
      sol.summary.message = "contact set still changing after " + std::to_string(round + 1) + " rounds";
    }
  }
  sol.summary.iterations = iterations;
  sol.num_elements = net.rod.num_elements;
  if (options.keep_start && sol.summary.converged())
    sol.start = std::make_shared<const NetworkStart>(NetworkStart{base, st});
  if (!field.empty()) sol.max_penetration = MaxPenetration(net, st, field, info);
  ExtractLoads(net, st, holds, &sol);
  sol.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return sol;
}

}  // namespace cablefit
