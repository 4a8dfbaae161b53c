#include "cablefit/core/solver/centerline_sampling.h"

#include <algorithm>

namespace cablefit {

Eigen::VectorXd UniformArcLengths(double length, int n) {
  return Eigen::VectorXd::LinSpaced(n, 0.0, length);
}

// Cubic Lagrange through the four nodes around each sample's interval (fewer near the ends).
// A fit samples every forward solve's centreline at half-millimetre spacing: the stencil's
// denominators are computed once per stencil, and sorted samples walk the intervals instead of
// searching them.
Polyline SampleCenterline(const Polyline& nodes, const Eigen::VectorXd& s) {
  const int n = nodes.size();
  Polyline out;
  out.s = s;
  out.points.resize(3, s.size());
  int lo_cached = -1, hi_cached = -1;
  double inv_den[4] = {0, 0, 0, 0};
  int i = 0;
  for (int k = 0; k < s.size(); ++k) {
    const double x = std::clamp(s[k], nodes.s[0], nodes.s[n - 1]);
    // The interval of x: the walk from the last one when samples ascend, a search otherwise.
    if (i < 0 || i > n - 2 || nodes.s[i] > x)
      i = static_cast<int>(std::upper_bound(nodes.s.data(), nodes.s.data() + n, x) - nodes.s.data()) - 1;
    while (i + 1 < n - 1 && nodes.s[i + 1] <= x) ++i;
    i = std::clamp(i, 0, std::max(0, n - 2));
    const int lo = std::clamp(i - 1, 0, std::max(0, n - 4));
    const int hi = std::min(n - 1, lo + 3);
    if (lo != lo_cached || hi != hi_cached) {
      for (int a = lo; a <= hi; ++a) {
        double d = 1.0;
        for (int b = lo; b <= hi; ++b)
          if (b != a) d *= nodes.s[a] - nodes.s[b];
        inv_den[a - lo] = 1.0 / d;
      }
      lo_cached = lo;
      hi_cached = hi;
    }
    Vec3 p = Vec3::Zero();
    for (int a = lo; a <= hi; ++a) {
      double w = inv_den[a - lo];
      for (int b = lo; b <= hi; ++b)
        if (b != a) w *= x - nodes.s[b];
      p += w * nodes.points.col(a);
    }
    out.points.col(k) = p;
  }
  return out;
}

}  // namespace cablefit
