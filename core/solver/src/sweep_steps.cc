#include "cablefit/core/solver/internal/sweep_steps.h"

#include <algorithm>
#include <cmath>

namespace cablefit::internal {

Polyline BentSideways(const Polyline& c, double amplitude) {
  Polyline out = c;
  const int n = c.size();
  if (n < 2) return out;
  const double length = c.s[n - 1] - c.s[0];
  if (!(length > 0)) return out;
  // A fixed direction, not parallel to any axis a drawing is likely to use.
  const Vec3 fixed = Vec3(0.267, 0.534, 0.802).normalized();
  for (int i = 0; i < n; ++i) {
    const int a = std::max(0, i - 1), b = std::min(n - 1, i + 1);
    Vec3 tangent = c.points.col(b) - c.points.col(a);
    if (tangent.norm() == 0) continue;
    tangent.normalize();
    Vec3 side = fixed - fixed.dot(tangent) * tangent;
    if (side.norm() < 1e-6) side = tangent.unitOrthogonal();
    out.points.col(i) +=
        amplitude * std::sin(M_PI * (c.s[i] - c.s[0]) / length) * side.normalized();
  }
  return out;
}

std::vector<double> ApproachSteps(const std::vector<double>& q) {
  std::vector<double> out;
  if (q.empty() || q.front() == 0.0) return out;
  double largest = 0.0;
  for (size_t i = 1; i < q.size(); ++i) largest = std::max(largest, std::abs(q[i] - q[i - 1]));
  const int n =
      largest > 0 ? std::max(1, static_cast<int>(std::ceil(std::abs(q.front()) / largest))) : 1;
  for (int k = 1; k <= n; ++k) out.push_back(q.front() * k / n);
  return out;
}

}  // namespace cablefit::internal
