#include "cablefit/core/base/cubic_spline_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cablefit {
namespace {

// A helix of radius 50 and pitch 40 over two turns, sampled unevenly (denser in the middle).
Eigen::Matrix3Xd Helix(int n) {
  Eigen::Matrix3Xd p(3, n);
  for (int i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / (n - 1);
    const double t = 4 * M_PI * (s - 0.3 * std::sin(2 * M_PI * s) / (2 * M_PI));
    p.col(i) << 50 * std::cos(t), 50 * std::sin(t), 40 * t / (2 * M_PI);
  }
  return p;
}

// The distance of p from the curve: from a dense polyline of it, refined around the nearest
// vertex (accurate to far below the tolerances tested).
double DistanceFromCurve(const CubicSpline& c, const Eigen::Vector3d& p) {
  constexpr int kSamples = 4000;
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kSamples; ++i) {
    const double d = (c.At(static_cast<double>(i) / kSamples) - p).norm();
    if (d < best_d) best_d = d, best = i;
  }
  double lo = std::max(0, best - 1) / static_cast<double>(kSamples);
  double hi = std::min(kSamples, best + 1) / static_cast<double>(kSamples);
  for (int k = 0; k < 60; ++k) {  // ternary search on the neighbourhood of the nearest vertex
    const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
    if ((c.At(a) - p).norm() < (c.At(b) - p).norm()) {
      hi = b;
    } else {
      lo = a;
    }
  }
  return std::min(best_d, (c.At(0.5 * (lo + hi)) - p).norm());
}

TEST(CubicSplineFit, EveryPointIsWithinTheToleranceWithFarFewerPoles) {
  const Eigen::Matrix3Xd p = Helix(400);
  for (const double tolerance : {1e-1, 1e-2, 1e-3}) {
    const auto fit = FitCubicSpline(p, tolerance, 400);
    ASSERT_TRUE(fit.has_value()) << tolerance;
    double worst = 0.0;
    for (int k = 0; k < 400; ++k) worst = std::max(worst, DistanceFromCurve(*fit, p.col(k)));
    EXPECT_LE(worst, tolerance * (1 + 1e-6));
    EXPECT_LT(fit->poles.cols(), 100) << tolerance;
    EXPECT_EQ(fit->interior_knots.size() + 4, static_cast<size_t>(fit->poles.cols()));
    for (size_t k = 0; k < fit->interior_knots.size(); ++k) {
      EXPECT_GT(fit->interior_knots[k], k == 0 ? 0.0 : fit->interior_knots[k - 1]);
      EXPECT_LT(fit->interior_knots[k], 1.0);
    }
    // The ends are the drawn ends, exactly.
    EXPECT_EQ(fit->At(0.0), Eigen::Vector3d(p.col(0)));
    EXPECT_EQ(fit->At(1.0), Eigen::Vector3d(p.col(399)));
  }
  // A tighter tolerance takes more poles; 2 mm cannot be met with 8 poles over two turns.
  EXPECT_LT(FitCubicSpline(p, 1e-1, 400)->poles.cols(), FitCubicSpline(p, 1e-3, 400)->poles.cols());
  EXPECT_FALSE(FitCubicSpline(p, 2.0, 8).has_value());
}

// A circular arc of 0.76 rad (420 mm), which one cubic holds to a few micrometres when the
// distance is measured across the curve: the fit finds that (chord-length parameters alone
// took 7 poles for 6 um).
TEST(CubicSplineFit, AShallowArcTakesOneCubic) {
  const double radius = 276.3, half = 0.38;
  Eigen::Matrix3Xd p(3, 226);
  for (int i = 0; i < 226; ++i) {
    const double phi = -half + 2 * half * i / 225.0;
    p.col(i) << radius * std::sin(phi), 0, radius * (std::cos(phi) - std::cos(half));
  }
  const auto fit = FitCubicSpline(p, 6e-3, 226);
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(fit->poles.cols(), 4);
  double worst = 0.0;
  for (int k = 0; k < 226; ++k) worst = std::max(worst, DistanceFromCurve(*fit, p.col(k)));
  EXPECT_LE(worst, 6e-3);
  // Its end tangents are the arc's (the clamps a reader takes from them).
  const Eigen::Vector3d start = (fit->poles.col(1) - fit->poles.col(0)).normalized();
  EXPECT_LT(std::acos(std::min(1.0, start.dot(Eigen::Vector3d(std::cos(half), 0, std::sin(half))))), 1e-4);
}

TEST(CubicSplineFit, AStraightLineTakesFourPolesOnIt) {
  Eigen::Matrix3Xd p(3, 30);
  for (int i = 0; i < 30; ++i) p.col(i) = Eigen::Vector3d(1, 2, 3) + (i * i / 29.0) * Eigen::Vector3d(0.6, 0, 0.8);
  const auto fit = FitCubicSpline(p, 1e-9, 30);
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(fit->poles.cols(), 4);
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d d = fit->poles.col(i) - Eigen::Vector3d(1, 2, 3);
    EXPECT_NEAR(d.cross(Eigen::Vector3d(0.6, 0, 0.8)).norm(), 0.0, 1e-12);
  }
}

// A relaxed harness segment's nodes [mm] (18 points ~22 mm apart on a gentle curve): the fit
// once met its tolerance at every point with a pole 3 m away, the curve looping out between
// the first points; no tube could be swept along it.
TEST(CubicSplineFit, TheCurveDoesNotSwingAwayBetweenItsPoints) {
  const double rows[][3] = {
      {789.690068, -339.347588, -139.359423}, {803.877515, -355.818354, -130.372795},
      {819.604878, -371.010073, -121.708879}, {836.993596, -384.506339, -113.429573},
      {856.044579, -395.868909, -105.627278}, {876.621805, -404.667042, -98.418744},
      {898.448665, -410.516366, -91.933846},  {921.121921, -413.121188, -86.300332},
      {944.144878, -412.311725, -81.626788},  {966.976664, -408.067436, -77.986934},
      {989.089721, -400.520227, -75.408398},  {1010.025100, -389.936334, -73.868080},
      {1029.627221, -376.949237, -73.244092}, {1049.052118, -363.673324, -73.118695},
      {1068.492546, -350.422931, -73.418125}, {1087.890633, -337.127051, -74.143250},
      {1107.187769, -323.715089, -75.296370}, {1126.323579, -310.117461, -76.881138}};
  const int n = static_cast<int>(std::size(rows));
  Eigen::Matrix3Xd p(3, n);
  for (int i = 0; i < n; ++i) p.col(i) << rows[i][0], rows[i][1], rows[i][2];
  const std::optional<CubicSpline> fit = FitCubicSpline(p, 0.005, n);
  ASSERT_TRUE(fit.has_value());
  double worst = 0.0;  // [mm] the curve's largest distance from the polyline of the points
  for (int k = 0; k <= 4000; ++k) {
    const Eigen::Vector3d c = fit->At(k / 4000.0);
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i + 1 < n; ++i) {
      const Eigen::Vector3d a = p.col(i), ab = p.col(i + 1) - p.col(i);
      const double t = std::clamp((c - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * ab - c).norm());
    }
    worst = std::max(worst, nearest);
  }
  // The chords' sagitta on this curve is a fraction of a millimetre.
  EXPECT_LT(worst, 1.0);
}

TEST(CubicSplineFit, InputsItCannotFitGiveNoFit) {
  Eigen::Matrix3Xd p = Helix(20);
  EXPECT_FALSE(FitCubicSpline(p.leftCols(3), 1e-3, 10).has_value());  // fewer than 4 points
  EXPECT_FALSE(FitCubicSpline(p, 0.0, 20).has_value());
  Eigen::Matrix3Xd repeated = p;
  repeated.col(5) = repeated.col(4);
  EXPECT_FALSE(FitCubicSpline(repeated, 1e-3, 20).has_value());
  p(1, 7) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(FitCubicSpline(p, 1e-3, 20).has_value());
}

}  // namespace
}  // namespace cablefit
