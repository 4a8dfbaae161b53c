#include "flat_cores.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace cablefit::internal {
namespace {

// Slack on "inside the section", as a fraction of the thickness: the tessellated outline and
// a core touching the jacket's inner wall are within it.
constexpr double kInsideSlack = 0.05;
// A tube with this fraction of its centres inside a jacket is one of its cores (the rest are
// the stripped tails beyond the jacket).
constexpr double kCoreFraction = 0.5;

bool InsideFlat(const DrawnCable& flat, const Vec3& p) {
  const Polyline& route = flat.centreline;
  const FlatSection& section = *flat.flat;
  double best = std::numeric_limits<double>::infinity();
  bool inside = false;
  for (Eigen::Index i = 0; i + 1 < route.size(); ++i) {
    const Vec3 a = route.points.col(i), ab = route.points.col(i + 1) - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const Vec3 q = a + t * ab;
    const double d = (p - q).norm();
    if (d >= best) continue;
    best = d;
    const Vec3 tangent = ab.normalized();
    Vec3 u = (1 - t) * section.wide_axes.col(i) + t * section.wide_axes.col(i + 1);
    u = (u - u.dot(tangent) * tangent).normalized();
    const Vec3 v = tangent.cross(u);
    const double slack = kInsideSlack * section.thickness;
    inside = std::abs((p - q).dot(u)) <= 0.5 * section.width + slack &&
             std::abs((p - q).dot(v)) <= 0.5 * section.thickness + slack &&
             std::abs((p - q).dot(tangent)) <= slack;
  }
  return inside;
}

}  // namespace

void MergeCoresIntoFlatJackets(const std::vector<DrawnTube>& tubes, HarnessDrawing* drawing,
                               AbsorbedTubes* shared) {
  std::vector<DrawnCable>& cables = drawing->cables;
  AbsorbedTubes own(*drawing);
  AbsorbedTubes& absorbed = shared ? *shared : own;
  for (const DrawnTube& tube : tubes) {
    if (tube.centres.cols() == 0 || tube.inner_radius > 0 || absorbed.Marked(tube)) continue;
    const size_t index = static_cast<size_t>(tube.index);
    if (tube.is_cable ? index >= cables.size() : index >= drawing->solids.size()) continue;
    for (size_t j = 0; j < cables.size(); ++j) {
      const DrawnCable& jacket = cables[j];
      if (absorbed.CableMarked(j) || !jacket.flat || jacket.centreline.size() < 2) continue;
      // A core is thinner than the jacket.
      if (2 * tube.radius > jacket.flat->thickness * (1 + kInsideSlack)) continue;
      Eigen::Index inside = 0;
      for (Eigen::Index k = 0; k < tube.centres.cols(); ++k)
        inside += InsideFlat(jacket, tube.centres.col(k)) ? 1 : 0;
      const double fraction = static_cast<double>(inside) / static_cast<double>(tube.centres.cols());
      if (fraction < kCoreFraction) continue;
      const std::string& name =
          tube.is_cable ? cables[index].name : drawing->solids[index].name;
      char line[160];
      std::snprintf(line, sizeof line,
                    "a %.4g mm core inside flat cable '%s' (%.0f %% of it inside): part of that "
                    "cable, not a separate one",
                    2e3 * tube.radius, jacket.name.c_str(), 100 * fraction);
      const std::string why = "'" + (name.empty() ? std::string("unnamed") : name) + "': " + line;
      absorbed.Mark(tube, why, drawing, static_cast<int>(j));
      break;
    }
  }
  if (!shared) own.RemoveFrom(drawing);
}

}  // namespace cablefit::internal
