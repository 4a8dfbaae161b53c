// Solving a rod network: one Newton system for the whole harness from its drawn shape, with
// one-sided frictionless contact against the obstacles by an active set (nodes that would
// penetrate are held on the tangent plane of the surface; holds that pull are released; planes
// follow the nearest surface point until nothing changes).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cablefit/core/network/network_model.h"
#include "cablefit/core/solver/rod_solution.h"
#include "cablefit/core/rod/rod_state.h"
#include "cablefit/core/solver/statics_solver.h"

namespace cablefit {

/// An equilibrium as the solver holds it: the start of a finer level of the same network.
struct NetworkStart {
  NetworkModel model;  // without contact rows
  RodState state;      // may hold contact supports beyond model's
};

struct NetworkOptions {
  double element_length = 0.01;  // [m]
  int refinement = 0;            // elements x 2^refinement
  StaticsOptions statics;
  /// Contacts are added where the surface comes closer than radius (1 - this fraction of the
  /// diameter); the reported penetration stays below about this fraction.
  double contact_tolerance = 0.002;
  /// Nodes drawn within this fraction of the diameter of a surface start in contact (pulled
  /// onto it). Kept small: pulling a drawn droop flat onto a panel it only nears can ask an
  /// inextensible cable for more length than it has; nodes further off find the surface by
  /// falling onto it.
  double contact_gap = 0.002;
  int max_contact_rounds = 100;  // each round is a warm solve of a few Newton iterations
  /// Where the solve starts: empty = the drawing; else one centreline per branch (a coarser
  /// level's equilibrium), whose tangents set the first frames. The model (junction angles,
  /// support targets) always comes from the drawing.
  std::vector<Polyline> initial_routes;
  /// With initial_routes: per branch, 3 x elements of that start, the material normal d1 of each
  /// of its elements (NetworkSolution::element_normals), so the start keeps the equilibrium's
  /// twist too; empty = twist as drawn. Positions alone lose it: the drawn twist put back on a
  /// coarser level's shape cost the next level 10-12 Newton iterations (movo sample, 5 x the
  /// energy of the equilibrium at the start), its own twist 3-5.
  std::vector<Eigen::Matrix3Xd> initial_normals;
  /// A coarser level's equilibrium of the same spec (NetworkSolution::start): the solve starts
  /// from its frames, slerped to this model's elements, and from its support forces. Preferred
  /// over initial_routes: a start drawn through the coarse nodes alone lost the supports' forces
  /// and the frames at junctions and clamps; on a 1000-segment harness with short connector
  /// stubs its first Newton Hessian had hundreds of unstable directions, and the level took 217
  /// iterations instead of a few.
  std::shared_ptr<const NetworkStart> start;
  /// Keep the equilibrium in NetworkSolution::start (a copy of the compiled model and state).
  bool keep_start = false;

  bool IsValid(std::string* why) const;
};

/// What branch b exerts on a junction's body, at the junction node (world frame).
struct JunctionLoads {
  std::vector<int> branch;      // attached branches
  std::vector<int> branch_end;  // 0: the branch's start is attached, 1: its end
  std::vector<Vec3> force;   // per attached branch [N]
  std::vector<Vec3> moment;  // per attached branch [N m]
  Vec3 force_residual = Vec3::Zero();   // sum of branch forces + the junction's weight [N]
  Vec3 moment_residual = Vec3::Zero();  // sum of branch moments [N m]
};

struct ContactLoad {
  int branch = -1;
  double s = 0.0;                 // [m] along the branch
  int obstacle = -1;
  Vec3 point = Vec3::Zero();      // [m] where it acts on the surface
  Vec3 force = Vec3::Zero();      // [N] exerted by the surface on the cable
};

struct NetworkSolution {
  StaticsSummary summary;
  std::vector<Polyline> branches;          // per branch: node s [m] and positions [m]
  /// Per branch: 3 x elements, each element's material normal d1 (unit; warm starts).
  std::vector<Eigen::Matrix3Xd> element_normals;
  /// Per branch: 3 x elements [N], the force of the part at larger s on the part at smaller s
  /// (as RodSolution::internal_force; its component along the branch is the tension).
  std::vector<Eigen::Matrix3Xd> internal_force;
  std::vector<SupportReaction> reactions;  // per spec support, branch by branch
  std::vector<JunctionLoads> junctions;
  std::vector<ContactLoad> contacts;
  double max_penetration = 0.0;  // [m] deepest remaining overlap of cable surface and solids
  /// Solids (indices into NetworkSpec::obstacles) the drawing runs the cable into by more than
  /// a quarter of its radius next to a support (within two diameters): a pipe in its flange, a
  /// wire in its connector. Held there by the support, they are no contact surfaces for it
  /// (pushing it out would fight the clamp).
  std::vector<int> attached_obstacles;
  /// The equilibrium itself, for a finer level's start (with NetworkOptions::keep_start).
  std::shared_ptr<const NetworkStart> start;
  int contact_rounds = 0;
  int num_elements = 0;
  bool converged() const { return summary.converged(); }
};

/// Compiles and solves `spec` starting from the drawn routes. Throws InvalidInput for an invalid
/// spec; a solver failure is reported in the summary, and so are invalid options
/// (TerminationType::kInvalidOptions, nothing solved).
NetworkSolution SolveNetwork(const NetworkSpec& spec, const NetworkOptions& options = {});

/// The drawn shape of a compiled network as a solver state (supports start at the poses the
/// drawing gives them; the solver moves them to their targets).
RodState DrawnNetworkState(const NetworkModel& net, const std::vector<Polyline>* routes = nullptr,
                           const std::vector<Eigen::Matrix3Xd>* normals = nullptr);

}  // namespace cablefit
