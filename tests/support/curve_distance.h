// Test helpers: a dense reference curve and the distance of recovered points from it.
#pragma once

#include <cmath>
#include <functional>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::testing {

/// Samples `f(u)` [m] for u in [0, 1] at n points.
inline Polyline SampleCurve(const std::function<Vec3(double)>& f, int n) {
  Polyline p;
  p.points.resize(3, n);
  for (int i = 0; i < n; ++i) p.points.col(i) = f(static_cast<double>(i) / (n - 1));
  p.ParameteriseByChords(0.0);
  return p;
}

/// Largest distance [m] of any point of `a` from the polyline `b` (one-sided Hausdorff).
/// The straight line from `a` to `b` [m] as `n` evenly spaced points.
inline Polyline StraightLine(const Vec3& a, const Vec3& b, int n = 11) {
  return SampleCurve([&](double u) -> Vec3 { return a + (b - a) * u; }, n);
}

inline double MaxDistanceToPolyline(const Polyline& a, const Polyline& b) {
  double worst = 0;
  for (int i = 0; i < a.size(); ++i) {
    const Vec3 p = a.points.col(i);
    double best = INFINITY;
    for (int j = 0; j + 1 < b.size(); ++j) {
      const Vec3 x = b.points.col(j), d = b.points.col(j + 1) - x;
      const double t = d.squaredNorm() > 0 ? std::clamp((p - x).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (x + t * d - p).norm());
    }
    worst = std::max(worst, best);
  }
  return worst;
}

}  // namespace cablefit::testing
