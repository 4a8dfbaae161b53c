#include "cablefit/formats/plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/png_file.h"
#include "colour_distance.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::ColourDistance;

double ClosestNear(const Image& image, const Eigen::Vector2d& p, int half, Rgb colour) {
  double best = 1e9;
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx) {
      const int x = static_cast<int>(p.x()) + dx, y = static_cast<int>(p.y()) + dy;
      if (image.Contains(x, y)) best = std::min(best, ColourDistance(image.At(x, y), colour));
    }
  return best;
}

// A friction-like loop: stiffness 2 N/mm, +-1 N of hysteresis, 0 -> 5 mm -> 0.
ForceCurve Loop() {
  ForceCurve curve;
  curve.x_name = "displacement";
  curve.y_name = "force";
  const int n = 41;
  curve.x.resize(n);
  curve.y.resize(n);
  for (int i = 0; i < n; ++i) {
    const bool loading = i <= 20;
    const double u = loading ? i / 20.0 : (40 - i) / 20.0;  // 0..1..0
    curve.x[i] = 0.005 * u;                                   // [m]
    curve.y[i] = 2000.0 * curve.x[i] + (loading ? 1.0 : -1.0) * (1 - std::exp(-8 * u));
  }
  return curve;
}

TEST(Plot, ForceChartShowsAxesSeriesLoopAndLegend) {
  const ForceCurve recorded = Loop();
  ForceCurve fitted = recorded;
  for (int i = 0; i < fitted.size(); ++i) fitted.y[i] = 2000.0 * fitted.x[i];
  const PlotSpec spec = ForceCurveChart(recorded, nullptr, &fitted, true);
  ASSERT_EQ(spec.series.size(), 3u);  // loading, unloading, fitted
  EXPECT_EQ(spec.x_label, "displacement [mm]");
  EXPECT_NE(spec.series[0].line, spec.series[1].line);  // loading vs unloading told apart
  PlotFrame frame;
  const Image image = RenderPlot(spec, PlotOptions{}, &frame);
  WritePng((cablefit::testing::FreshTempDir("render") / "force_chart.png").string(), image);
  ASSERT_EQ(image.width, 1000);

  // Axes: the frame's left and bottom edges are dark all along.
  const Rgb ink{40, 40, 40};
  int dark_left = 0, dark_bottom = 0;
  const int left = static_cast<int>(std::round(frame.left)), bottom = static_cast<int>(std::round(frame.bottom));
  for (int y = static_cast<int>(frame.top) + 2; y < bottom - 2; ++y) dark_left += ColourDistance(image.At(left, y), ink) < 90;
  for (int x = left + 2; x < static_cast<int>(frame.right) - 2; ++x) dark_bottom += ColourDistance(image.At(x, bottom), ink) < 90;
  EXPECT_GT(dark_left, 0.95 * (bottom - frame.top - 4));
  EXPECT_GT(dark_bottom, 0.95 * (frame.right - frame.left - 4));

  // Series: recorded markers where the data are (mm, N), the fitted line through its values.
  for (int i : {5, 15, 25, 35})
    // Open triangles for unloading: their outline lies a few pixels from the data point.
    EXPECT_LT(ClosestNear(image, frame.ToPixel(recorded.x[i] * 1e3, recorded.y[i]), 4, SeriesColour(0)), 40.0) << i;
  EXPECT_LT(ClosestNear(image, frame.ToPixel(2.5, 5.0), 1, SeriesColour(1)), 40.0);
  // Loop shading: between loading (above) and unloading (below) at x = 4 mm, off the fitted line.
  const Eigen::Vector2d inside = frame.ToPixel(4.0, 8.0 + 0.6);
  const Rgb shaded = image.At(static_cast<int>(inside.x()), static_cast<int>(inside.y()));
  EXPECT_LT(shaded.r, 245);
  EXPECT_GT(shaded.b, shaded.r);
  // Outside the loop stays white (or grid grey).
  const Eigen::Vector2d outside = frame.ToPixel(1.0, 9.0);
  EXPECT_GT(image.At(static_cast<int>(outside.x()), static_cast<int>(outside.y())).r, 220);
}

TEST(Plot, DeviationChartShadesGapsAndBreaksLines) {
  DeviationTrace trace{"fitted", Eigen::VectorXd::LinSpaced(101, 0.0, 1.0), Eigen::VectorXd(101)};
  for (int i = 0; i <= 100; ++i) trace.deviation[i] = 0.004 * std::sin(3.0 * trace.s[i]) + 0.001;
  DeviationTrace baseline = trace;
  baseline.name = "baseline";
  baseline.deviation *= 2.0;
  for (int i = 40; i <= 60; ++i) baseline.deviation[i] = std::numeric_limits<double>::quiet_NaN();
  const PlotSpec spec = DeviationAlongArcLengthChart({baseline, trace}, {{0.4, 0.6}});
  PlotFrame frame;
  const Image image = RenderPlot(spec, PlotOptions{}, &frame);
  WritePng((cablefit::testing::FreshTempDir("render") / "deviation_chart.png").string(), image);
  EXPECT_DOUBLE_EQ(frame.y_min, 0.0);
  // Gap band: grey, not white, in an empty spot inside it; white outside.
  const Eigen::Vector2d in_gap = frame.ToPixel(0.47, 0.3);
  const Rgb grey = image.At(static_cast<int>(in_gap.x()), static_cast<int>(in_gap.y()));
  EXPECT_LT(grey.r, 240);
  EXPECT_NEAR(grey.r, grey.b, 3);
  const Eigen::Vector2d no_gap = frame.ToPixel(0.27, 0.3);
  EXPECT_GT(image.At(static_cast<int>(no_gap.x()), static_cast<int>(no_gap.y())).r, 245);
  // Baseline drawn outside the gap, absent inside it (NaN breaks the line).
  const double d20 = baseline.deviation[20] * 1e3, d50 = 2.0 * (4.0 * std::sin(1.5) + 1.0);
  EXPECT_LT(ClosestNear(image, frame.ToPixel(0.2, d20), 1, SeriesColour(0)), 40.0);
  EXPECT_GT(ClosestNear(image, frame.ToPixel(0.5, d50), 2, SeriesColour(0)), 80.0);
  EXPECT_LT(ClosestNear(image, frame.ToPixel(0.5, trace.deviation[50] * 1e3), 1, SeriesColour(1)), 40.0);
}

TEST(Plot, RejectsMismatchedSeries) {
  PlotSpec spec;
  spec.series.push_back({"bad", Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(2)});
  EXPECT_THROW_WITH(RenderPlot(spec, PlotOptions{}), InvalidInput, "'bad': 3 x values but 2 y values");
  EXPECT_THROW_WITH(RenderPlot(PlotSpec{}, PlotOptions{10, 10}), InvalidInput, "plot size");
}

}  // namespace
}  // namespace cablefit
