#include "diagnose/diagnose_observation.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cablefit::addin {
namespace {

double Median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

ShapeObservation ObservationFromScan(const ScanCenterline& scan) {
  ShapeObservation obs;
  obs.points = scan.points;
  obs.s = scan.s;
  double mean_support = 1.0;
  if (scan.support.size() > 0) mean_support = std::max(1.0, scan.support.cast<double>().mean());
  obs.noise_sigma = std::max(kMinCentreNoise, scan.noise_sigma / std::sqrt(mean_support));
  for (const ScanCoverageInterval& c : scan.coverage) obs.coverage.emplace_back(c.s_start, c.s_end);
  return obs;
}

double EstimateCenterlineNoise(const Polyline& line) {
  const int n = line.size();
  if (n < 8) return kDefaultCentreNoise;
  std::vector<double> d;
  d.reserve(static_cast<std::size_t>(3 * (n - 4)));
  for (int i = 2; i + 2 < n; ++i) {
    const Vec3 f = line.points.col(i - 2) - 4.0 * line.points.col(i - 1) +
                   6.0 * line.points.col(i) - 4.0 * line.points.col(i + 1) + line.points.col(i + 2);
    for (int k = 0; k < 3; ++k) d.push_back(f[k]);
  }
  const double med = Median(d);
  for (double& x : d) x = std::abs(x - med);
  const double sigma = 1.4826 * Median(d) / std::sqrt(70.0);
  return std::max(kMinCentreNoise, sigma);
}

ShapeObservation ObservationFromCenterline(const Polyline& line, double length) {
  ShapeObservation obs;
  obs.points = line.points;
  if (line.s.size() == line.points.cols()) {
    obs.s = line.s;
  } else {
    Polyline copy = line;
    copy.ParameteriseByChords();
    obs.s = copy.s;
  }
  obs.noise_sigma = EstimateCenterlineNoise(line);
  obs.coverage.emplace_back(0.0, length);
  return obs;
}

}  // namespace cablefit::addin
