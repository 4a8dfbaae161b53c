#include "cablefit/formats/kbl_center_curve.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "cablefit/core/base/errors.h"

namespace cablefit {

Vec3 EvaluateUniformBSpline(const Eigen::Matrix3Xd& control, int degree, double t) {
  const int n = static_cast<int>(control.cols());
  CABLEFIT_REQUIRE(degree >= 1 && n > degree,
                   "a B-spline needs more control points than its degree");
  const int p = degree;
  // Knot span [k, k+1) holding t; the last span is closed so t = n evaluates.
  const int k = std::clamp(static_cast<int>(std::floor(t)), p, n - 1);
  std::vector<Vec3> d(static_cast<size_t>(p + 1));
  for (int j = 0; j <= p; ++j) d[static_cast<size_t>(j)] = control.col(j + k - p);
  // De Boor with knots t_i = i: alpha = (t - t_{j+k-p}) / (t_{j+1+k-r} - t_{j+k-p}).
  for (int r = 1; r <= p; ++r) {
    for (int j = p; j >= r; --j) {
      const double alpha = (t - (j + k - p)) / static_cast<double>(p + 1 - r);
      d[static_cast<size_t>(j)] =
          (1.0 - alpha) * d[static_cast<size_t>(j - 1)] + alpha * d[static_cast<size_t>(j)];
    }
  }
  return d[static_cast<size_t>(p)];
}

Polyline SampleUniformBSpline(const Eigen::Matrix3Xd& control, int degree, int samples_per_span) {
  const int n = static_cast<int>(control.cols());
  if (degree < 1) throw InvalidInput("degree " + std::to_string(degree) + " (expected 1 or more)");
  if (n <= degree) {
    throw InvalidInput(std::to_string(n) + " control points for degree " + std::to_string(degree) +
                       " (expected more than the degree)");
  }
  const int spans = n - degree;
  const int per_span = std::max(1, samples_per_span);
  const int count = spans * per_span + 1;
  Polyline out;
  out.points.resize(3, count);
  for (int i = 0; i < count; ++i) {
    const double t = degree + static_cast<double>(i) / per_span;
    out.points.col(i) = EvaluateUniformBSpline(control, degree, t);
  }
  out.ParameteriseByChords();
  return out;
}

}  // namespace cablefit
