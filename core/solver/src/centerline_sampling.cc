#include "cablefit/core/solver/centerline_sampling.h"

#include <algorithm>

namespace cablefit {

Eigen::VectorXd UniformArcLengths(double length, int n) {
  return Eigen::VectorXd::LinSpaced(n, 0.0, length);
}

Polyline SampleCenterline(const Polyline& nodes, const Eigen::VectorXd& s) {
  const int n = nodes.size();
  Polyline out;
  out.s = s;
  out.points.resize(3, s.size());
  for (int k = 0; k < s.size(); ++k) {
    const double x = std::clamp(s[k], nodes.s[0], nodes.s[n - 1]);
    int i = static_cast<int>(std::upper_bound(nodes.s.data(), nodes.s.data() + n, x) - nodes.s.data()) - 1;
    i = std::clamp(i, 0, n - 2);
    // Cubic Lagrange through the four nodes around the interval (fewer near the ends).
    const int lo = std::clamp(i - 1, 0, std::max(0, n - 4));
    const int hi = std::min(n - 1, lo + 3);
    Vec3 p = Vec3::Zero();
    for (int a = lo; a <= hi; ++a) {
      double w = 1.0;
      for (int b = lo; b <= hi; ++b)
        if (b != a) w *= (x - nodes.s[b]) / (nodes.s[a] - nodes.s[b]);
      p += w * nodes.points.col(a);
    }
    out.points.col(k) = p;
  }
  return out;
}

}  // namespace cablefit
