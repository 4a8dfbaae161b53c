// Known-radius circle fits on slabs of a tube's surface points: the scan tracer's slice fit,
// offered to other readers that have a tube's surface and a first centreline (a mesh's
// skeleton route), to put that centreline on the tube's axis.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace cablefit::internal {

/// Moves each of `centres` (3 x n [m], in order along a tube of radius `radius` [m]) to the
/// centre of the robust known-radius circle fit of the `surface` points (3 x m [m]) in the slab
/// `half_width` [m] either side of it, square to the local axis (bent with it). A centre whose
/// slab holds too few points or too short an arc stays. The centres are then smoothed as the
/// scan tracer smooths its stretches (5-point quadratic Savitzky-Golay).
struct TubeSlices {
  std::vector<char> moved;  ///< per centre, whether its fit held
  double radius = 0.0;      ///< [m] median free radius of the clean slices (0: none)
};
TubeSlices FitTubeSlices(const Eigen::Matrix3Xd& surface, double radius, double half_width,
                         Eigen::Matrix3Xd* centres);

}  // namespace cablefit::internal
