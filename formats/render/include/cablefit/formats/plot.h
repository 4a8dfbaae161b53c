// 2-D charts without GL: force/moment against displacement/angle with hysteresis shading, and
// deviation along arc length with the stretches the scanner did not see. A small software
// rasteriser with analytic anti-aliasing and FreeType text; output is an Image (write with
// WritePng).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cablefit/core/rod/recording_case.h"
#include "cablefit/formats/image.h"

namespace cablefit {

enum class LineStyle { kSolid, kDashed, kDotted, kNone };
enum class MarkerShape { kNone, kCircle, kSquare, kTriangle, kDiamond };

/// One curve. Non-finite y values break the line (e.g. where nothing was measured).
struct PlotSeries {
  std::string name;  // legend entry; empty = not listed
  Eigen::VectorXd x;  // n, in the plot's x unit
  Eigen::VectorXd y;  // n, in the plot's y unit
  Rgb colour{31, 119, 180};
  LineStyle line = LineStyle::kSolid;
  MarkerShape marker = MarkerShape::kNone;
  double line_width = 2.0;  // [px]
  double marker_size = 4.0;  // [px] half-width
  bool marker_filled = true;  // false: outline with a white inside
};

/// A filled polygon behind the curves, e.g. the area of a hysteresis loop.
struct PlotFill {
  std::string name;
  Eigen::Matrix2Xd polygon;  // 2 x n in data units (x; y), closed implicitly
  Rgb colour{31, 119, 180};
  double alpha = 0.18;
};

/// A vertical band across the whole plot height, e.g. a stretch not seen by the scanner.
struct PlotBand {
  double x_begin = 0.0;
  double x_end = 0.0;
};

struct PlotSpec {
  std::string title;
  std::string x_label;  // with unit, e.g. "displacement [mm]"
  std::string y_label;
  std::vector<PlotSeries> series;
  std::vector<PlotFill> fills;
  std::vector<PlotBand> bands;
  std::string band_label = "not seen";  // legend entry for the bands
  std::optional<std::pair<double, double>> x_range;  // unset: data range, nicely rounded
  std::optional<std::pair<double, double>> y_range;
};

struct PlotOptions {
  int width = 1000;  // [px]
  int height = 640;  // [px]
};

/// Where the data area landed, so tests and image maps can find data points.
struct PlotFrame {
  double left = 0, top = 0, right = 0, bottom = 0;  // data area [px]
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // axis ranges in data units
  Eigen::Vector2d ToPixel(double x, double y) const;
};

/// Renders `spec`; fills `frame` when given. Throws InvalidInput on a size mismatch in a series
/// or an unusable size.
Image RenderPlot(const PlotSpec& spec, const PlotOptions& options, PlotFrame* frame = nullptr);

/// Colours for series that must be told apart (Okabe & Ito 2008, colour-blind safe).
Rgb SeriesColour(int index);

/// Force (or moment) curve chart: `recorded` as markers split into loading (x increasing,
/// filled circles, solid) and unloading (x decreasing, open triangles, dashed), optional
/// `nominal` and `fitted` model curves, and the loop between loading and unloading shaded.
/// Units: displacement [mm], angle [deg], force [N], moment [N mm].
PlotSpec ForceCurveChart(const ForceCurve& recorded, const ForceCurve* nominal,
                         const ForceCurve* fitted, bool shade_hysteresis = true);

/// A named deviation trace along arc length.
struct DeviationTrace {
  std::string name;
  Eigen::VectorXd s;          // n [m]
  Eigen::VectorXd deviation;  // n [m]; NaN where unknown
};

/// Deviation [mm] against arc length s [m], several traces, `gaps` ([m] intervals the scan did
/// not cover) shaded.
PlotSpec DeviationAlongArcLengthChart(const std::vector<DeviationTrace>& traces,
                                      const std::vector<std::pair<double, double>>& gaps);

}  // namespace cablefit
