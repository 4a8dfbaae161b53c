// Test-only synthetic hand-held scans: points on the visible part of a tube around a known
// centreline, seen from one scanner direction, with gaps, clamp margins, Gaussian noise and
// scattered plus clustered outliers.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::testing {

/// Arc-length sampled curve from a parametric function on [0, 1] (fine chords, `n` samples).
inline Polyline SampleCurve(const std::function<Vec3(double)>& f, int n = 20000) {
  Polyline line;
  line.points.resize(3, n);
  for (int i = 0; i < n; ++i) line.points.col(i) = f(static_cast<double>(i) / (n - 1));
  line.ParameteriseByChords(0.0);
  return line;
}

struct SyntheticScanSpec {
  double diameter = 4e-3;          // [m]
  double coverage_deg = 200.0;     // visible arc of the circumference
  Vec3 scanner_direction = Vec3(0.3, -0.4, 0.87);  // from the cable towards the scanner
  double noise_sigma = 0.1e-3;     // [m] isotropic Gaussian
  double clamp_margin = 0.01;      // [m] unseen at each end
  std::vector<Eigen::Vector2d> gaps;  // [m] unseen s intervals
  int points = 20000;              // on-surface points
  double outlier_fraction = 0.005;
  int cluster_size = 8;            // half the outliers come in clusters of this many points
  unsigned seed = 7;
};

struct SyntheticScan {
  PointCloud cloud;
  int outliers = 0;
};

inline SyntheticScan MakeSyntheticScan(const Polyline& curve, const SyntheticScanSpec& spec) {
  std::mt19937 rng(spec.seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double length = curve.s(curve.size() - 1);
  const double r = 0.5 * spec.diameter;
  const double half = 0.5 * spec.coverage_deg * M_PI / 180.0;
  auto at = [&](double s, Vec3* p, Vec3* t) {
    int i = static_cast<int>(std::upper_bound(curve.s.data(), curve.s.data() + curve.size(), s) - curve.s.data()) - 1;
    i = std::clamp(i, 0, curve.size() - 2);
    const double u = (s - curve.s(i)) / (curve.s(i + 1) - curve.s(i));
    *p = (1 - u) * curve.points.col(i) + u * curve.points.col(i + 1);
    *t = (curve.points.col(i + 1) - curve.points.col(i)).normalized();
  };
  auto seen = [&](double s) {
    if (s < spec.clamp_margin || s > length - spec.clamp_margin) return false;
    for (const auto& g : spec.gaps)
      if (s > g(0) && s < g(1)) return false;
    return true;
  };
  std::vector<Vec3> pts;
  const Vec3 scanner = spec.scanner_direction.normalized();
  while (static_cast<int>(pts.size()) < spec.points) {
    const double s = uni(rng) * length;
    if (!seen(s)) continue;
    Vec3 c, t;
    at(s, &c, &t);
    Vec3 w = scanner - scanner.dot(t) * t;
    if (w.norm() < 1e-3) w = t.unitOrthogonal();
    w.normalize();
    const Vec3 v = t.cross(w);
    const double phi = (2.0 * uni(rng) - 1.0) * half;
    const Vec3 n = std::cos(phi) * w + std::sin(phi) * v;
    pts.push_back(c + r * n + spec.noise_sigma * Vec3(gauss(rng), gauss(rng), gauss(rng)));
  }
  SyntheticScan out;
  const int n_out = static_cast<int>(spec.outlier_fraction * spec.points);
  int made = 0;
  while (made < n_out) {
    double s = uni(rng) * length;
    if (!seen(s)) continue;
    Vec3 c, t;
    at(s, &c, &t);
    const Vec3 dir = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    const Vec3 centre = c + (r + 0.5e-3 + 4e-3 * uni(rng)) * dir;  // off the surface, near it
    const bool cluster = made < n_out / 2;
    const int k = cluster ? std::min(spec.cluster_size, n_out - made) : 1;
    for (int j = 0; j < k; ++j) pts.push_back(centre + (cluster ? 0.3e-3 : 0.0) * Vec3(gauss(rng), gauss(rng), gauss(rng)));
    made += k;
  }
  std::shuffle(pts.begin(), pts.end(), rng);
  out.cloud.points.resize(3, static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) out.cloud.points.col(static_cast<Eigen::Index>(i)) = pts[i];
  out.outliers = made;
  return out;
}

}  // namespace cablefit::testing
