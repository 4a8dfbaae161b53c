// Where a fit's residual bends: the places along the cable where what a fit leaves curves most.
// A curvature span the model lacks leaves a step of curvature over its span, a contact a peak
// of curvature at its place (the moment of a point force is piecewise linear), so that the
// residual's own curvature says where a placed effect belongs, on any layout. A pair search
// starts its placed effects there, beside the fixed grid of places.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace cablefit {

/// A place where a residual bends.
struct ResidualBend {
  double s = 0.0;          // [m] arc length of the peak
  double width = 0.0;      // [m] how wide the bend is (where it exceeds half its peak)
  double curvature = 0.0;  // [1/m] the residual's curvature there (its size)
};

/// The `count` strongest bends of the residual `offsets` (3n [m], point minus curve) of the
/// points at arc lengths `s` (n [m], increasing) on a cable of `length` [m], strongest first,
/// each at least `separation` of the cable from the others. The curvature is the second
/// derivative of a quadratic fitted to the offsets over a window of `window` of the cable about
/// each point (which averages the noise out), wider where the points are too sparse for it;
/// windows with too few points or one side unseen (a gap, an end) are skipped.
std::vector<ResidualBend> FindResidualBends(const Eigen::VectorXd& offsets,
                                            const Eigen::VectorXd& s, double length, int count,
                                            double window = 0.12, double separation = 0.1);

}  // namespace cablefit
