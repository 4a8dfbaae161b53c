// Least-squares circle through 3-D points: the cross-section of a swept tube.
#pragma once

#include <Eigen/Core>

namespace cablefit {

struct CircleFit {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // [same unit as the points]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // unit normal of the best plane
  double radius = 0.0;
  double rms_residual = 0.0;  ///< RMS distance of the points from the fitted circle
  bool ok = false;            ///< false for fewer than 3 points or collinear points
};

/// Plane by principal components, then the algebraic circle fit of Kasa in that plane
/// (I. Kasa, "A circle fitting procedure and its error analysis", IEEE Trans. Instrum. Meas.
/// 25(1), 1976): exact for points on a circle, also on a partial arc.
CircleFit FitCircle(const Eigen::Matrix3Xd& points);  // points: 3 x n

}  // namespace cablefit
