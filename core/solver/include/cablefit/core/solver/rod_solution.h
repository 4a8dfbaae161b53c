// What a solved rod reports: centreline and frames, internal force and moment along s, the
// reaction of every support, energy and the solver's summary.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/rod_state.h"
#include "cablefit/core/solver/statics_solver.h"

namespace cablefit {

struct SupportReaction {
  SupportKind kind = SupportKind::kClamp;
  double s = 0.0;                 // [m]
  Vec3 force = Vec3::Zero();      // [N] exerted by the support on the cable (world)
  Vec3 moment = Vec3::Zero();     // [N m] about the support point (world)
};

struct RodSolution {
  Polyline centerline;               // nodes: s [m] and positions 3 x (n+1) [m]
  Eigen::VectorXd frame_s;           // n [m] element midpoints
  std::vector<Frame> frames;         // n element material frames
  Eigen::Matrix3Xd internal_force;   // 3 x n [N] force of the part s' > s on the part s' < s
  Eigen::VectorXd moment_s;          // e [m] edge positions
  Eigen::Matrix3Xd internal_moment;  // 3 x e [N m] world frame
  std::vector<SupportReaction> reactions;  // one per support, in spec order
  double energy = 0.0;               // [J] elastic + potential of loads
  double elastic_energy = 0.0;       // [J]
  double twist_angle = 0.0;          // [rad] total twist: integral of the twist rate
  StaticsSummary summary;
};

RodSolution ExtractSolution(const RodModel& model, const RodState& state,
                            const StaticsSummary& summary);

}  // namespace cablefit
