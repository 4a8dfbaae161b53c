#include "curve_projection.h"

#include <algorithm>
#include <limits>

namespace cablefit {

CurveProjection ProjectOntoCurve(const Polyline& curve, const Eigen::Matrix3Xd& points,
                                 const Eigen::VectorXd& s_guess, double window) {
  const int m = curve.size();
  const int n = static_cast<int>(points.cols());
  CurveProjection out;
  out.offset.resize(3, n);
  out.s.resize(n);
  const double* sb = curve.s.data();
  for (int i = 0; i < n; ++i) {
    const Vec3 p = points.col(i);
    const int lo = std::max(0, static_cast<int>(std::lower_bound(sb, sb + m, s_guess[i] - window) - sb) - 1);
    const int hi = std::min(m - 1, static_cast<int>(std::upper_bound(sb, sb + m, s_guess[i] + window) - sb));
    double best = std::numeric_limits<double>::infinity();
    Vec3 best_q = curve.points.col(0);
    double best_s = 0.0;
    for (int k = lo; k < hi; ++k) {
      const Vec3 a = curve.points.col(k), b = curve.points.col(k + 1);
      const Vec3 ab = b - a;
      const double len2 = ab.squaredNorm();
      const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
      const Vec3 q = a + t * ab;
      const double d = (p - q).squaredNorm();
      if (d < best) {
        best = d;
        best_q = q;
        best_s = sb[k] + t * (sb[k + 1] - sb[k]);
      }
    }
    out.offset.col(i) = p - best_q;
    out.s[i] = best_s;
  }
  return out;
}

}  // namespace cablefit
