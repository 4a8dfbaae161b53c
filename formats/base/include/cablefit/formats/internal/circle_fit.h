// Circle fits to cable cross-sections, shared by the scan tracer (robust fits to the visible arc
// of a scanned cable, in the plane perpendicular to the local axis) and the CAD tube recovery
// (the cross-section of a swept tube, 3-D points). Both rest on one algebraic fit, Kasa's.
#pragma once

#include <Eigen/Core>

namespace cablefit::internal {

struct CircleFitResult {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // 2 [m], plane coordinates
  double radius = 0.0;                               // [m]
  double scale = 0.0;      // [m] robust residual scale (1.4826 * MAD) at convergence
  bool converged = false;  // false when the normal equations were singular or diverged
};

/// Radius known: minimises sum rho(|q_i - c| - radius) by IRLS/Gauss-Newton with Tukey's
/// biweight (c = 4.685 scale), starting at `initial`. `scale_floor` [m] keeps the weights from
/// collapsing on very clean data. A partial arc of ~120 degrees fixes the centre when the radius
/// is known (two unknowns). Reference: Chernov, "Circular and Linear Regression" (2010), ch. 4;
/// Huber & Ronchetti, "Robust Statistics" (2009), IRLS.
CircleFitResult FitCircleKnownRadius(const Eigen::Matrix2Xd& points,  // 2 x m [m]
                                     const Eigen::Vector2d& initial,  // 2 [m]
                                     double radius, double scale_floor);

/// The algebraic circle fit of Kasa: minimises sum w_i (|q_i - c|^2 - r^2)^2, a linear least
/// squares problem; exact for points on a circle, also on a partial arc. Result not converged
/// for fewer than 3 points, zero total weight or (nearly) collinear points. Reference: I. Kasa,
/// "A circle fitting procedure and its error analysis", IEEE Trans. Instrum. Meas. 25(1), 1976.
CircleFitResult FitCircleAlgebraic(const Eigen::Matrix2Xd& points,   // 2 x m [m]
                                   const Eigen::VectorXd& weights);  // m [-]

/// Radius free: weighted algebraic (Kasa) fit refined by Gauss-Newton on geometric distances.
/// `weights` (m, >= 0) come from a previous robust fit. Poorly conditioned on short arcs: the
/// caller judges by the arc span. Reference: Kasa (1976), IEEE Trans. Instrum. Meas. 25(1).
CircleFitResult FitCircleFree(const Eigen::Matrix2Xd& points,   // 2 x m [m]
                              const Eigen::VectorXd& weights);  // m [-]

/// Tukey biweight for a residual divided by its cutoff (0 beyond |u| >= 1).
inline double TukeyWeight(double u) {
  if (u >= 1.0 || u <= -1.0) return 0.0;
  const double a = 1.0 - u * u;
  return a * a;
}

/// Angular span [rad] of the points around `centre`: 2 pi minus the largest angular gap.
double ArcSpan(const Eigen::Matrix2Xd& points, const Eigen::Vector2d& centre);

/// 1.4826 * median(|values|); 0 for empty input. Reorders a copy.
double RobustScale(Eigen::VectorXd values);

/// A circle in space.
struct CircleFit {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // [same unit as the points]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // unit normal of the best plane
  double radius = 0.0;
  double rms_residual = 0.0;  ///< RMS distance of the points from the fitted circle
  bool ok = false;            ///< false for fewer than 3 points or collinear points
};

/// Plane by principal components, then the algebraic (Kasa) fit in that plane.
CircleFit FitCircle(const Eigen::Matrix3Xd& points);  // points: 3 x n

}  // namespace cablefit::internal
