// A clamped cubic B-spline through a sampled curve within a tolerance, with as few poles as the
// search below finds: least squares with the end points held (Piegl & Tiller, "The NURBS Book",
// 2nd ed., section 9.4.1, eqs. 9.63-9.67) on chord-length parameters, its knots placed so that
// every span holds parameters (eqs. 9.68-9.69; then the normal equations are positive definite,
// Schoenberg-Whitney). The pole count is doubled until the fit holds, then bisected down.
// Why not OpenCASCADE's GeomAPI_PointsToBSpline: it ends in a BFGS smoothing of the parameters
// that took ~5 ms per relaxed cable, the largest part of writing a 30-cable harness's STEP.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace cablefit {

/// A clamped cubic B-spline: knots 0 (x4), the interior ones (x1 each), 1 (x4).
struct CubicSpline {
  Eigen::Matrix3Xd poles;             ///< 3 x m, in the unit of the fitted points
  std::vector<double> interior_knots; ///< m - 4 knots, strictly increasing in (0, 1)
  /// The point at parameter u in [0, 1].
  Eigen::Vector3d At(double u) const;
};

/// The fit of `points` (3 x n, n >= 4, consecutive points distinct) whose every point is within
/// `tolerance` (same unit) of the curve at its chord-length parameter; the first and last points
/// are the curve's ends. At most `max_poles` poles; std::nullopt when even that many do not hold
/// the tolerance (or the points are not finite).
std::optional<CubicSpline> FitCubicSpline(const Eigen::Matrix3Xd& points, double tolerance,
                                          int max_poles);

}  // namespace cablefit
