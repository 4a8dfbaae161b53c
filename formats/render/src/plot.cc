#include "cablefit/formats/plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "cablefit/core/base/errors.h"
#include "canvas.h"
#include "font.h"
#include "ticks.h"

namespace cablefit {
namespace {

using render::Font;
using render::FontWeight;
using render::Point2;
using render::TextAlign;

const Rgb kInk{40, 40, 40};
const Rgb kGrid{228, 228, 228};
const Rgb kBand{170, 170, 170};
const Rgb kWhite{255, 255, 255};
constexpr int kTickSize = 14;

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // Pads by `fraction` of the span; a degenerate range gets a unit-ish span.
  std::pair<double, double> Padded(double fraction) const {
    if (!(lo <= hi)) return {0.0, 1.0};
    double span = hi - lo;
    if (!(span > 0)) span = std::max(std::abs(lo), 1.0) * 0.1;
    return {lo - fraction * span, hi + fraction * span};
  }
};

render::DashPattern DashFor(LineStyle style, double width) {
  switch (style) {
    case LineStyle::kDashed: return {6.0 * width / 2 + 4, 4.0 + width};
    case LineStyle::kDotted: return {1.0, 2.5 * width};
    default: return {};
  }
}

void DrawMarker(Image& image, const Point2& c, MarkerShape shape, double size, Rgb colour,
                bool filled) {
  std::vector<Point2> polygon;
  switch (shape) {
    case MarkerShape::kNone: return;
    case MarkerShape::kCircle:
      if (filled) {
        render::FillCircle(image, c, size, colour);
      } else {
        render::FillCircle(image, c, size, kWhite);
        render::StrokeCircle(image, c, size - 0.6, 1.4, colour);
      }
      return;
    case MarkerShape::kSquare:
      polygon = {c + Point2(-size, -size), c + Point2(size, -size), c + Point2(size, size), c + Point2(-size, size)};
      break;
    case MarkerShape::kTriangle:
      polygon = {c + Point2(0, -1.25 * size), c + Point2(1.15 * size, 0.85 * size), c + Point2(-1.15 * size, 0.85 * size)};
      break;
    case MarkerShape::kDiamond:
      polygon = {c + Point2(0, -1.3 * size), c + Point2(1.3 * size, 0), c + Point2(0, 1.3 * size), c + Point2(-1.3 * size, 0)};
      break;
  }
  if (filled) {
    render::FillPolygon(image, polygon, colour);
  } else {
    render::FillPolygon(image, polygon, kWhite);
    polygon.push_back(polygon.front());
    render::StrokePolyline(image, polygon, 1.4, colour);
  }
}

void DrawLegendSample(Image& image, const Point2& at, const PlotSeries& s) {
  if (s.line != LineStyle::kNone)
    render::StrokePolyline(image, {at, at + Point2(30, 0)}, s.line_width, s.colour, DashFor(s.line, s.line_width));
  DrawMarker(image, at + Point2(15, 0), s.marker, s.marker_size, s.colour, s.marker_filled);
}

}  // namespace

Eigen::Vector2d PlotFrame::ToPixel(double x, double y) const {
  return {left + (x - x_min) / (x_max - x_min) * (right - left),
          bottom - (y - y_min) / (y_max - y_min) * (bottom - top)};
}

Rgb SeriesColour(int index) {
  // Okabe & Ito (2008), "Color Universal Design": distinguishable with any colour vision.
  static constexpr std::array<Rgb, 7> kColours = {{{0, 114, 178}, {213, 94, 0}, {0, 158, 115},
                                                   {230, 159, 0}, {204, 121, 167}, {86, 180, 233},
                                                   {0, 0, 0}}};
  return kColours[static_cast<std::size_t>(std::abs(index)) % kColours.size()];
}

Image RenderPlot(const PlotSpec& spec, const PlotOptions& options, PlotFrame* frame_out) {
  if (options.width < 200 || options.height < 150 || options.width > 8192 || options.height > 8192)
    throw InvalidInput("plot size must lie between 200 x 150 and 8192 x 8192 px");
  for (const PlotSeries& s : spec.series)
    if (s.x.size() != s.y.size())
      throw InvalidInput("plot series '" + s.name + "': " + std::to_string(s.x.size()) + " x values but " +
                         std::to_string(s.y.size()) + " y values");
  Font& regular = Font::Get(FontWeight::kRegular);
  Font& bold = Font::Get(FontWeight::kBold);

  Range xr, yr;
  for (const PlotSeries& s : spec.series)
    for (Eigen::Index i = 0; i < s.x.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
        xr.Add(s.x[i]);
        yr.Add(s.y[i]);
      }
  for (const PlotFill& f : spec.fills)
    for (Eigen::Index i = 0; i < f.polygon.cols(); ++i) {
      xr.Add(f.polygon(0, i));
      yr.Add(f.polygon(1, i));
    }
  for (const PlotBand& b : spec.bands) {
    xr.Add(b.x_begin);
    xr.Add(b.x_end);
  }
  PlotFrame frame;
  std::tie(frame.x_min, frame.x_max) = spec.x_range ? *spec.x_range : xr.Padded(0.02);
  std::tie(frame.y_min, frame.y_max) = spec.y_range ? *spec.y_range : yr.Padded(0.06);
  if (!(frame.x_max > frame.x_min) || !(frame.y_max > frame.y_min))
    throw InvalidInput("plot axis range must have min < max");

  const render::Ticks xt = render::NiceTicks(frame.x_min, frame.x_max, std::max(3, options.width / 110));
  const render::Ticks yt = render::NiceTicks(frame.y_min, frame.y_max, std::max(3, options.height / 80));
  double y_label_width = 0;
  for (double v : yt.values) y_label_width = std::max(y_label_width, regular.Width(render::FormatTick(v, yt.decimals), kTickSize));
  frame.left = 30 + y_label_width + 14;
  frame.right = options.width - 24.0;
  frame.top = spec.title.empty() ? 20.0 : 54.0;
  frame.bottom = options.height - 62.0;

  Image image = Image::Filled(options.width, options.height, kWhite);
  // Grid, then bands and fills, then curves: data always above the scaffolding.
  for (double v : xt.values) {
    const double x = std::round(frame.ToPixel(v, 0).x()) + 0.5;
    render::StrokeSegment(image, {x, frame.top}, {x, frame.bottom}, 1.0, kGrid);
  }
  for (double v : yt.values) {
    const double y = std::round(frame.ToPixel(0, v).y()) + 0.5;
    render::StrokeSegment(image, {frame.left, y}, {frame.right, y}, 1.0, kGrid);
  }
  Image layer = image;  // data layer, clipped to the data area when pasted back
  for (const PlotBand& b : spec.bands) {
    const double x0 = frame.ToPixel(b.x_begin, 0).x(), x1 = frame.ToPixel(b.x_end, 0).x();
    render::FillRect(layer, std::min(x0, x1), frame.top, std::max(x0, x1), frame.bottom, kBand, 0.28);
  }
  for (const PlotFill& f : spec.fills) {
    std::vector<Point2> polygon;
    for (Eigen::Index i = 0; i < f.polygon.cols(); ++i) polygon.push_back(frame.ToPixel(f.polygon(0, i), f.polygon(1, i)));
    render::FillPolygon(layer, polygon, f.colour, f.alpha);
  }
  for (const PlotSeries& s : spec.series) {
    std::vector<Point2> points;
    for (Eigen::Index i = 0; i < s.x.size(); ++i)
      points.push_back(std::isfinite(s.x[i]) && std::isfinite(s.y[i])
                           ? Point2(frame.ToPixel(s.x[i], s.y[i]))
                           : Point2(std::numeric_limits<double>::quiet_NaN(), 0.0));
    if (s.line != LineStyle::kNone) render::StrokePolyline(layer, points, s.line_width, s.colour, DashFor(s.line, s.line_width));
    for (const Point2& p : points)
      if (std::isfinite(p.x())) DrawMarker(layer, p, s.marker, s.marker_size, s.colour, s.marker_filled);
  }
  const int l = static_cast<int>(frame.left), t = static_cast<int>(frame.top);
  const int r = static_cast<int>(std::ceil(frame.right)), b = static_cast<int>(std::ceil(frame.bottom));
  for (int y = t; y <= b; ++y)
    for (int x = l; x <= r; ++x) image.Set(x, y, layer.At(x, y));

  // Axes box, ticks and labels.
  const double bl = std::round(frame.left) + 0.5, bb = std::round(frame.bottom) + 0.5;
  const double br = std::round(frame.right) + 0.5, bt = std::round(frame.top) + 0.5;
  render::StrokePolyline(image, {{bl, bt}, {br, bt}, {br, bb}, {bl, bb}, {bl, bt}}, 1.2, kInk);
  for (double v : xt.values) {
    const double x = std::round(frame.ToPixel(v, 0).x()) + 0.5;
    render::StrokeSegment(image, {x, bb}, {x, bb + 5}, 1.2, kInk);
    regular.Draw(image, x, bb + 21, render::FormatTick(v, xt.decimals), kTickSize, kInk, TextAlign::kCentre);
  }
  for (double v : yt.values) {
    const double y = std::round(frame.ToPixel(0, v).y()) + 0.5;
    render::StrokeSegment(image, {bl - 5, y}, {bl, y}, 1.2, kInk);
    regular.Draw(image, bl - 9, y + 5, render::FormatTick(v, yt.decimals), kTickSize, kInk, TextAlign::kRight);
  }
  regular.Draw(image, (frame.left + frame.right) / 2, options.height - 16.0, spec.x_label, 15, kInk, TextAlign::kCentre);
  regular.DrawVertical(image, 22, (frame.top + frame.bottom) / 2, spec.y_label, 15, kInk);
  if (!spec.title.empty()) bold.Draw(image, frame.left, 34, spec.title, 18, kInk);

  // Legend in the data-area corner that hides the fewest data points.
  struct Entry { const PlotSeries* series; const PlotFill* fill; std::string text; };
  std::vector<Entry> entries;
  for (const PlotSeries& s : spec.series) if (!s.name.empty()) entries.push_back({&s, nullptr, s.name});
  for (const PlotFill& f : spec.fills) if (!f.name.empty()) entries.push_back({nullptr, &f, f.name});
  if (!spec.bands.empty() && !spec.band_label.empty()) entries.push_back({nullptr, nullptr, spec.band_label});
  if (!entries.empty()) {
    double text_w = 0;
    for (const Entry& e : entries) text_w = std::max(text_w, regular.Width(e.text, kTickSize));
    const double w = 30 + 12 + text_w + 20, h = 22.0 * static_cast<double>(entries.size()) + 10;
    std::array<Point2, 4> corners = {Point2(frame.right - w - 10, frame.top + 10), Point2(frame.left + 10, frame.top + 10),
                                     Point2(frame.right - w - 10, frame.bottom - h - 10), Point2(frame.left + 10, frame.bottom - h - 10)};
    std::size_t best = 0;
    long best_hidden = std::numeric_limits<long>::max();
    for (std::size_t c = 0; c < corners.size(); ++c) {
      long hidden = 0;
      for (const PlotSeries& s : spec.series)
        for (Eigen::Index i = 0; i < s.x.size(); ++i) {
          const Eigen::Vector2d p = frame.ToPixel(s.x[i], s.y[i]);
          hidden += p.x() >= corners[c].x() && p.x() <= corners[c].x() + w && p.y() >= corners[c].y() && p.y() <= corners[c].y() + h;
        }
      if (hidden < best_hidden) { best_hidden = hidden; best = c; }
    }
    const Point2 o = corners[best];
    render::FillRect(image, o.x(), o.y(), o.x() + w, o.y() + h, kWhite, 0.9);
    render::StrokePolyline(image, {o, o + Point2(w, 0), o + Point2(w, h), o + Point2(0, h), o}, 1.0, Rgb{190, 190, 190});
    double y = o.y() + 5 + 11;
    for (const Entry& e : entries) {
      const Point2 at(o.x() + 10, y);
      if (e.series) {
        DrawLegendSample(image, at, *e.series);
      } else {
        const Rgb c = e.fill ? e.fill->colour : kBand;
        const double a = e.fill ? std::max(0.25, e.fill->alpha) : 0.35;
        render::FillRect(image, at.x(), at.y() - 6, at.x() + 30, at.y() + 6, c, a);
      }
      regular.Draw(image, at.x() + 42, y + 5, e.text, kTickSize, kInk);
      y += 22;
    }
  }
  if (frame_out) *frame_out = frame;
  return image;
}

PlotSpec ForceCurveChart(const ForceCurve& recorded, const ForceCurve* nominal, const ForceCurve* fitted,
                         bool shade_hysteresis) {
  const bool angle = recorded.x_name == "angle";
  const bool moment = recorded.y_name == "moment";
  const double xs = angle ? 180.0 / std::numbers::pi : 1e3;  // -> deg or mm
  const double ys = moment ? 1e3 : 1.0;                      // -> N mm or N
  PlotSpec spec;
  spec.title = std::string(moment ? "moment" : "force") + " vs " + (angle ? "angle" : "displacement");
  spec.x_label = angle ? "angle [deg]" : "displacement [mm]";
  spec.y_label = moment ? "moment [N mm]" : "force [N]";
  const Rgb colour = SeriesColour(0);
  if (shade_hysteresis && recorded.size() >= 3) {
    PlotFill fill{"hysteresis loop", Eigen::Matrix2Xd(2, recorded.size()), colour, 0.14};
    fill.polygon.row(0) = recorded.x.transpose() * xs;
    fill.polygon.row(1) = recorded.y.transpose() * ys;
    spec.fills.push_back(fill);
  }
  // Split the recording at reversals: a segment is loading when |x| grows.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> lx, ly, ux, uy;
  int previous = 0;  // direction of the previous segment: +1 loading, -1 unloading
  for (int i = 0; i + 1 < recorded.size(); ++i) {
    const int dir = std::abs(recorded.x[i + 1]) >= std::abs(recorded.x[i]) ? 1 : -1;
    auto& xsv = dir > 0 ? lx : ux;
    auto& ysv = dir > 0 ? ly : uy;
    if (dir != previous) {
      if (!xsv.empty()) { xsv.push_back(nan); ysv.push_back(nan); }
      xsv.push_back(recorded.x[i] * xs);
      ysv.push_back(recorded.y[i] * ys);
    }
    xsv.push_back(recorded.x[i + 1] * xs);
    ysv.push_back(recorded.y[i + 1] * ys);
    previous = dir;
  }
  auto series = [](std::string name, const std::vector<double>& x, const std::vector<double>& y) {
    PlotSeries s;
    s.name = std::move(name);
    s.x = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
    s.y = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
    return s;
  };
  if (!lx.empty()) {
    PlotSeries s = series("recorded, loading", lx, ly);
    s.colour = colour;
    s.line_width = 1.2;
    s.marker = MarkerShape::kCircle;
    s.marker_size = 3.2;
    spec.series.push_back(s);
  }
  if (!ux.empty()) {
    PlotSeries s = series("recorded, unloading", ux, uy);
    s.colour = colour;
    s.line = LineStyle::kDashed;
    s.line_width = 1.2;
    s.marker = MarkerShape::kTriangle;
    s.marker_size = 3.6;
    s.marker_filled = false;
    spec.series.push_back(s);
  }
  auto model = [&](const ForceCurve& curve, std::string name, Rgb c, LineStyle style) {
    PlotSeries s;
    s.name = std::move(name);
    s.x = curve.x * xs;
    s.y = curve.y * ys;
    s.colour = c;
    s.line = style;
    s.line_width = 2.4;
    spec.series.push_back(s);
  };
  if (nominal) model(*nominal, "nominal model", SeriesColour(6), LineStyle::kDashed);
  if (fitted) model(*fitted, "fitted model", SeriesColour(1), LineStyle::kSolid);
  return spec;
}

PlotSpec DeviationAlongArcLengthChart(const std::vector<DeviationTrace>& traces,
                                      const std::vector<std::pair<double, double>>& gaps) {
  PlotSpec spec;
  spec.title = "deviation along the cable";
  spec.x_label = "arc length s [m]";
  spec.y_label = "deviation [mm]";
  double y_max = 0.0;
  for (std::size_t i = 0; i < traces.size(); ++i) {
    const DeviationTrace& t = traces[i];
    if (t.s.size() != t.deviation.size())
      throw InvalidInput("deviation trace '" + t.name + "': " + std::to_string(t.s.size()) + " arc lengths but " +
                         std::to_string(t.deviation.size()) + " deviations");
    PlotSeries s;
    s.name = t.name;
    s.x = t.s;
    s.y = t.deviation * 1e3;
    s.colour = SeriesColour(static_cast<int>(i));
    s.line_width = 2.2;
    for (Eigen::Index k = 0; k < s.y.size(); ++k)
      if (std::isfinite(s.y[k])) y_max = std::max(y_max, s.y[k]);
    spec.series.push_back(s);
  }
  for (const auto& [a, b] : gaps) spec.bands.push_back({a, b});
  // Deviations are distances: the axis starts at zero so heights compare honestly.
  spec.y_range = std::make_pair(0.0, y_max > 0 ? y_max * 1.08 : 1.0);
  return spec;
}

}  // namespace cablefit
