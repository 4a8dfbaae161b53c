#include "canvas.h"

#include <algorithm>
#include <cmath>

namespace cablefit::render {
namespace {

// Per-pixel coverage over a clipped bounding box; shapes take the max, then blend once.
// The coverage lives in one picture-sized buffer per thread that is all zeros between masks:
// a mask records the span it touches in each row, and Blend visits and clears only those. A
// fresh zeroed box per stroke (a plot's curves and grid lines span the whole plot) cost more in
// clearing and page faults than the drawing. One mask at a time per thread: no drawing function
// holds two.
struct CoverageMask {
  int x0 = 0, y0 = 0, w = 0, h = 0;

  CoverageMask(const Image& image, double xmin, double ymin, double xmax, double ymax)
      : store_(Store()) {
    x0 = std::max(0, static_cast<int>(std::floor(xmin)));
    y0 = std::max(0, static_cast<int>(std::floor(ymin)));
    const int x1 = std::min(image.width, static_cast<int>(std::ceil(xmax)) + 1);
    const int y1 = std::min(image.height, static_cast<int>(std::ceil(ymax)) + 1);
    w = std::max(0, x1 - x0);
    h = std::max(0, y1 - y0);
    if (store_.width != image.width || store_.height != image.height) {
      store_.width = image.width;
      store_.height = image.height;
      store_.c.assign(static_cast<std::size_t>(image.width) * image.height, 0.0f);
      store_.first.assign(static_cast<std::size_t>(image.height), image.width);
      store_.last.assign(static_cast<std::size_t>(image.height), -1);
    }
  }
  float& at(int x, int y) {
    int& first = store_.first[static_cast<std::size_t>(y)];
    int& last = store_.last[static_cast<std::size_t>(y)];
    first = std::min(first, x);
    last = std::max(last, x);
    return store_.c[static_cast<std::size_t>(y) * store_.width + x];
  }

  void Blend(Image& image, Rgb colour, double alpha) {
    for (int y = y0; y < y0 + h; ++y) {
      int& first = store_.first[static_cast<std::size_t>(y)];
      int& last = store_.last[static_cast<std::size_t>(y)];
      float* row = store_.c.data() + static_cast<std::size_t>(y) * store_.width;
      for (int x = first; x <= last; ++x) {
        const float v = row[x];
        if (v > 0.0f) image.Blend(x, y, colour, alpha * std::min(v, 1.0f));
        row[x] = 0.0f;
      }
      first = store_.width;
      last = -1;
    }
  }

 private:
  struct Storage {
    int width = -1, height = -1;
    std::vector<float> c;
    std::vector<int> first, last;  // per row: the touched columns (first > last: none)
  };
  static Storage& Store() {
    static thread_local Storage storage;
    return storage;
  }
  Storage& store_;
};

double DistanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Adds a capsule (segment of half-width `hw` with round ends) to the mask.
void AddCapsule(CoverageMask& mask, const Point2& a, const Point2& b, double hw) {
  const int xa = std::max(mask.x0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - hw - 1)));
  const int xb = std::min(mask.x0 + mask.w - 1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + hw + 1)));
  const int ya = std::max(mask.y0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - hw - 1)));
  const int yb = std::min(mask.y0 + mask.h - 1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + hw + 1)));
  for (int y = ya; y <= yb; ++y)
    for (int x = xa; x <= xb; ++x) {
      const double d = DistanceToSegment(Point2(x + 0.5, y + 0.5), a, b);
      // A pixel-wide linear ramp approximates the area of the pixel inside the stroke.
      const auto cov = static_cast<float>(std::clamp(hw + 0.5 - d, 0.0, 1.0));
      if (cov > 0.0f) mask.at(x, y) = std::max(mask.at(x, y), cov);
    }
}

bool Finite(const Point2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

}  // namespace

void StrokePolyline(Image& image, const std::vector<Point2>& points, double width, Rgb colour,
                    const DashPattern& dash, double alpha) {
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  for (const Point2& p : points) {
    if (!Finite(p)) continue;
    xmin = std::min(xmin, p.x()); xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()); ymax = std::max(ymax, p.y());
  }
  if (xmin > xmax) return;
  const double hw = width / 2;
  CoverageMask mask(image, xmin - hw - 2, ymin - hw - 2, xmax + hw + 2, ymax + hw + 2);
  if (mask.w == 0 || mask.h == 0) return;
  double dash_total = 0;
  for (double d : dash) dash_total += d;
  // Dash state carries over from segment to segment so the pattern flows round corners. It is
  // kept as (index, remaining length) rather than a running phase: a phase grows without bound
  // and its rounding could stall the walk.
  std::size_t k = 0;
  double remaining = dash.empty() ? 0.0 : dash[0];
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point2& a = points[i - 1];
    const Point2& b = points[i];
    if (!Finite(a) || !Finite(b)) continue;
    if (dash.empty() || !(dash_total > 0)) {
      AddCapsule(mask, a, b, hw);
      continue;
    }
    const double len = (b - a).norm();
    double t = 0.0;
    while (len - t > 1e-9) {
      const double step = std::min(remaining, len - t);
      if (k % 2 == 0 && step > 0) AddCapsule(mask, a + (b - a) * (t / len), a + (b - a) * ((t + step) / len), hw);
      t += step;
      remaining -= step;
      if (remaining <= 1e-9) {
        k = (k + 1) % dash.size();
        remaining = std::max(dash[k], 0.0);
      }
    }
  }
  mask.Blend(image, colour, alpha);
}

void StrokeSegment(Image& image, const Point2& a, const Point2& b, double width, Rgb colour,
                   double alpha) {
  StrokePolyline(image, {a, b}, width, colour, {}, alpha);
}

void FillPolygon(Image& image, const std::vector<Point2>& polygon, Rgb colour, double alpha) {
  if (polygon.size() < 3) return;
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  for (const Point2& p : polygon) {
    if (!Finite(p)) return;
    xmin = std::min(xmin, p.x()); xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()); ymax = std::max(ymax, p.y());
  }
  CoverageMask mask(image, xmin, ymin, xmax, ymax);
  constexpr int kSub = 4;  // sub-scanlines per pixel row: vertical anti-aliasing
  std::vector<double> crossings;
  for (int y = mask.y0; y < mask.y0 + mask.h; ++y) {
    for (int s = 0; s < kSub; ++s) {
      const double sy = y + (s + 0.5) / kSub;
      crossings.clear();
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Point2& a = polygon[i];
        const Point2& b = polygon[(i + 1) % polygon.size()];
        if ((a.y() <= sy) != (b.y() <= sy))
          crossings.push_back(a.x() + (sy - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
      }
      std::sort(crossings.begin(), crossings.end());
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        const double xa = std::max(crossings[k], static_cast<double>(mask.x0));
        const double xb = std::min(crossings[k + 1], static_cast<double>(mask.x0 + mask.w));
        for (int x = static_cast<int>(std::floor(xa)); x < xb && x < mask.x0 + mask.w; ++x) {
          // Exact horizontal overlap of the span with the pixel: horizontal anti-aliasing.
          const double overlap = std::min(xb, x + 1.0) - std::max(xa, static_cast<double>(x));
          if (overlap > 0 && x >= mask.x0) mask.at(x, y) += static_cast<float>(overlap / kSub);
        }
      }
    }
  }
  mask.Blend(image, colour, alpha);
}

void FillRect(Image& image, double x0, double y0, double x1, double y1, Rgb colour, double alpha) {
  FillPolygon(image, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, colour, alpha);
}

void FillCircle(Image& image, const Point2& centre, double radius, Rgb colour, double alpha) {
  CoverageMask mask(image, centre.x() - radius - 1, centre.y() - radius - 1, centre.x() + radius + 1,
                    centre.y() + radius + 1);
  for (int y = mask.y0; y < mask.y0 + mask.h; ++y)
    for (int x = mask.x0; x < mask.x0 + mask.w; ++x) {
      const double d = (Point2(x + 0.5, y + 0.5) - centre).norm();
      mask.at(x, y) = static_cast<float>(std::clamp(radius + 0.5 - d, 0.0, 1.0));
    }
  mask.Blend(image, colour, alpha);
}

void StrokeCircle(Image& image, const Point2& centre, double radius, double width, Rgb colour,
                  double alpha) {
  const double hw = width / 2;
  CoverageMask mask(image, centre.x() - radius - hw - 1, centre.y() - radius - hw - 1,
                    centre.x() + radius + hw + 1, centre.y() + radius + hw + 1);
  for (int y = mask.y0; y < mask.y0 + mask.h; ++y)
    for (int x = mask.x0; x < mask.x0 + mask.w; ++x) {
      const double d = std::abs((Point2(x + 0.5, y + 0.5) - centre).norm() - radius);
      mask.at(x, y) = static_cast<float>(std::clamp(hw + 0.5 - d, 0.0, 1.0));
    }
  mask.Blend(image, colour, alpha);
}

void DrawArrow(Image& image, const Point2& tail, const Point2& head, double width,
               double head_size, Rgb colour) {
  const Point2 d = head - tail;
  const double len = d.norm();
  if (len < 1e-9) return;
  const Point2 u = d / len;
  const Point2 n(-u.y(), u.x());
  const Point2 base = head - u * head_size;
  StrokeSegment(image, tail, base + u * 0.5, width, colour);
  FillPolygon(image, {head, base + n * head_size * 0.45, base - n * head_size * 0.45}, colour);
}

}  // namespace cablefit::render
