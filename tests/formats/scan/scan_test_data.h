// Test-only helpers for the scan tests: truth.json's scan facts, and distances/arc lengths
// against a polyline.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::testing {

/// truth.json's `extra.scan` block (what the scan generator did).
struct TruthScan {
  double noise_sigma = 0.0;          // [m]
  int n_outliers = 0;
  std::vector<Eigen::Vector2d> gaps;  // [m] s intervals not scanned (besides the clamp margins)
  Eigen::Vector2d clamp_margins = Eigen::Vector2d::Zero();  // [m]
};

inline TruthScan LoadTruthScan(const std::filesystem::path& path) {
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& extra = j.at("extra");
  TruthScan t;
  const auto& scan = extra.at("scan");
  t.noise_sigma = scan.at("noise_sigma").get<double>();
  t.n_outliers = scan.at("n_outliers").get<int>();
  for (const auto& g : scan.at("gaps")) t.gaps.emplace_back(g[0].get<double>(), g[1].get<double>());
  t.clamp_margins = {scan.at("clamp_margins")[0].get<double>(), scan.at("clamp_margins")[1].get<double>()};
  return t;
}

/// Catmull-Rom refinement of a polyline sampled at arc lengths: the chords of the refined line
/// follow the curve to O(h^4), so chord interpolation no longer hides sub-0.1 mm errors.
inline Polyline Densify(const Polyline& line, int parts) {
  const int n = line.size();
  Polyline out;
  out.points.resize(3, (n - 1) * parts + 1);
  out.s.resize((n - 1) * parts + 1);
  auto tangent = [&](int i) -> Eigen::Vector3d {
    const int a = std::max(i - 1, 0), b = std::min(i + 1, n - 1);
    return (line.points.col(b) - line.points.col(a)) / (line.s(b) - line.s(a));
  };
  for (int i = 0; i + 1 < n; ++i) {
    const double h = line.s(i + 1) - line.s(i);
    const Eigen::Vector3d p0 = line.points.col(i), p1 = line.points.col(i + 1);
    const Eigen::Vector3d m0 = tangent(i) * h, m1 = tangent(i + 1) * h;
    for (int k = 0; k < parts; ++k) {
      const double u = static_cast<double>(k) / parts, u2 = u * u, u3 = u2 * u;
      out.points.col(i * parts + k) = (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 +
                                      (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1;
      out.s(i * parts + k) = line.s(i) + u * h;
    }
  }
  out.points.col(out.size() - 1) = line.points.col(n - 1);
  out.s(out.size() - 1) = line.s(n - 1);
  return out;
}

/// Distance [m] from p to the polyline and the arc length [m] of the closest point on it.
inline std::pair<double, double> ProjectOnPolyline(const Polyline& line, const Eigen::Vector3d& p) {
  double best = 1e300, best_s = 0.0;
  for (int i = 0; i + 1 < line.size(); ++i) {
    const Eigen::Vector3d a = line.points.col(i), b = line.points.col(i + 1);
    const Eigen::Vector3d ab = b - a;
    const double u = std::clamp(ab.dot(p - a) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const double d = (a + u * ab - p).norm();
    if (d < best) {
      best = d;
      best_s = line.s(i) + u * (line.s(i + 1) - line.s(i));
    }
  }
  return {best, best_s};
}

}  // namespace cablefit::testing
