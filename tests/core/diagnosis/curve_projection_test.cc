// The windowed projection must give exactly what a scan of every segment in the window gives,
// also where the curve comes back close to itself (a loop) and where points lie far off it.
#include "curve_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace cablefit {
namespace {

CurveProjection BruteForce(const Polyline& curve, const Eigen::Matrix3Xd& points,
                           const Eigen::VectorXd& s_guess, double window) {
  const int m = curve.size();
  CurveProjection out;
  out.offset.resize(3, points.cols());
  out.s.resize(points.cols());
  for (int i = 0; i < points.cols(); ++i) {
    const Vec3 p = points.col(i);
    double best = std::numeric_limits<double>::infinity();
    Vec3 q_best = curve.points.col(0);
    double s_best = 0.0;
    for (int k = 0; k + 1 < m; ++k) {
      if (curve.s[k + 1] < s_guess[i] - window || curve.s[k] > s_guess[i] + window) continue;
      const Vec3 a = curve.points.col(k), ab = curve.points.col(k + 1) - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      const Vec3 q = a + t * ab;
      if ((p - q).squaredNorm() < best) {
        best = (p - q).squaredNorm();
        q_best = q;
        s_best = curve.s[k] + t * (curve.s[k + 1] - curve.s[k]);
      }
    }
    out.offset.col(i) = p - q_best;
    out.s[i] = s_best;
  }
  return out;
}

// A helix-like loop of length about 1 m that passes within a few mm of itself.
Polyline Loop(int samples) {
  Polyline c;
  c.points.resize(3, samples);
  c.s.resize(samples);
  double s = 0.0;
  for (int k = 0; k < samples; ++k) {
    const double u = 2.2 * M_PI * k / (samples - 1);
    c.points.col(k) = Vec3(0.15 * std::cos(u), 0.15 * std::sin(u), 0.004 * u);
    if (k > 0) s += (c.points.col(k) - c.points.col(k - 1)).norm();
    c.s[k] = s;
  }
  return c;
}

TEST(CurveProjectionTest, MatchesTheScanOfEverySegmentInTheWindow) {
  const Polyline curve = Loop(2001);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> along(-0.05, curve.s[curve.size() - 1] + 0.05);
  std::normal_distribution<double> off(0.0, 0.01);
  const int n = 400;
  Eigen::Matrix3Xd points(3, n);
  Eigen::VectorXd s(n);
  for (int i = 0; i < n; ++i) {
    const int k = std::clamp(static_cast<int>(i * 2000.0 / n), 0, 2000);
    // Every fifth point far off the curve, every seventh with a poor arc-length guess.
    const double spread = i % 5 == 0 ? 0.1 : 1.0;
    points.col(i) = curve.points.col(k) + Vec3(off(rng), off(rng), off(rng)) / spread;
    s[i] = i % 7 == 0 ? along(rng) : curve.s[k];
  }
  for (double window : {0.0, 0.002, 0.13, 2.0}) {
    const CurveProjection fast = ProjectOntoCurve(curve, points, s, window);
    const CurveProjection slow = BruteForce(curve, points, s, window);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR((fast.offset.col(i) - slow.offset.col(i)).norm(), 0.0, 1e-12) << i;
      EXPECT_NEAR(fast.s[i], slow.s[i], 1e-12) << i;
    }
  }
}

TEST(CurveProjectionTest, ShortCurves) {
  for (int m : {2, 3, 9, 10, 17}) {
    const Polyline curve = Loop(m);
    Eigen::Matrix3Xd points = curve.points.array() + 0.003;
    const CurveProjection fast = ProjectOntoCurve(curve, points, curve.s, 1.0);
    const CurveProjection slow = BruteForce(curve, points, curve.s, 1.0);
    EXPECT_LT((fast.offset - slow.offset).norm(), 1e-12) << m;
  }
}

}  // namespace
}  // namespace cablefit
