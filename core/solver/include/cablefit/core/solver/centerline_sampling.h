// Reading a solved centreline between its nodes.
#pragma once

#include <Eigen/Core>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// Samples a node centreline at arc lengths `s` [m] by local cubic (four-node Lagrange)
/// interpolation; arc lengths outside the nodes are clamped to the ends.
Polyline SampleCenterline(const Polyline& nodes, const Eigen::VectorXd& s);

/// n uniformly spaced arc lengths from 0 to length [m].
Eigen::VectorXd UniformArcLengths(double length, int n);

}  // namespace cablefit
