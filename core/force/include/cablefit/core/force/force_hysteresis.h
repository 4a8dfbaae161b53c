// Rate-independent hysteresis of a force rig: the Iwan model, a parallel set of Jenkins elements
// (a spring k_i in series with a Coulomb slider of slip force f_i) driven by the rig's
// displacement or angle. Source: W. D. Iwan, "A distributed-element model for hysteresis and its
// steady-state dynamic response", J. Appl. Mech. 33 (1966) 893-900; the discrete (parallel
// Jenkins) form obeys Masing's rules by construction.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace cablefit {

/// One spring-slider pair. Units follow the rig: [N/m] and [N] for pinned_bending,
/// [N m/rad] and [N m] for clamped_torsion.
struct JenkinsElement {
  double stiffness = 0.0;   // k_i
  double slip_force = 0.0;  // f_i
  /// Displacement of the spring when the slider starts to slip, f_i / k_i.
  double SlipDisplacement() const { return slip_force / stiffness; }
};

/// Normalised force z in [-1, 1] of a Jenkins element with slip displacement `slip_displacement`
/// (> 0) and unit slip force, driven through `x` (n) from the unloaded (virgin) state at
/// `x_start`. The element force for slip force f is f * z.
Eigen::VectorXd UnitJenkinsResponse(double slip_displacement, const Eigen::VectorXd& x,
                                    double x_start = 0.0);  // n -> n [-]

/// Total force (n) of the Iwan model driven through `x` (n) from the virgin state at `x_start`.
Eigen::VectorXd IwanResponse(const std::vector<JenkinsElement>& elements, const Eigen::VectorXd& x,
                             double x_start = 0.0);

/// Index of the last row of the first load cycle: x leaves x[0], turns, and the cycle ends at the
/// first later row where x is back at (or beyond) x[0]. The last row if it never comes back.
int FirstCycleEnd(const Eigen::VectorXd& x);

/// Area enclosed by the polygon through rows 0..FirstCycleEnd(x) of the curve (x, y), closed
/// from the last row back to the first: the energy dissipated in the first cycle, in the units
/// of x times y. A single-valued curve y(x) encloses zero area.
double FirstCycleLoopArea(const Eigen::VectorXd& x, const Eigen::VectorXd& y);

}  // namespace cablefit
