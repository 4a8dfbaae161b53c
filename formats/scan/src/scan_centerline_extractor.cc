// Scan -> centreline pipeline: statistical outlier removal (Rusu et al., "Towards 3D point cloud
// based object maps for household environments", RAS 56(11), 2008: mean k-NN distance test),
// slice tracing (tube_tracer), refinement (stretch), chaining with bridges (stretch_chain).
#include "cablefit/formats/scan_centerline_extractor.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/internal/circle_fit.h"
#include "point_index.h"
#include "stretch.h"
#include "stretch_chain.h"
#include "tube_tracer.h"

namespace cablefit {
namespace {

constexpr int kMinPoints = 20;

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

std::string Mm(double metres) {
  std::ostringstream o;
  o.precision(3);
  o << metres * 1e3 << " mm";
  return o.str();
}

// Marks points whose mean distance to their k nearest neighbours is anomalously large; returns
// the median nearest-neighbour distance (the scan's point spacing) [m].
double MarkSparseOutliers(const Eigen::Matrix3Xd& points, const scan::PointIndex& index,
                          const ScanCenterlineOptions& options, std::vector<char>* usable) {
  const Eigen::Index n = points.cols();
  std::vector<double> mean_distance(static_cast<std::size_t>(n));
  std::vector<double> nearest(static_cast<std::size_t>(n));
  std::vector<int> ids;
  std::vector<double> dist;
  const int k = std::min<int>(options.outlier_neighbours + 1, static_cast<int>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    if (i % 4096 == 0) CheckCancelled();  // a batch item's --timeout covers the scan too
    index.Nearest(points.col(i), k, &ids, &dist);  // includes the point itself at distance 0
    const double sum = std::accumulate(dist.begin(), dist.end(), 0.0);
    mean_distance[static_cast<std::size_t>(i)] = sum / std::max<double>(1.0, static_cast<double>(dist.size()) - 1.0);
    nearest[static_cast<std::size_t>(i)] = dist.size() > 1 ? dist[1] : 0.0;
  }
  const double med = Median(mean_distance);
  std::vector<double> dev(mean_distance.size());
  for (std::size_t i = 0; i < dev.size(); ++i) dev[i] = std::abs(mean_distance[i] - med);
  const double spread = std::max(1.4826 * Median(dev), 1e-3 * med);
  const double limit = med + options.outlier_threshold * spread;
  usable->assign(static_cast<std::size_t>(n), 1);
  for (std::size_t i = 0; i < mean_distance.size(); ++i) (*usable)[i] = mean_distance[i] <= limit;
  return Median(nearest);
}

}  // namespace

ScanGuide ScanGuide::FromRodSpec(const RodSpec& spec) {
  if (spec.supports.size() < 2) throw InvalidInput("scan guide needs two supports (clamps) at the cable ends");
  auto [first, last] = std::minmax_element(spec.supports.begin(), spec.supports.end(),
                                           [](const SupportSpec& a, const SupportSpec& b) { return a.s < b.s; });
  if (first->tangent.norm() == 0.0 || last->tangent.norm() == 0.0)
    throw InvalidInput("scan guide: clamp tangent is zero");
  ScanGuide g;
  g.start_position = first->position;
  g.start_tangent = first->tangent.normalized();
  g.end_position = last->position;
  g.end_tangent = last->tangent.normalized();
  g.length = spec.length > 0.0 ? spec.length : last->s - first->s;
  return g;
}

bool ScanCenterlineOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(diameter > 0.0) || !std::isfinite(diameter)) return fail("diameter must be positive");
  if (!(step >= 0.0) || !std::isfinite(step)) return fail("step must be >= 0 (0 = automatic)");
  if (outlier_neighbours < 3) return fail("outlier_neighbours must be >= 3");
  if (!(outlier_threshold > 0.0)) return fail("outlier_threshold must be positive");
  if (!(residual_cutoff > 1.0)) return fail("residual_cutoff must be > 1");
  if (!(min_stretch_diameters >= 0.0)) return fail("min_stretch_diameters must be >= 0");
  return true;
}

ScanCenterline ExtractScanCenterline(const PointCloud& scan, const ScanCenterlineOptions& options,
                                     const std::optional<ScanGuide>& guide) {
  std::string why;
  if (!options.IsValid(&why)) throw InvalidInput("scan centreline options: " + why);
  const Eigen::Matrix3Xd& points = scan.points;
  if (points.cols() == 0) throw InvalidInput("scan is empty");
  if (points.cols() < kMinPoints) {
    throw InvalidInput("scan has " + std::to_string(points.cols()) + " points, at least " +
                       std::to_string(kMinPoints) + " are needed");
  }
  if (!points.allFinite()) throw InvalidInput("scan has non-finite coordinates");

  const scan::PointIndex index(points);
  std::vector<char> usable;
  const double spacing = MarkSparseOutliers(points, index, options, &usable);

  const double radius = 0.5 * options.diameter;
  scan::SliceParams params;
  params.radius = radius;
  // Slices about a radius apart: thin enough that bends stay nearly straight within a slab,
  // thick enough for tens of points per slab at typical hand-held densities.
  params.step = options.step > 0.0 ? options.step : std::max(std::min(radius, 2.5e-3), 2.0 * spacing);
  params.half_width = params.step;
  params.window = 0.6 * radius;
  params.scale_floor = 1e-6;
  params.inlier_cutoff = options.residual_cutoff;
  params.min_support = 8;
  params.min_span = 1.0;  // ~57 degrees: with the radius known, enough to place the centre
  const double min_length = options.min_stretch_diameters * options.diameter;

  std::vector<scan::Trace> traces = scan::TraceTube(points, index, usable, params, min_length);
  if (traces.empty()) {
    throw InvalidInput("no cable surface of diameter " + Mm(options.diameter) + " found among " +
                       std::to_string(points.cols()) + " scan points");
  }
  // Noise from the tracing pass sets the robust scale of the refinement.
  std::vector<double> residuals;
  for (const scan::Trace& t : traces)
    for (const scan::SliceFit& f : t) residuals.insert(residuals.end(), f.central_residuals.begin(), f.central_residuals.end());
  std::vector<double> abs_res(residuals.size());
  std::transform(residuals.begin(), residuals.end(), abs_res.begin(), [](double r) { return std::abs(r); });
  params.scale_floor = std::max(1.4826 * Median(abs_res), 1e-6);

  std::vector<scan::Stretch> stretches;
  for (const scan::Trace& t : traces) {
    scan::Stretch s = scan::RefineTrace(t, points, index, params);
    if (s.size() >= 2 && s.Length() >= min_length) stretches.push_back(std::move(s));
  }
  if (stretches.empty()) {
    throw InvalidInput("no cable surface of diameter " + Mm(options.diameter) + " found among " +
                       std::to_string(points.cols()) + " scan points");
  }

  ScanCenterline out;
  out.point_count = static_cast<int>(points.cols());
  scan::ChainStretches(stretches, guide, options.diameter, &out);

  abs_res.clear();
  std::vector<char> used(static_cast<std::size_t>(points.cols()), 0);
  for (const scan::Stretch& s : stretches) {
    for (double r : s.residuals) abs_res.push_back(std::abs(r));
    for (int i : s.inliers) used[static_cast<std::size_t>(i)] = 1;
  }
  // Each slab fit spends two degrees of freedom on its centre: undo that shrinkage of the
  // residuals (support = points per fit).
  const double support = out.support.size() > 0 ? out.support.cast<double>().mean() : 10.0;
  out.noise_sigma = 1.4826 * Median(abs_res) * std::sqrt(support / std::max(support - 2.0, 1.0));
  out.outlier_count = static_cast<int>(std::count(used.begin(), used.end(), 0));

  std::vector<double> radii;
  for (Eigen::Index i = 0; i < out.radius.size(); ++i)
    if (std::isfinite(out.radius(i))) radii.push_back(out.radius(i));
  if (radii.size() >= 5) {
    const double r = Median(radii);
    if (std::abs(r - radius) > 0.1 * radius) {
      out.warnings.push_back("fitted cable diameter " + Mm(2.0 * r) + " differs from the nominal " +
                             Mm(options.diameter));
    }
  }
  if (out.noise_sigma > 0.2 * radius) out.warnings.push_back("scan noise " + Mm(out.noise_sigma) + " is large for the cable radius");
  if (out.outlier_count > 0.05 * out.point_count) {
    out.warnings.push_back(std::to_string(out.outlier_count) + " of " + std::to_string(out.point_count) +
                           " scan points fit no cable section");
  }
  return out;
}

}  // namespace cablefit
