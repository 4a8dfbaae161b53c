// Traces a scanned tube slice by slice: each slice is a slab perpendicular to the current axis
// whose points are fitted by a robust circle of the cable radius; the next slice is predicted
// along the tangent. Stops at gaps, at the scan's ends, and where another trace already runs.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "point_index.h"

namespace cablefit::scan {

struct SliceParams {
  double radius = 0.0;         // [m] cable radius used by the fits
  double step = 0.0;           // [m] distance between slices
  double half_width = 0.0;     // [m] slab half-thickness (>= step / 2 so slabs overlap)
  double window = 0.0;         // [m] in-plane acceptance beyond `radius` around the prediction
  double scale_floor = 0.0;    // [m] lower bound of the residual scale
  double inlier_cutoff = 3.5;  // residual / scale beyond which a point is a fit outlier
  int min_support = 8;         // inliers a slice needs
  double min_span = 1.0;       // [rad] visible arc a slice needs
};

struct SliceFit {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   // 3 [m]
  Eigen::Vector3d tangent = Eigen::Vector3d::UnitX(); // 3 [-] unit slab normal used
  double free_radius = 0.0;     // [m] free circle fit, NaN when the arc is too short to tell
  double span = 0.0;            // [rad] angular span of the inliers
  double scale = 0.0;           // [m] robust residual scale of this fit
  std::vector<int> inliers;     // point indices
  std::vector<double> central_residuals;  // [m] all candidates with |axial| <= step / 2
  double axial_min = 0.0;       // [m] smallest axial offset of an inlier from the centre
  double axial_max = 0.0;       // [m] largest axial offset of an inlier from the centre
};

/// Fits one slab centred at `guess` (3 [m]) with unit normal `tangent` (3). `curvature` (3
/// [1/m], kappa * principal normal, may be zero) bends the slab with the local axis so that
/// thick slabs on tight bends stay unbiased. False when the slab has too little support or arc.
bool FitSlice(const Eigen::Matrix3Xd& points, const PointIndex& index, const Eigen::Vector3d& guess,
              const Eigen::Vector3d& tangent, const Eigen::Vector3d& curvature,
              const SliceParams& params, SliceFit* fit);

/// One traced stretch: slices in order along the tube.
using Trace = std::vector<SliceFit>;

/// Seeds at unclaimed usable points and traces both ways until every usable point is claimed.
/// `usable` (n) masks statistical outliers. Traces shorter than `min_length` [m] are dropped
/// (stray clusters).
std::vector<Trace> TraceTube(const Eigen::Matrix3Xd& points, const PointIndex& index,
                             const std::vector<char>& usable, const SliceParams& params,
                             double min_length);

}  // namespace cablefit::scan
