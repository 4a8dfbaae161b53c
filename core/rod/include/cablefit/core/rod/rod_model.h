// The immutable, compiled rod: discretisation, stiffness, loads and supports of one set-up at one
// resolution. Built once from a RodSpec by CompileRodModel() (which validates the spec) or from
// a network by CompileNetworkModel(), both laid out by one compiler (internal/model_compiler.h);
// the solver only reads it (MuJoCo's mjModel / mjData split: what changes lives in RodState).
//
// Discretisation (why this one): a quaternion Cosserat/Kirchhoff rod on a staggered grid
// (Lang, Linn & Arnold 2011, "Multi-body dynamics simulation of geometrically exact Cosserat
// rods", the model behind IPS Cable Simulation). Each element carries one unit
// quaternion (its material frame); node positions are prefix sums r_{i+1} = r_i + h_i d3_i, so the
// rod is exactly inextensible and unshearable without penalty terms, and the only unknowns are
// rotations. The discrete Darboux vector between neighbouring frame samples a, b is
// u = (2/ds) Im(conj(q_a) q_b), second-order accurate in h, with an error expansion in even
// powers of h that Richardson extrapolation exploits. Bending couples only neighbours, so the
// Hessian is block-tridiagonal (3x3 blocks) and a Newton step costs O(n).
//
// The same model holds a rod network (a harness tree, see network_model.h): elements then form
// a tree of nodes rooted at the anchor, positions are sums along tree paths, and the frame
// samples form a tree too (junction frames join branches), so the Hessian is a block tree.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/rod/rod_spec.h"

namespace cablefit {

/// One frame sample of the chain: an element (has length) or a support frame (length 0).
struct RodItem {
  bool is_element = true;
  int element = -1;         // element index if is_element
  int support = -1;         // support index if a support frame
  int junction = -1;        // junction index if a network junction's frame
  double length = 0.0;      // [m] element length, 0 for a support frame
  double s = 0.0;           // [m] arc length of the sample (element midpoint or support)
  bool masked[3] = {false, false, false};  // body-frame rotation DOFs held fixed
  bool has_spring = false;  // compliant clamp: spring towards the clamp frame
  Mat3 spring_stiffness = Mat3::Zero();    // [N m/rad] in the clamp frame
};

/// Bending/twist coupling between items a and a+1.
struct RodEdge {
  int a = 0;                     // item index (strain measured from a to b)
  int b = 1;                     // item index; a + 1 on a single rod
  double ds = 0.0;               // [m] distance between the two samples
  double s = 0.0;                // [m] arc length of the edge centre
  Mat3 stiffness = Mat3::Zero();  // [N m^2] material frame (d1, d2, d3)
  Vec3 natural = Vec3::Zero();    // [1/m] natural Darboux vector (cell average), material frame
  /// Relative rotation (w, x, y, z) of b's frame to a's at rest: the strain is measured from
  /// q_a * rest to q_b (junction edges, where branches meet at an angle). Identity on a rod.
  Eigen::Vector4d rest = Eigen::Vector4d(1, 0, 0, 0);
  bool has_rest = false;
};

struct RodSupport {
  SupportKind kind = SupportKind::kClamp;
  double s = 0.0;     // [m]
  int node = 0;       // node index where it acts
  int item = -1;      // its frame item (clamp, clip), or -1 (pin)
  Vec3 position = Vec3::Zero();   // [m] target position
  Frame frame;                    // target frame (clamp, clip)
  bool sliding = false;           // free translation along the frame tangent
  int constraint_row = -1;        // first row in the position constraints, -1 for the anchor
  int constraint_rows = 0;        // 3, 2 when sliding, 1 for a contact
  /// The constraint holds this support's position relative to the nearest support towards the
  /// anchor that fixes its node (c = P (r - r_ref - (p - p_ref))), -1 = relative to the anchor.
  /// Equivalent at the solution, but each Jacobian row then spans only the cable between the
  /// two supports instead of the whole path from the anchor: O(n) rather than O(n m) entries.
  int reference = -1;
  /// One-sided contact with a solid (network models): one row, the distance along frame.d3 (the
  /// surface normal) from the contact plane through `position`.
  bool contact = false;
  /// [m/N] Axial compliance of the support's stretch, sum of h / EA over the cable between it
  /// and its reference support: its position rows then hold c = compliance * lambda instead of
  /// c = 0 (the stretch lengthens under tension). 0 = rigid (inextensible cable, contacts).
  double compliance = 0.0;
  /// The support the Newton system measures this support's rows from (the rows' basis): a
  /// support met just before it in a depth-first walk of the tree, when that one is nearer than
  /// `reference`, else `reference` itself. Its rows then span only the cable between the two,
  /// and every element lies on few of them, so the elimination of a harness with hundreds of
  /// connectors stays O(n). The physics (reactions, stretches) stays that of `reference`: the
  /// rows in this basis are c_k - P_k sum_{m in row_chain} c_m of the rows measured from
  /// `reference` (row_chain: the supports from row_reference up that chain of references to
  /// `reference`, each holding its full position), a change of basis the solver undoes.
  int row_reference = -1;
  std::vector<int> row_chain;
};

struct RodModel {
  std::string name;
  double length = 0.0;               // [m] of the cable, of all branches on a network
  Vec3 gravity = Vec3(0, 0, -9.81);  // [m/s^2]
  int num_elements = 0;
  Eigen::VectorXd node_s;         // (num_elements + 1) [m]
  Eigen::VectorXd element_length;  // num_elements [m]
  std::vector<RodItem> items;
  std::vector<int> element_item;  // element -> item index
  std::vector<RodEdge> edges;
  std::vector<RodSupport> supports;
  int anchor_support = 0;  // the position support whose node is fixed by construction
  /// Supports with rows, each after every support of its row_chain (depth-first preorder of
  /// their nodes): the order the rows' change of basis is applied in.
  std::vector<int> row_support_order;
  int anchor_node = 0;
  int num_constraints = 0;  // position-constraint rows
  // Topology. element_nodes[j] = (from, to): r_to = r_from + h_j d3_j. Nodes form a tree rooted
  // at anchor_node: node_parent (-1 at the anchor), the element joining a node to its parent,
  // and its sign (+1: r_node = r_parent + h d3, -1: r_node = r_parent - h d3); node_order lists
  // parents before children. Frame samples form a tree for the Hessian: item_parent, and
  // item_order lists every item before its parent (elimination order).
  std::vector<std::array<int, 2>> element_nodes;
  std::vector<int> node_parent;
  std::vector<int> node_parent_element;
  std::vector<int> node_parent_sign;
  std::vector<int> node_order;
  std::vector<int> node_depth;  // elements between a node and the anchor
  std::vector<int> item_parent;
  std::vector<int> item_parent_edge;  // the edge joining an item to its parent, -1 at a root
  std::vector<int> item_order;
  /// Per element: coefficient vector a_j so that the potential of gravity and dead point loads is
  /// sum_j a_j . d3_j (+ const) at load factor 1 [N m].
  std::vector<Vec3> load_coefficient;
  Eigen::VectorXd node_mass;  // (num_elements + 1) [kg] lumped
  /// num_elements [N] EA of each element; 0 = inextensible. Gives the supports' compliance.
  Eigen::VectorXd element_axial_stiffness;
  std::vector<std::pair<int, Vec3>> node_loads;  // dead point loads at nodes [N]
  double force_scale = 1.0;   // [N] characteristic force for tolerances
  int num_nodes() const { return static_cast<int>(node_parent.size()); }
  /// Calls f(element, sign) for every element on the path from the anchor to `node`, where
  /// r_node = r_anchor + sum sign * h_element * d3_element.
  template <class F>
  void ForEachPathElement(int node, F&& f) const {
    for (int n = node; node_parent[n] >= 0; n = node_parent[n])
      f(node_parent_element[n], node_parent_sign[n]);
  }
  /// The same from node `from` (-1 for the anchor) to `node`: r_node = r_from + sum sign *
  /// h_element * d3_element over the tree path between them, up from `node` to their lowest
  /// common ancestor, then up from `from` (its signs turned). From an ancestor: only the first.
  template <class F>
  void ForEachPathElementFrom(int from, int node, F&& f) const {
    int a = node, b = from;
    if (b < 0) {
      for (; node_parent[a] >= 0; a = node_parent[a]) f(node_parent_element[a], node_parent_sign[a]);
      return;
    }
    for (; node_depth[a] > node_depth[b]; a = node_parent[a])
      f(node_parent_element[a], node_parent_sign[a]);
    for (; node_depth[b] > node_depth[a]; b = node_parent[b])
      f(node_parent_element[b], -node_parent_sign[b]);
    for (; a != b; a = node_parent[a], b = node_parent[b]) {
      f(node_parent_element[a], node_parent_sign[a]);
      f(node_parent_element[b], -node_parent_sign[b]);
    }
  }
};

/// How finely to discretise: the target element length, or explicit per-span element counts.
struct Discretisation {
  double element_length = 0.005;        // [m] used when elements_per_span is empty
  std::vector<int> elements_per_span;   // one entry per span between breakpoints
  int refinement = 0;                   // multiplies every span count by 2^refinement
};

/// Validates `spec` (throws InvalidInput with a one-line reason) and compiles it.
RodModel CompileRodModel(const RodSpec& spec, const Discretisation& disc = {});

/// Breakpoints (supports, point loads, ends) of a spec, sorted: spans lie between them.
std::vector<double> SpanBreakpoints(const RodSpec& spec);

/// Validates a RodSpec; throws InvalidInput naming the first problem. A network branch may have
/// no support of its own (require_support = false).
void ValidateRodSpec(const RodSpec& spec, bool require_support = true);

/// Bending/twist stiffness in the material frame (d1, d2, d3) [N m^2].
Mat3 MaterialStiffness(const MaterialSpec& material);

/// The compiled support of `support` acting at `node` (arc length s [m]), without constraint rows.
RodSupport MakeRodSupport(const SupportSpec& support, double s, int node);

/// The frame sample of a clamp or clip at arc length s: masked rotations, or a rotational
/// spring for a compliant clamp (rigid directions get 1e8 x cable_stiffness [N m/rad]).
RodItem MakeSupportItem(const SupportSpec& support, int support_index, double s,
                        double cable_stiffness);

}  // namespace cablefit
