#include "cablefit/core/base/helix.h"

#include <cmath>

namespace cablefit {

Polyline SampleHelix(double radius, double pitch, double turns) {
  const int n = static_cast<int>(96 * turns) + 1;
  Polyline h;
  h.points.resize(3, n);
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * turns * k / (n - 1);
    h.points.col(k) = Vec3(radius * std::cos(a), radius * std::sin(a), pitch * a / (2 * M_PI));
  }
  h.ParameteriseByChords();
  return h;
}

}  // namespace cablefit
