#include "cablefit/core/rod/internal/natural_curvature.h"

#include <algorithm>
#include <cmath>

namespace cablefit::internal {
namespace {

double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

double Envelope(const NaturalCurvatureSpec& p, double s) {
  if (s < p.s_start || s > p.s_end) return 0.0;
  if (p.ramp <= 0) return 1.0;
  const double r = std::min(p.ramp, 0.5 * (p.s_end - p.s_start));
  if (r <= 0) return 0.0;
  return Smoothstep((s - p.s_start) / r) * Smoothstep((p.s_end - s) / r);
}

}  // namespace

Vec3 NaturalCurvatureAt(const std::vector<NaturalCurvatureSpec>& pieces, double s) {
  Vec3 k = Vec3::Zero();
  for (const auto& p : pieces) k += Envelope(p, s) * p.kappa;
  return k;
}

Vec3 AverageNaturalCurvature(const std::vector<NaturalCurvatureSpec>& pieces, double s0,
                             double s1) {
  if (pieces.empty() || s1 <= s0) return Vec3::Zero();
  // Split at every interval end and ramp end so each sub-interval is smooth, then 4-point Gauss.
  std::vector<double> cuts = {s0, s1};
  for (const auto& p : pieces) {
    const double r = std::min(std::max(p.ramp, 0.0), 0.5 * (p.s_end - p.s_start));
    for (double c : {p.s_start, p.s_start + r, p.s_end - r, p.s_end})
      if (c > s0 && c < s1) cuts.push_back(c);
  }
  std::sort(cuts.begin(), cuts.end());
  static const double kX[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                               0.8611363115940526};
  static const double kW[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                               0.3478548451374538};
  Vec3 sum = Vec3::Zero();
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], b = cuts[i + 1];
    if (b <= a) continue;
    for (int g = 0; g < 4; ++g)
      sum += 0.5 * (b - a) * kW[g] * NaturalCurvatureAt(pieces, 0.5 * (a + b) + 0.5 * (b - a) * kX[g]);
  }
  return sum / (s1 - s0);
}

}  // namespace cablefit::internal
