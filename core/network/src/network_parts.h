// Pieces shared by the network compiler, its validation and its start shape.
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/network/network_model.h"
#include "cablefit/core/rod/rod_state.h"

namespace cablefit {

std::string BranchLabel(const NetworkSpec& spec, int branch);      // "branch 'name'"
std::string JunctionLabel(const NetworkSpec& spec, int junction);  // "junction 'name'"
double TotalLength(const NetworkSpec& spec);                       // [m]
/// The branch as a single-rod spec (for validation and span breakpoints).
RodSpec BranchRodSpec(const NetworkSpec& spec, int branch);

/// Frame (w, x, y, z) of every item of the compiled network in its drawn shape: element
/// tangents along the route's chords, twist-free (parallel transport) along each branch; a
/// support frame takes its neighbouring element's frame, a junction its first branch's end frame.
/// `routes` (one per branch, as long as the branch) replace the drawn routes when given: the
/// start of a finer level from the coarser level's equilibrium; `normals` (with routes: per
/// branch, 3 x that route's elements, each element's material normal) then replace the drawn
/// twist, interpolated to this model's element midpoints.
std::vector<Eigen::Vector4d> DrawnFrames(const NetworkModel& net,
                                         const std::vector<Polyline>* routes = nullptr,
                                         const std::vector<Eigen::Matrix3Xd>* normals = nullptr);

/// A finer level's start: `from_state` (an equilibrium of `from`, a compilation of the same spec
/// on other elements; contact supports beyond the spec's may follow) carried to `to`: element
/// frames slerped along each branch, support and junction frames, support poses and multipliers
/// kept. False (and `state` untouched) when the two do not match.
bool TransferNetworkState(const NetworkModel& from, const RodState& from_state,
                          const NetworkModel& to, RodState* state);

}  // namespace cablefit
