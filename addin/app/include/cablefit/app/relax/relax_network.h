// Which cables of a drawing `relax` solves together, and the solve of such a group as one rod
// network: cables joined at a breakout (three or more ends meeting in the drawing, or a junction
// declared in harness.json) form one network; a cable near a solid it does not pass through is
// solved with contact against it (the network solver, with one branch).
#pragma once

#include <string>
#include <vector>

#include "cablefit/formats/harness_drawing.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/relax/relax_cable.h"
#include "cablefit/core/network/network_simulator.h"

namespace cablefit::addin {

struct RelaxGroup {
  std::vector<int> cables;  ///< drawing cable indices
  struct Junction {
    std::string name;
    std::vector<CableJunction::End> ends;
    double compliance = 0.0;  // [rad/(N m)]
    double mass = 0.0;        // [kg]
    bool declared = false;    // from harness.json (else found in the drawing)
  };
  std::vector<Junction> junctions;
  std::vector<int> obstacles;  ///< drawing solids the group must stay out of
  /// A cable of the group is pre-formed (HarnessConfig::preformed): its rest shape comes from
  /// its drawn route, which only the network model carries.
  bool preformed = false;
  /// Solved by the network solver (junctions, contact or a pre-formed cable), else as a single
  /// rod.
  bool network() const { return !junctions.empty() || !obstacles.empty() || preformed; }
};

/// Groups the drawing's cables. `boxes` are the solids' bounding boxes. Throws InvalidInput
/// when a declared junction names a cable the drawing does not have.
std::vector<RelaxGroup> GroupCables(const HarnessDrawing& drawing,
                                    const std::vector<OrientedBox>& boxes,
                                    const HarnessConfig& config);

/// A solved network group: one relaxation per group cable (same order) and the group's JSON
/// (junction loads, contacts, solver figures).
struct GroupRelaxation {
  std::vector<CableRelaxation> cables;
  json::Json json;
};

/// How relax discretises and refines a network: first-level elements of total length / 1500
/// within [2 mm, 1 cm], at least two levels, a third and fourth while they stay within 12000
/// elements; the requested accuracy and statics options from `options`.
struct NetworkRelaxPlan {
  NetworkOptions options;
  RefinementPlan plan;
};
NetworkRelaxPlan PlanNetworkRelax(const NetworkSpec& spec, const SimulationOptions& options);

/// The refinement level (index into a relax's `level_elements`) at which a network is solved
/// many times over (motion poses, tolerance corners): the finest with at most 2000 elements
/// (a warm solve costs a few Newton iterations there: a 100-pose sweep of a 30-branch harness in
/// a few seconds), else the first. The relax's own levels, so its first level's start is known
/// good.
int RepeatedSolveLevel(const std::vector<int>& level_elements);

/// The network without gravity on one level (`options` at refinement 0), for the springback/sag
/// split: it needs no extrapolated accuracy. Started from `loaded`, the node centrelines of the
/// solution under gravity (one per branch), so Newton only takes the gravity off instead of
/// solving again from the drawing (`loaded_normals`, its NetworkSolution::element_normals, keep
/// its twist); solved from the drawing when that start fails
/// (SimulateNetwork's fallback). Without `loaded` (empty) it starts from the drawing.
NetworkSimulation SimulateWithoutGravity(const NetworkSpec& spec, const NetworkOptions& options,
                                         const std::vector<Polyline>& loaded,
                                         const std::vector<Eigen::Matrix3Xd>& loaded_normals = {});

/// The network a group is solved as: one branch per group cable (same order), set up as
/// SetUpCable does with the group's junction ends (`setups`, one per branch), the group's
/// junctions and obstacles. Throws InvalidInput for an invalid set-up.
NetworkSpec GroupNetworkSpec(const HarnessDrawing& drawing, const RelaxGroup& group,
                             const std::vector<OrientedBox>& boxes, const HarnessConfig& config,
                             std::vector<CableSetup>* setups);

/// Branch `branch` of a network solution as a single rod's solution: node centreline, element
/// tangents (d1, d2 unknown: NaN), internal forces, the reactions of its own supports.
RodSolution BranchSolution(const NetworkSpec& spec, const NetworkSolution& solution, int branch);

/// Solves a network group from the drawn routes (two resolutions, Richardson-extrapolated).
/// Throws InvalidInput for an invalid set-up; a solver failure is reported per cable.
GroupRelaxation RelaxNetworkGroup(const HarnessDrawing& drawing, const RelaxGroup& group,
                                  const std::vector<OrientedBox>& boxes,
                                  const HarnessConfig& config, const SimulationOptions& options);

/// One box per drawing solid, in order (empty for a solid without tessellation): what
/// SetUpCable and GroupCables take.
std::vector<OrientedBox> SolidBoxes(const HarnessDrawing& drawing);

/// One group relaxed, the way `cablefit relax` and the CAD add-in both do it: the network solve
/// or the single-rod one. On failure `problem` is one line (exception or non-convergence) and
/// `cables` must not be used; `network` is the group's JSON (null for a single rod).
/// A network that does not converge as one is not a failure of all its cables: each is then
/// relaxed on its own, its junction ends held where the drawing has them (with a note saying
/// so); `cables` holds those that converged and `cable_problems` (cable index, one line) the
/// others, while `problem` stays empty.
struct GroupOutcome {
  std::vector<CableRelaxation> cables;
  json::Json network;
  std::string problem;
  std::vector<std::pair<int, std::string>> cable_problems;
  double measure_seconds = 0.0;  ///< [s] spent measuring the solved cables (of the whole solve)
};
GroupOutcome RelaxGroupCables(const HarnessDrawing& drawing, const RelaxGroup& group,
                              const std::vector<OrientedBox>& boxes, const HarnessConfig& config,
                              const SimulationOptions& options);

/// A one-line label of a group: its cable names, comma separated.
std::string GroupLabel(const HarnessDrawing& drawing, const RelaxGroup& group);

}  // namespace cablefit::addin
