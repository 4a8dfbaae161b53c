// What the motion sweeps of a rod (motion_sweep.h) and of a network (core/network/network_sweep.h)
// share: the walk from the drawn pose to the first one, the jump test, and the bent starts that
// leave an unstable branch.
#pragma once

#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::internal {

/// Amplitudes of the bent starts, as fractions of the length: a symmetric saddle (a straight
/// rod pushed past its Euler load) holds the solver's small frame kicks; a bend of the order of
/// the buckled shape's does not.
inline constexpr double kEscapeBends[] = {0.01, 0.03, 0.1};

/// `c` bent sideways by a half sine of `amplitude` [m] (zero at its ends, so junctions and end
/// supports stay put), in a fixed direction normal to it.
Polyline BentSideways(const Polyline& c, double amplitude);

/// The parameters of the walk from the drawn pose (0) to q.front(), in steps no longer than the
/// sweep's largest; empty when the sweep starts at 0.
std::vector<double> ApproachSteps(const std::vector<double>& q);

/// A pose jumped to another branch: its largest move is more than `factor` times the previous
/// pose's (`previous` > 0: the first pose has no yardstick) and more than `floor` [m].
inline bool Jumped(double step, double previous, double factor, double floor) {
  return previous > 0 && step > factor * previous && step > floor;
}

}  // namespace cablefit::internal
