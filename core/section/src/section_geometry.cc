// Geometric predicates of circular section parts: overlap test and smallest enclosing circle.
#include <algorithm>
#include <cmath>
#include <functional>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/section/section.h"

namespace cablefit {

bool PartsOverlap(const SectionPart& a, const SectionPart& b, double tolerance) {
  // An annulus separates the plane into its hole and its outside, so a connected part that does
  // not cross b's ring lies entirely in b's hole or entirely outside b's outer circle; hence the
  // areas are disjoint exactly when the discs are apart or one disc fits in the other's hole.
  const double d = (a.centre - b.centre).norm();
  if (d >= a.outer_radius + b.outer_radius - tolerance) return false;
  if (d + b.outer_radius <= a.inner_radius + tolerance) return false;
  if (d + a.outer_radius <= b.inner_radius + tolerance) return false;
  return true;
}

bool PartInsideAnnulus(const SectionPart& inner, const SectionPart& outer, double tolerance) {
  const double d = (inner.centre - outer.centre).norm();
  return d + inner.outer_radius <= outer.outer_radius + tolerance &&
         (outer.inner_radius == 0.0 || d - inner.outer_radius >= outer.inner_radius - tolerance);
}

std::vector<std::vector<int>> FillerExclusions(const std::vector<SectionPart>& parts) {
  const int n = static_cast<int>(parts.size());
  std::vector<std::vector<int>> out(n);
  for (int f = 0; f < n; ++f) {
    if (!parts[f].fills_gaps) continue;
    // Valid parts are either inside the filler or apart from it by a whole radius, so a loose
    // tolerance separates the two cases robustly against round-off.
    const double tol = 1e-6 * parts[f].outer_radius;
    auto disc_within = [&](int i, int j, double radius_j) {
      return (parts[i].centre - parts[j].centre).norm() + parts[i].outer_radius <= radius_j + tol;
    };
    std::vector<int> inside;
    for (int i = 0; i < n; ++i) {
      if (i != f && disc_within(i, f, parts[f].outer_radius)) inside.push_back(i);
    }
    // Discs nested in another contained part's disc (a wire in a tube's bore) are excluded
    // with it already.
    for (int i : inside) {
      bool nested = false;
      for (int j : inside) {
        const double cavity = parts[j].fills_gaps ? parts[j].outer_radius : parts[j].inner_radius;
        nested |= j != i && disc_within(i, j, cavity);
      }
      if (!nested) out[f].push_back(i);
    }
  }
  return out;
}

namespace {

// Minimum over t in [lo, hi] of a convex function, by golden-section search.
double MinimiseConvex(const std::function<double(double)>& f, double lo, double hi,
                      double* argmin) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi;
  double c = b - r * (b - a), d = a + r * (b - a);
  double fc = f(c), fd = f(d);
  for (int it = 0; it < 90 && b - a > 1e-15 * (std::abs(a) + std::abs(b) + 1e-300); ++it) {
    if (fc < fd) {
      b = d, d = c, fd = fc, c = b - r * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd, d = a + r * (b - a), fd = f(d);
    }
  }
  *argmin = 0.5 * (a + b);
  return f(*argmin);
}

}  // namespace

void SmallestEnclosingCircle(const std::vector<SectionPart>& parts, Vec2* centre,
                             double* radius) {
  CABLEFIT_REQUIRE(!parts.empty(), "enclosing circle of nothing");
  Vec2 lo = parts[0].centre, hi = parts[0].centre;  // 2 [m] box of the centres
  for (const SectionPart& p : parts) {
    lo = lo.cwiseMin(p.centre);
    hi = hi.cwiseMax(p.centre);
  }
  // The reach max_i(|c_i - x| + R_i) is convex in x, so its minimum over y for fixed x is convex
  // in x too: two nested one-dimensional searches find the optimum (which lies in the box).
  auto reach = [&parts](const Vec2& x) {
    double m = 0.0;
    for (const SectionPart& p : parts) m = std::max(m, (p.centre - x).norm() + p.outer_radius);
    return m;
  };
  auto best_over_y = [&](double x, double* y) {
    return MinimiseConvex([&](double t) { return reach(Vec2(x, t)); }, lo.y(), hi.y(), y);
  };
  double x = 0.0, y = 0.0;
  MinimiseConvex([&](double t) { return best_over_y(t, &y); }, lo.x(), hi.x(), &x);
  best_over_y(x, &y);
  *centre = Vec2(x, y);
  *radius = reach(*centre);
}

}  // namespace cablefit
