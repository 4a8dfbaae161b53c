#include "cablefit/formats/internal/tube_slices.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "point_index.h"
#include "stretch.h"
#include "tube_tracer.h"

namespace cablefit::internal {
namespace {

// A slice of points on the surface itself scatters about its circle by the tessellation's
// sag at most (a few per mille of the radius for a usable mesh).
constexpr double kCleanScale = 0.01;

}  // namespace

namespace {

// One pass of slice fits of radius `radius` about the centres of `first`: the fitted centres in
// `centres` (unchanged where a fit fails), the free radii of the slices whose scatter about the
// fitted circle is below `clean` [m] (all wide-arc slices when `clean` is infinite).
void FitPass(const Eigen::Matrix3Xd& surface, const scan::PointIndex& index,
             const Eigen::Matrix3Xd& first, double radius, double half_width, double clean,
             Eigen::Matrix3Xd* centres, std::vector<char>* moved, std::vector<double>* radii) {
  scan::SliceParams params;
  params.radius = radius;
  params.half_width = half_width;
  params.step = 2 * half_width;
  params.window = 0.5 * radius;          // the first centreline is within a fraction of r
  params.scale_floor = 1e-4 * radius;    // a mesh's vertices lie on its surface, no noise
  params.min_span = 2.0;                 // a closed surface shows the whole circle
  const Eigen::Index n = first.cols();
  *centres = first;
  moved->assign(static_cast<size_t>(n), 0);
  radii->clear();
  for (Eigen::Index i = 0; i < n; ++i) {
    // Axis and curvature from the first centreline about a radius either side.
    Eigen::Index a = i, b = i;
    while (a > 0 && (first.col(i) - first.col(a)).norm() < radius) --a;
    while (b + 1 < n && (first.col(b) - first.col(i)).norm() < radius) ++b;
    if (a == b) continue;
    const Eigen::Vector3d tangent = (first.col(b) - first.col(a)).normalized();
    Eigen::Vector3d curvature = Eigen::Vector3d::Zero();
    if (a < i && i < b) {
      const Eigen::Vector3d t0 = (first.col(i) - first.col(a)).normalized();
      const Eigen::Vector3d t1 = (first.col(b) - first.col(i)).normalized();
      const double ds = 0.5 * (first.col(b) - first.col(a)).norm();
      curvature = (t1 - t0) / ds;
      curvature -= curvature.dot(tangent) * tangent;
    }
    scan::SliceFit fit;
    if (!scan::FitSlice(surface, index, first.col(i), tangent, curvature, params, &fit)) continue;
    centres->col(i) = fit.centre;
    (*moved)[static_cast<size_t>(i)] = 1;
    if (std::isfinite(fit.free_radius) && fit.scale <= clean) radii->push_back(fit.free_radius);
  }
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

TubeSlices FitTubeSlices(const Eigen::Matrix3Xd& surface, double radius, double half_width,
                         Eigen::Matrix3Xd* centres) {
  const Eigen::Index n = centres->cols();
  TubeSlices out;
  out.moved.assign(static_cast<size_t>(n), 0);
  if (n < 3 || surface.cols() == 0 || !(radius > 0)) return out;
  const scan::PointIndex index(surface);
  const Eigen::Matrix3Xd first = *centres;
  // The given radius may be off by the tessellation's sag (cuts through facets lie inside the
  // surface), and fitted with it, points on the surface scatter by that much: a first pass finds
  // the slices' own radius, a second fits with it and keeps the radius of the clean slices only
  // (one reaching into a branch or a cap scatters).
  std::vector<double> radii;
  FitPass(surface, index, first, radius, half_width, std::numeric_limits<double>::infinity(), centres,
          &out.moved, &radii);
  const double own = Median(radii);
  if (own > 0 && std::abs(own - radius) < 0.1 * radius) radius = own;
  FitPass(surface, index, first, radius, half_width, kCleanScale * radius, centres, &out.moved, &radii);
  // As the tracer's stretches: a 5-point quadratic Savitzky-Golay pass takes the slices' scatter
  // out and leaves a curve of constant curvature unshrunk.
  *centres = scan::SmoothCentres(*centres);
  out.radius = Median(radii);
  return out;
}

}  // namespace cablefit::internal
