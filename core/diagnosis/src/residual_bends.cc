#include "residual_bends.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace cablefit {
namespace {

// Points a window needs for its quadratic to average noise rather than follow it.
constexpr int kMinWindowPoints = 7;

}  // namespace

std::vector<ResidualBend> FindResidualBends(const Eigen::VectorXd& offsets,
                                            const Eigen::VectorXd& s, double length, int count,
                                            double window, double separation) {
  const Eigen::Index n = s.size();
  std::vector<ResidualBend> bends;
  if (n < kMinWindowPoints || offsets.size() != 3 * n || !(length > 0)) return bends;
  // The window is widened to hold enough points at the recording's mean spacing: a recording
  // thinned to a few tens of points has fewer than that in a tenth of the cable.
  const double spacing = (s[n - 1] - s[0]) / static_cast<double>(n - 1);
  const double h = std::max(0.5 * window * length, 0.5 * (kMinWindowPoints + 1) * spacing);
  Eigen::VectorXd k = Eigen::VectorXd::Zero(n);  // the residual's curvature at each point
  std::vector<bool> valid(static_cast<size_t>(n), false);
  Eigen::Index lo = 0, hi = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    while (lo < n && s[lo] < s[j] - h) ++lo;
    while (hi < n && s[hi] <= s[j] + h) ++hi;
    const Eigen::Index m = hi - lo;
    // Both sides of the point seen: a window cut by a gap or an end would extrapolate.
    if (m < kMinWindowPoints || s[j] - s[lo] < 0.5 * h || s[hi - 1] - s[j] < 0.5 * h) continue;
    Eigen::MatrixXd a(m, 3);
    Eigen::MatrixXd b(m, 3);
    for (Eigen::Index i = 0; i < m; ++i) {
      const double u = (s[lo + i] - s[j]) / h;  // scaled for conditioning
      a.row(i) << 1.0, u, u * u;
      b.row(i) = offsets.segment<3>(3 * (lo + i)).transpose();
    }
    const Eigen::MatrixXd c = a.colPivHouseholderQr().solve(b);  // 3 x 3: rows 1, u, u^2
    k[j] = 2.0 * c.row(2).norm() / (h * h);
    valid[static_cast<size_t>(j)] = true;
  }
  // Peaks strongest first, each far enough from the ones taken.
  std::vector<Eigen::Index> order;
  for (Eigen::Index j = 0; j < n; ++j)
    if (valid[static_cast<size_t>(j)]) order.push_back(j);
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index p, Eigen::Index q) { return k[p] > k[q]; });
  for (Eigen::Index j : order) {
    if (static_cast<int>(bends.size()) >= count || !(k[j] > 0)) break;
    bool near = false;
    for (const ResidualBend& b : bends) near = near || std::abs(b.s - s[j]) < separation * length;
    if (near) continue;
    // The bend's extent: where the curvature stays above half the peak, around it.
    Eigen::Index a = j, e = j;
    while (a > 0 && valid[static_cast<size_t>(a - 1)] && k[a - 1] >= 0.5 * k[j]) --a;
    while (e + 1 < n && valid[static_cast<size_t>(e + 1)] && k[e + 1] >= 0.5 * k[j]) ++e;
    bends.push_back({s[j], s[e] - s[a], k[j]});
  }
  return bends;
}

}  // namespace cablefit
