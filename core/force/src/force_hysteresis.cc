// Iwan / Jenkins hysteresis (Iwan 1966), see force_hysteresis.h.
#include "cablefit/core/force/force_hysteresis.h"

#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"

namespace cablefit {

Eigen::VectorXd UnitJenkinsResponse(double slip_displacement, const Eigen::VectorXd& x,
                                    double x_start) {
  CABLEFIT_REQUIRE(slip_displacement > 0.0, "Jenkins slip displacement must be positive");
  Eigen::VectorXd z(x.size());
  double state = 0.0;  // spring force / slip force
  double previous = x_start;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    state = std::clamp(state + (x[i] - previous) / slip_displacement, -1.0, 1.0);
    previous = x[i];
    z[i] = state;
  }
  return z;
}

Eigen::VectorXd IwanResponse(const std::vector<JenkinsElement>& elements, const Eigen::VectorXd& x,
                             double x_start) {
  Eigen::VectorXd total = Eigen::VectorXd::Zero(x.size());
  for (const JenkinsElement& e : elements) {
    if (e.slip_force <= 0.0) continue;
    total += e.slip_force * UnitJenkinsResponse(e.SlipDisplacement(), x, x_start);
  }
  return total;
}

int FirstCycleEnd(const Eigen::VectorXd& x) {
  const int n = static_cast<int>(x.size());
  if (n < 2) return n - 1;
  const double scale = (x.array() - x[0]).abs().maxCoeff();
  const double tol = 1e-9 * std::max(scale, 1e-300);
  // Direction of the first move away from the start.
  int i = 1;
  while (i < n && std::abs(x[i] - x[0]) <= tol) ++i;
  if (i == n) return n - 1;
  const double direction = x[i] > x[0] ? 1.0 : -1.0;
  bool turned = false;
  for (int j = i + 1; j < n; ++j) {
    if (direction * (x[j] - x[j - 1]) < -tol) turned = true;
    if (turned && direction * (x[j] - x[0]) <= tol) return j;
  }
  return n - 1;
}

double FirstCycleLoopArea(const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  CABLEFIT_REQUIRE(x.size() == y.size(), "loop area needs x and y of equal length");
  const int end = FirstCycleEnd(x);
  double twice_area = 0.0;  // shoelace formula
  for (int i = 0; i <= end; ++i) {
    const int next = i == end ? 0 : i + 1;
    twice_area += x[i] * y[next] - x[next] * y[i];
  }
  return 0.5 * std::abs(twice_area);
}

}  // namespace cablefit
