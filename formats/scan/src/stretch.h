// A seen stretch of cable: refined, lightly smoothed centres of one trace.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tube_tracer.h"

namespace cablefit::scan {

struct Stretch {
  Eigen::Matrix3Xd centres;   // 3 x n [m], ordered along the stretch
  Eigen::Matrix3Xd tangents;  // 3 x n [-] unit, towards increasing index
  Eigen::VectorXd radius;     // n [m] free fit, NaN where the arc is too short
  Eigen::VectorXi support;    // n [-] inliers per centre
  double head_extent = 0.0;   // [m] seen surface before the first centre along -tangent
  double tail_extent = 0.0;   // [m] seen surface after the last centre along +tangent
  std::vector<int> inliers;   // point indices used by any of its fits (may repeat)
  std::vector<double> residuals;  // [m] central-slab residuals, for the noise estimate

  int size() const { return static_cast<int>(centres.cols()); }
  /// Chord length through the centres [m].
  double Length() const;
};

/// Re-fits every slice of `trace` with the axis and curvature of the smoothed trace (removes the
/// lag of the predicted tangent and the bias of bent slabs), then smooths the centres with a
/// 5-point quadratic Savitzky-Golay filter (Savitzky & Golay, Anal. Chem. 36(8), 1964), which
/// leaves curves of constant curvature unshrunk. Slices that no longer fit are dropped.
Stretch RefineTrace(const Trace& trace, const Eigen::Matrix3Xd& points, const PointIndex& index,
                    const SliceParams& params);

/// 5-point quadratic Savitzky-Golay smoothing of the columns (ends: shorter symmetric windows).
Eigen::Matrix3Xd SmoothCentres(const Eigen::Matrix3Xd& centres);  // 3 x n [m]

}  // namespace cablefit::scan
