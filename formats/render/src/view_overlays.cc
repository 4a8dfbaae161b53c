#include "view_overlays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "canvas.h"
#include "font.h"
#include "ticks.h"
#include "view_planning.h"

namespace cablefit::render {
namespace {

constexpr int kTitleSize = 17;
constexpr int kLabelSize = 14;

void DrawSupportSymbol(Image& image, const Point2& c, SupportMarkerKind kind, double size) {
  const Rgb white{255, 255, 255};
  switch (kind) {
    case SupportMarkerKind::kClamp:  // filled square: holds position and direction
      FillRect(image, c.x() - size - 1.5, c.y() - size - 1.5, c.x() + size + 1.5, c.y() + size + 1.5, white);
      FillRect(image, c.x() - size, c.y() - size, c.x() + size, c.y() + size, kInk);
      break;
    case SupportMarkerKind::kClip:  // ring: holds position, lets the cable slide/turn
      StrokeCircle(image, c, size, 4.5, white);
      StrokeCircle(image, c, size, 2.2, kInk);
      break;
    case SupportMarkerKind::kPin: {  // triangle: holds position only
      const std::vector<Point2> outer = {{c.x(), c.y() - size * 1.35 - 2}, {c.x() + size * 1.25 + 2, c.y() + size + 1.2},
                                         {c.x() - size * 1.25 - 2, c.y() + size + 1.2}};
      const std::vector<Point2> inner = {{c.x(), c.y() - size * 1.35}, {c.x() + size * 1.25, c.y() + size},
                                         {c.x() - size * 1.25, c.y() + size}};
      FillPolygon(image, outer, white);
      FillPolygon(image, inner, kInk);
      break;
    }
  }
}

}  // namespace

std::string FormatLength(double metres) {
  char buffer[32];
  const double mm = metres * 1e3;
  if (mm >= 1000.0)
    std::snprintf(buffer, sizeof buffer, "%g m", std::round(metres * 100.0) / 100.0);
  else
    std::snprintf(buffer, sizeof buffer, "%g mm", std::round(mm * 100.0) / 100.0);
  return buffer;
}

void DrawPanelFrame(Image& image, const ViewCamera& camera) {
  const double x0 = camera.x + 0.5, y0 = camera.y + 0.5;
  const double x1 = camera.x + camera.width - 0.5, y1 = camera.y + camera.height - 0.5;
  StrokePolyline(image, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}, 1.0, kFrame);
  Font::Get(FontWeight::kBold).Draw(image, camera.x + 12, camera.y + 24, camera.title, kTitleSize, kInk);
}

void DrawSupports(Image& image, const ViewCamera& camera, const Scene& scene) {
  Font& font = Font::Get(FontWeight::kRegular);
  for (std::size_t i = 0; i < scene.supports.size(); ++i) {
    const SceneSupport& support = scene.supports[i];
    if (!support.position.allFinite()) continue;
    const Point2 c = camera.Project(support.position);
    if (static_cast<int>(i) == scene.highlighted_support) {
      StrokeCircle(image, c, 15.0, 3.0, kHighlight);
    }
    DrawSupportSymbol(image, c, support.kind, 5.5);
    const std::string label = support.label.empty() ? std::to_string(i + 1) : support.label;
    if (label.find_first_not_of(' ') == std::string::npos) continue;  // asked to be unlabelled
    // Label up and to the right, on a white halo so it stays legible over the tube.
    const double w = font.Width(label, kLabelSize);
    // To the left instead where the panel's edge would cut it.
    double lx = c.x() + 10;
    if (lx + w > camera.x + camera.width - 4) lx = c.x() - 10 - w;
    const double ly = c.y() - 9;
    FillRect(image, lx - 2, ly - 12, lx + w + 2, ly + 4, Rgb{255, 255, 255}, 0.8);
    font.Draw(image, lx, ly, label, kLabelSize, kInk);
  }
}

// A cross, so it is not read as a clip's ring.
void DrawLabelMark(Image& image, const Point2& c) {
  StrokeSegment(image, {c.x() - 4.5, c.y() - 4.5}, {c.x() + 4.5, c.y() + 4.5}, 2.0, kInk);
  StrokeSegment(image, {c.x() - 4.5, c.y() + 4.5}, {c.x() + 4.5, c.y() - 4.5}, 2.0, kInk);
}

void DrawLabels(Image& image, const ViewCamera& camera, const Scene& scene) {
  Font& font = Font::Get(FontWeight::kRegular);
  for (const SceneLabel& label : scene.labels) {
    if (!label.position.allFinite() || label.text.empty()) continue;
    const Point2 c = camera.Project(label.position);
    DrawLabelMark(image, c);
    // Below and to the right (support labels sit above), on a white halo, kept inside the panel.
    const double w = font.Width(label.text, kLabelSize);
    double lx = c.x() + 8, ly = c.y() + 18;
    lx = std::min(lx, camera.x + camera.width - w - 6);
    lx = std::max(lx, static_cast<double>(camera.x) + 4);
    ly = std::min(ly, camera.y + camera.height - 6.0);
    FillRect(image, lx - 2, ly - 12, lx + w + 2, ly + 4, Rgb{255, 255, 255}, 0.8);
    font.Draw(image, lx, ly, label.text, kLabelSize, kInk);
  }
}

void DrawGravityArrow(Image& image, const ViewCamera& camera, const Eigen::Vector3d& gravity) {
  if (!(gravity.norm() > 0.0) || !gravity.allFinite()) return;
  const Eigen::Vector3d v = camera.rotation * gravity.normalized();
  const Point2 c(camera.x + 34.0, camera.y + camera.height - kPanelFooterBand / 2.0);
  Font& font = Font::Get(FontWeight::kRegular);
  const double planar = std::hypot(v.x(), v.y());
  if (planar < 0.25) {
    // Gravity (nearly) along the line of sight: dot = towards the viewer, cross = away.
    StrokeCircle(image, c, 9.0, 1.8, kInk);
    if (v.z() > 0) {
      FillCircle(image, c, 2.8, kInk);
    } else {
      StrokeSegment(image, c + Point2(-6, -6), c + Point2(6, 6), 1.8, kInk);
      StrokeSegment(image, c + Point2(-6, 6), c + Point2(6, -6), 1.8, kInk);
    }
  } else {
    const Point2 d = Point2(v.x(), -v.y()) / planar;
    DrawArrow(image, c - d * 14.0, c + d * 14.0, 2.2, 9.0, kInk);
  }
  font.Draw(image, c.x() + 18, c.y() + 5, "g", kLabelSize + 1, kInk);
}

void DrawScaleBar(Image& image, const ViewCamera& camera) {
  const double target_px = std::clamp(camera.width * 0.2, 60.0, 220.0);
  const double length = NiceNumber(target_px / camera.pixels_per_metre, true);
  const double px = length * camera.pixels_per_metre;
  const double x1 = camera.x + camera.width - 20.0;
  const double x0 = x1 - px;
  const double y = camera.y + camera.height - 18.0;
  StrokeSegment(image, {x0, y}, {x1, y}, 2.2, kInk);
  StrokeSegment(image, {x0, y - 6}, {x0, y + 1}, 1.6, kInk);
  StrokeSegment(image, {x1, y - 6}, {x1, y + 1}, 1.6, kInk);
  Font::Get(FontWeight::kRegular).Draw(image, (x0 + x1) / 2, y - 8, FormatLength(length), kLabelSize,
                                       kInk, TextAlign::kCentre);
}

void DrawColourBar(Image& image, int x, int y, int width, int height, const ColourScale& scale) {
  Font& bold = Font::Get(FontWeight::kBold);
  Font& regular = Font::Get(FontWeight::kRegular);
  bold.Draw(image, x, y - 14, scale.label, 15, kInk);
  for (int row = 0; row < height; ++row) {
    const double t = 1.0 - (row + 0.5) / height;  // top = maximum
    const Rgb c = Viridis(t);
    for (int col = 0; col < width; ++col) image.Set(x + col, y + row, c);
  }
  const double x0 = x - 0.5, y0 = y - 0.5, x1 = x + width + 0.5, y1 = y + height + 0.5;
  StrokePolyline(image, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}, 1.0, kMutedInk);
  const Ticks ticks = NiceTicks(scale.min, scale.max, std::max(3, height / 60));
  auto tick = [&](double v, int decimals) {
    const double ty = y + height * (1.0 - scale.Normalised(v));
    StrokeSegment(image, {x + width, ty}, {x + width + 6.0, ty}, 1.3, kInk);
    regular.Draw(image, x + width + 10.0, ty + 5, FormatTick(v, decimals), kLabelSize, kInk);
  };
  // The ends are always labelled (the reader wants the maximum), inner ticks only where they
  // do not collide with an end label.
  const double min_gap = 18.0 / height * (scale.max - scale.min);
  for (double v : ticks.values)
    if (v - scale.min > min_gap && scale.max - v > min_gap) tick(v, ticks.decimals);
  auto exact = [&](double v) {
    return std::abs(v / ticks.step - std::round(v / ticks.step)) < 1e-6 ? ticks.decimals : ticks.decimals + 1;
  };
  tick(scale.min, exact(scale.min));
  tick(scale.max, exact(scale.max));
}

int DrawLegend(Image& image, int x, int y, const std::vector<const Scene*>& scenes,
               bool with_scan_points) {
  bool ghost = false, scan = false, highlight = false, labels = false, solids = false;
  bool kinds[3] = {false, false, false};
  for (const Scene* scene : scenes) {
    ghost = ghost || !scene->ghosts.empty();
    scan = scan || (with_scan_points && scene->scan_points.cols() > 0);
    highlight = highlight || !scene->highlights.empty() || scene->highlighted_support >= 0;
    labels = labels || !scene->labels.empty();
    solids = solids || !scene->solids.empty();
    for (const SceneSupport& s : scene->supports) kinds[static_cast<int>(s.kind)] = true;
  }
  Font& font = Font::Get(FontWeight::kRegular);
  const int step = 24;
  const std::string ghost_name =
      scenes.front()->ghosts.empty() || scenes.front()->ghosts.front().name.empty()
          ? "reference"
          : scenes.front()->ghosts.front().name;
  const std::string highlight_name = scenes.front()->highlight_label;
  // Moved left as far as the longest entry needs, so no entry runs off the picture.
  double widest = 0;
  for (const std::string& text : {ghost_name, highlight_name, std::string("largest deviation"),
                                  std::string("scan points")})
    widest = std::max(widest, font.Width(text, kLabelSize));
  x = std::min(x, static_cast<int>(image.width - 26 - widest - 8));
  auto entry = [&](const std::string& text) {
    font.Draw(image, x + 26, y + 5, text, kLabelSize, kInk);
    y += step;
  };
  if (ghost) {
    StrokeSegment(image, {x + 0.0, y + 0.0}, {x + 18.0, y + 0.0}, 1.8, Rgb{140, 140, 140});
    entry(ghost_name);
  }
  for (int k = 0; k < 3; ++k) {
    if (!kinds[k]) continue;
    const auto kind = static_cast<SupportMarkerKind>(k);
    DrawSupportSymbol(image, {x + 9.0, y + 0.0}, kind, 5.5);
    entry(ToString(kind));
  }
  if (solids) {
    FillRect(image, x + 1, y - 6, x + 17, y + 6, Rgb{115, 120, 133}, 0.35);
    entry("part");
  }
  if (labels) {
    DrawLabelMark(image, {x + 9.0, y + 0.0});
    entry("largest deviation");
  }
  if (scan) {
    for (int i = 0; i < 3; ++i) FillCircle(image, {x + 3.0 + 6 * i, y + 0.0}, 1.3, Rgb{70, 70, 70});
    entry("scan points");
  }
  if (highlight) {
    FillRect(image, x, y - 5, x + 18, y + 5, kHighlight, 0.45);
    entry(highlight_name);
  }
  return y;
}

}  // namespace cablefit::render
