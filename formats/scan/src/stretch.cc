// Trace refinement and smoothing; method notes in stretch.h.
#include "stretch.h"

#include <algorithm>
#include <cmath>

namespace cablefit::scan {
namespace {

// Unit tangents by central differences (one-sided at the ends).
Eigen::Matrix3Xd Tangents(const Eigen::Matrix3Xd& c, const Eigen::Matrix3Xd& fallback) {
  const Eigen::Index n = c.cols();
  Eigen::Matrix3Xd t(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index a = std::max<Eigen::Index>(k - 1, 0);
    const Eigen::Index b = std::min<Eigen::Index>(k + 1, n - 1);
    const Eigen::Vector3d d = c.col(b) - c.col(a);
    t.col(k) = d.norm() > 0.0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d(fallback.col(k));
  }
  return t;
}

// Curvature vector kappa * N [1/m] from a wide stencil (+-2 samples) to keep noise low.
Eigen::Vector3d CurvatureAt(const Eigen::Matrix3Xd& c, const Eigen::Vector3d& t, Eigen::Index k) {
  const Eigen::Index n = c.cols();
  if (n < 5 || k < 2 || k > n - 3) return Eigen::Vector3d::Zero();
  const double h = 0.25 * (c.col(k + 2) - c.col(k - 2)).norm();
  if (h <= 0.0) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d second = (c.col(k + 2) - 2.0 * c.col(k) + c.col(k - 2)) / (4.0 * h * h);
  return second - t.dot(second) * t;
}

}  // namespace

double Stretch::Length() const {
  double l = 0.0;
  for (Eigen::Index k = 1; k < centres.cols(); ++k) l += (centres.col(k) - centres.col(k - 1)).norm();
  return l;
}

Eigen::Matrix3Xd SmoothCentres(const Eigen::Matrix3Xd& c) {
  const Eigen::Index n = c.cols();
  Eigen::Matrix3Xd out = c;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (k >= 2 && k <= n - 3) {
      out.col(k) = (-3.0 * c.col(k - 2) + 12.0 * c.col(k - 1) + 17.0 * c.col(k) +
                    12.0 * c.col(k + 1) - 3.0 * c.col(k + 2)) / 35.0;
    } else if (k >= 1 && k <= n - 2) {
      // 3-point quadratic SG is the identity; a light [1 2 1] would shrink bends, so keep it.
      out.col(k) = c.col(k);
    }
  }
  return out;
}

Stretch RefineTrace(const Trace& trace, const Eigen::Matrix3Xd& points, const PointIndex& index,
                    const SliceParams& params) {
  const auto n = static_cast<Eigen::Index>(trace.size());
  Eigen::Matrix3Xd raw(3, n), raw_t(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    raw.col(k) = trace[static_cast<std::size_t>(k)].centre;
    raw_t.col(k) = trace[static_cast<std::size_t>(k)].tangent;
  }
  const Eigen::Matrix3Xd smooth = SmoothCentres(raw);
  const Eigen::Matrix3Xd tangents = Tangents(smooth, raw_t);
  std::vector<SliceFit> fits;
  fits.reserve(trace.size());
  for (Eigen::Index k = 0; k < n; ++k) {
    SliceFit fit;
    const Eigen::Vector3d t = tangents.col(k);
    if (FitSlice(points, index, smooth.col(k), t, CurvatureAt(smooth, t, k), params, &fit))
      fits.push_back(std::move(fit));
  }
  // Slabs hanging over the end of the seen surface hold few points and place their centre
  // poorly: trim them, but keep their points for the seen extent.
  std::size_t first = 0, last = fits.size();
  if (!fits.empty()) {
    std::vector<std::size_t> counts;
    for (const SliceFit& f : fits) counts.push_back(f.inliers.size());
    std::nth_element(counts.begin(), counts.begin() + static_cast<std::ptrdiff_t>(counts.size() / 2), counts.end());
    const double enough = 0.5 * static_cast<double>(counts[counts.size() / 2]);
    while (last - first > 2 && static_cast<double>(fits[first].inliers.size()) < enough) ++first;
    while (last - first > 2 && static_cast<double>(fits[last - 1].inliers.size()) < enough) --last;
  }
  Stretch s;
  const auto m = static_cast<Eigen::Index>(last - first);
  Eigen::Matrix3Xd centres(3, m), fit_t(3, m);
  s.radius.resize(m);
  s.support.resize(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const SliceFit& f = fits[first + static_cast<std::size_t>(k)];
    centres.col(k) = f.centre;
    fit_t.col(k) = f.tangent;
    s.radius(k) = f.free_radius;
    s.support(k) = static_cast<int>(f.inliers.size());
  }
  for (const SliceFit& f : fits) {
    s.inliers.insert(s.inliers.end(), f.inliers.begin(), f.inliers.end());
    s.residuals.insert(s.residuals.end(), f.central_residuals.begin(), f.central_residuals.end());
  }
  s.centres = SmoothCentres(centres);
  s.tangents = m > 1 ? Tangents(s.centres, fit_t) : fit_t;
  if (m > 0) {
    // Seen extent beyond the end centres: the farthest inlier of the end (and trimmed) slabs.
    const Eigen::Vector3d c0 = s.centres.col(0), t0 = s.tangents.col(0);
    const Eigen::Vector3d c1 = s.centres.col(m - 1), t1 = s.tangents.col(m - 1);
    s.head_extent = -fits[first].axial_min;
    s.tail_extent = fits[last - 1].axial_max;
    for (std::size_t k = 0; k <= first; ++k)
      for (int i : fits[k].inliers) s.head_extent = std::max(s.head_extent, -t0.dot(points.col(i) - c0));
    for (std::size_t k = last - 1; k < fits.size(); ++k)
      for (int i : fits[k].inliers) s.tail_extent = std::max(s.tail_extent, t1.dot(points.col(i) - c1));
  }
  return s;
}

}  // namespace cablefit::scan
