// The immutable, compiled rod: discretisation, stiffness, loads and supports of one set-up at one
// resolution. Built once from a RodSpec by CompileRodModel() (which validates the spec); the
// solver only reads it (MuJoCo's mjModel / mjData split: what changes lives in RodState).
//
// Discretisation (why this one): a quaternion Cosserat/Kirchhoff rod on a staggered grid
// (Lang, Linn & Arnold 2011, "Multi-body dynamics simulation of geometrically exact Cosserat
// rods", the model behind seed 000's IPS Cable Simulation). Each element carries one unit
// quaternion (its material frame); node positions are prefix sums r_{i+1} = r_i + h_i d3_i, so the
// rod is exactly inextensible and unshearable without penalty terms, and the only unknowns are
// rotations. The discrete Darboux vector between neighbouring frame samples a, b is
// u = (2/ds) Im(conj(q_a) q_b), second-order accurate in h, with an error expansion in even
// powers of h that Richardson extrapolation exploits. Bending couples only neighbours, so the
// Hessian is block-tridiagonal (3x3 blocks) and a Newton step costs O(n).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cablefit/core/geometry_types.h"
#include "cablefit/core/rod_spec.h"

namespace cablefit {

/// One frame sample of the chain: an element (has length) or a support frame (length 0).
struct RodItem {
  bool is_element = true;
  int element = -1;         // element index if is_element
  int support = -1;         // support index if a support frame
  double length = 0.0;      // [m] element length, 0 for a support frame
  double s = 0.0;           // [m] arc length of the sample (element midpoint or support)
  bool masked[3] = {false, false, false};  // body-frame rotation DOFs held fixed
  bool has_spring = false;  // compliant clamp: spring towards the clamp frame
  Mat3 spring_stiffness = Mat3::Zero();    // [N m/rad] in the clamp frame
};

/// Bending/twist coupling between items a and a+1.
struct RodEdge {
  int a = 0;                     // item index; the other item is a + 1
  double ds = 0.0;               // [m] distance between the two samples
  double s = 0.0;                // [m] arc length of the edge centre
  Mat3 stiffness = Mat3::Zero();  // [N m^2] material frame (d1, d2, d3)
  Vec3 natural = Vec3::Zero();    // [1/m] natural Darboux vector (cell average), material frame
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
  int constraint_rows = 0;        // 3, or 2 when sliding
};

struct RodModel {
  RodSpec spec;  // the validated input
  int num_elements = 0;
  Eigen::VectorXd node_s;         // (num_elements + 1) [m]
  Eigen::VectorXd element_length;  // num_elements [m]
  std::vector<RodItem> items;
  std::vector<int> element_item;  // element -> item index
  std::vector<RodEdge> edges;
  std::vector<RodSupport> supports;
  int anchor_support = 0;  // the position support whose node is fixed by construction
  int anchor_node = 0;
  int num_constraints = 0;  // position-constraint rows
  /// Per element: coefficient vector a_j so that the potential of gravity and dead point loads is
  /// sum_j a_j . d3_j (+ const) at load factor 1 [N m].
  std::vector<Vec3> load_coefficient;
  Eigen::VectorXd node_mass;  // (num_elements + 1) [kg] lumped
  std::vector<std::pair<int, Vec3>> node_loads;  // dead point loads at nodes [N]
  double force_scale = 1.0;   // [N] characteristic force for tolerances
  /// +1 if node i lies after element j as seen from the anchor, -1 before, 0 otherwise.
  int Sign(int node, int element) const {
    if (element >= anchor_node && element < node) return 1;
    if (element < anchor_node && element >= node) return -1;
    return 0;
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

/// Validates a RodSpec; throws InvalidInput naming the first problem.
void ValidateRodSpec(const RodSpec& spec);

}  // namespace cablefit
