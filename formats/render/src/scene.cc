#include "cablefit/formats/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

// Deviation extremes over every tube [mm]; {+inf, -inf} when no tube carries deviations.
std::pair<double, double> DeviationRangeMm(const Scene& scene) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const SceneTube& tube : scene.tubes) {
    for (Eigen::Index i = 0; i < tube.deviation.size(); ++i) {
      const double v = tube.deviation[i] * 1e3;
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  return {lo, hi};
}

ColourScale ScaleFromRange(double lo, double hi) {
  ColourScale scale;
  if (!(lo <= hi)) return scale;  // no data: keep the default 0..1 mm
  // Deviations are distances: start at zero so that colour means the same in every picture.
  scale.min = std::min(0.0, lo);
  scale.max = hi;
  if (!(scale.max > scale.min)) scale.max = scale.min + 1.0;
  return scale;
}

}  // namespace

SupportMarkerKind MarkerOf(SupportKind kind) {
  switch (kind) {
    case SupportKind::kClamp:
      return SupportMarkerKind::kClamp;
    case SupportKind::kClip:
      return SupportMarkerKind::kClip;
    case SupportKind::kPin:
      return SupportMarkerKind::kPin;
  }
  return SupportMarkerKind::kPin;
}

std::string ToString(SupportMarkerKind kind) {
  switch (kind) {
    case SupportMarkerKind::kClamp: return "clamp";
    case SupportMarkerKind::kClip: return "clip";
    case SupportMarkerKind::kPin: return "pin";
  }
  return "clamp";
}

ColourScale EffectiveColourScale(const Scene& scene) {
  if (scene.colour_scale) return *scene.colour_scale;
  const auto [lo, hi] = DeviationRangeMm(scene);
  return ScaleFromRange(lo, hi);
}

ColourScale CommonColourScale(const Scene& a, const Scene& b) {
  if (a.colour_scale) return *a.colour_scale;
  if (b.colour_scale) return *b.colour_scale;
  const auto [lo_a, hi_a] = DeviationRangeMm(a);
  const auto [lo_b, hi_b] = DeviationRangeMm(b);
  return ScaleFromRange(std::min(lo_a, lo_b), std::max(hi_a, hi_b));
}

}  // namespace cablefit
