#include "output/relaxed_wide_axes.h"

#include <algorithm>

#include "cablefit/core/base/errors.h"
#include "relax/relax_route.h"

namespace cablefit::addin {
namespace {

bool HasMaterialFrames(const RodSolution& solution) {
  if (solution.frames.empty() || solution.frame_s.size() != static_cast<Eigen::Index>(solution.frames.size()))
    return false;
  for (const Frame& f : solution.frames)
    if (!f.d1.allFinite() || !(f.d1.norm() > 0.5)) return false;
  return true;
}

// d1 at arc length `s` [m]: linear between element midpoints, the end frames' beyond them.
Vec3 MaterialD1(const RodSolution& solution, double s) {
  const Eigen::VectorXd& at = solution.frame_s;  // n [m]
  const Eigen::Index n = at.size();
  if (s <= at[0]) return solution.frames.front().d1;
  if (s >= at[n - 1]) return solution.frames.back().d1;
  const Eigen::Index j = std::upper_bound(at.data(), at.data() + n, s) - at.data() - 1;
  const double w = (s - at[j]) / (at[j + 1] - at[j]);
  return (1 - w) * solution.frames[static_cast<size_t>(j)].d1 +
         w * solution.frames[static_cast<size_t>(j + 1)].d1;
}

}  // namespace

Eigen::Matrix3Xd WrittenWideAxes(const Polyline& written, const RodSolution* solution,
                                 const DrawnCable& drawn) {
  CABLEFIT_REQUIRE(drawn.flat.has_value(), "WrittenWideAxes needs a flat cable");
  const bool relaxed = solution != nullptr && HasMaterialFrames(*solution);
  Eigen::Matrix3Xd axes(3, written.size());  // 3 x n unit
  const RouteProjector drawn_route(drawn.centreline);
  for (Eigen::Index i = 0; i < written.size(); ++i) {
    Vec3 axis;
    if (relaxed) {
      axis = MaterialD1(*solution, written.s[i]);
    } else {
      const double s = drawn_route.NearestArcLength(written.points.col(i));
      axis = NormalAt(drawn.centreline, drawn.flat->wide_axes, s);
    }
    const Vec3 tangent = RouteTangent(written, written.s[i]);
    axes.col(i) = (axis - axis.dot(tangent) * tangent).normalized();
  }
  return axes;
}

}  // namespace cablefit::addin
