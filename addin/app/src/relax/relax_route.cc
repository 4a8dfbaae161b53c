#include "relax/relax_route.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cablefit/core/base/errors.h"

namespace cablefit::addin {
namespace {

// Index i such that s in [s_i, s_{i+1}] (last segment for s beyond the end).
Eigen::Index Segment(const Polyline& route, double s) {
  const Eigen::Index n = route.s.size();
  const double* begin = route.s.data();
  const Eigen::Index i = std::upper_bound(begin, begin + n, s) - begin - 1;
  return std::clamp<Eigen::Index>(i, 0, n - 2);
}

}  // namespace

Vec3 RoutePoint(const Polyline& route, double s);

Polyline CleanRoute(const Polyline& drawn) {
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < drawn.points.cols(); ++i) {
    if (!drawn.points.col(i).allFinite()) throw InvalidInput("the route has non-finite points");
    // Sub-nanometre steps are duplicates from chained edges, not geometry.
    if (keep.empty() || (drawn.points.col(i) - drawn.points.col(keep.back())).norm() > 1e-9) {
      keep.push_back(i);
    }
  }
  if (keep.size() < 2) throw InvalidInput("the route has fewer than two distinct points");
  Polyline raw;
  raw.points.resize(3, static_cast<Eigen::Index>(keep.size()));
  for (size_t k = 0; k < keep.size(); ++k) {
    raw.points.col(static_cast<Eigen::Index>(k)) = drawn.points.col(keep[k]);
  }
  raw.ParameteriseByChords();
  // Uniform resampling at the median spacing (at most length / 64): a straight line given by
  // its two ends next to a finely sampled arc would otherwise bias the local tangent fits.
  std::vector<double> gaps(static_cast<size_t>(raw.size() - 1));
  for (Eigen::Index i = 0; i + 1 < raw.size(); ++i)
    gaps[static_cast<size_t>(i)] = raw.s[i + 1] - raw.s[i];
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2),
                   gaps.end());
  const double length = raw.s[raw.size() - 1];
  const double spacing = std::min(gaps[gaps.size() / 2], length / 64);
  const Eigen::Index n =
      std::max<Eigen::Index>(2, static_cast<Eigen::Index>(std::ceil(length / spacing - 1e-9)) + 1);
  Polyline route;
  route.s = Eigen::VectorXd::LinSpaced(n, 0.0, length);
  route.points.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) route.points.col(i) = RoutePoint(raw, route.s[i]);
  route.points.col(0) = raw.points.col(0);
  route.points.col(n - 1) = raw.points.col(raw.size() - 1);
  return route;
}

Polyline RoundedRoute(const Polyline& route, double width) {
  CABLEFIT_REQUIRE(route.size() >= 2 && width > 0, "RoundedRoute needs a route and a width > 0");
  const double length = route.s[route.size() - 1];
  const double sigma = 0.5 * width;
  // Eight samples per sigma resolve the kernel; at most 200000 keep a long thin cable cheap.
  const Eigen::Index n = std::clamp<Eigen::Index>(
      static_cast<Eigen::Index>(std::ceil(8 * length / sigma)) + 1, 2, 200000);
  const double h = length / static_cast<double>(n - 1);
  Eigen::Matrix3Xd fine(3, n);  // 3 x n [m]
  for (Eigen::Index i = 0; i < n; ++i) fine.col(i) = RoutePoint(route, h * static_cast<double>(i));
  const Eigen::Index reach = static_cast<Eigen::Index>(std::ceil(3 * sigma / h));
  std::vector<double> weight(static_cast<size_t>(reach + 1));
  for (Eigen::Index k = 0; k <= reach; ++k)
    weight[static_cast<size_t>(k)] = std::exp(-0.5 * std::pow(static_cast<double>(k) * h / sigma, 2));
  // Beyond an end the route continues as its point reflection through that end.
  auto at = [&](Eigen::Index i) -> Vec3 {
    if (i < 0) return 2 * fine.col(0) - fine.col(std::min(-i, n - 1));
    if (i >= n) return 2 * fine.col(n - 1) - fine.col(std::max<Eigen::Index>(2 * (n - 1) - i, 0));
    return fine.col(i);
  };
  Polyline out;
  out.points.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    Vec3 sum = weight[0] * fine.col(i);
    double total = weight[0];
    for (Eigen::Index k = 1; k <= reach; ++k) {
      sum += weight[static_cast<size_t>(k)] * (at(i - k) + at(i + k));
      total += 2 * weight[static_cast<size_t>(k)];
    }
    out.points.col(i) = sum / total;
  }
  out.ParameteriseByChords();
  return out;
}

Vec3 RoutePoint(const Polyline& route, double s) {
  const Eigen::Index i = Segment(route, s);
  const double len = route.s[i + 1] - route.s[i];
  const double w = std::clamp((s - route.s[i]) / len, 0.0, 1.0);
  return (1 - w) * route.points.col(i) + w * route.points.col(i + 1);
}

Vec3 RouteTangent(const Polyline& route, double s) {
  const Eigen::Index n = route.size();
  if (n == 2) return (route.points.col(1) - route.points.col(0)).normalized();
  // Up to 6 samples nearest s (a window shifted inwards at the ends), cubic in (s' - s).
  const Eigen::Index window = std::min<Eigen::Index>(6, n);
  const int degree = static_cast<int>(std::min<Eigen::Index>(3, window - 1));
  const Eigen::Index centre = Segment(route, s);
  const Eigen::Index first = std::clamp<Eigen::Index>(centre - window / 2 + 1, 0, n - window);
  const double scale = route.s[first + window - 1] - route.s[first];  // keeps A well scaled
  // Fixed-size storage (at most 6 x 4): a KBL route has thousands of samples, each fitted once
  // for its transported frame, and heap-allocated matrices were most of that.
  using Design = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 4>;
  using Values = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 6, 3>;
  Design a(window, degree + 1);
  Values b(window, 3);
  for (Eigen::Index k = 0; k < window; ++k) {
    const double t = (route.s[first + k] - s) / scale;
    double tp = 1.0;
    for (int p = 0; p <= degree; ++p, tp *= t) a(k, p) = tp;
    b.row(k) = route.points.col(first + k).transpose();
  }
  // Normal equations: with t scaled to about [-1, 1] the 4 x 4 Gram matrix of 1, t, t^2, t^3 is
  // well conditioned, and its LDL^T costs a tenth of a pivoted QR of the 6 x 4 design (the QR
  // and pow were 8 % of a 1000-segment harness's set-up and measuring).
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4> gram = a.transpose() * a;
  const Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 4, 3> coeff =
      gram.ldlt().solve(a.transpose() * b);  // (degree+1) x 3
  const Vec3 d = coeff.row(1).transpose();
  // Drawn points that coincide around s leave no direction: bad geometry, not a bug.
  if (!(d.norm() > 0))
    throw InvalidInput("the drawn route has no direction at s = " + MessageNumber(s) + " m");
  return d.normalized();
}

Eigen::Matrix3Xd TransportedNormals(const Polyline& route, const Vec3& d1_start) {
  const Eigen::Index n = route.size();
  Eigen::Matrix3Xd tangents(3, n);  // 3 x n unit
  for (Eigen::Index i = 0; i < n; ++i) tangents.col(i) = RouteTangent(route, route.s[i]);
  Eigen::Matrix3Xd normals(3, n);  // 3 x n unit
  Vec3 r = d1_start - d1_start.dot(tangents.col(0)) * tangents.col(0);
  if (r.norm() < 1e-9) r = tangents.col(0).unitOrthogonal();
  normals.col(0) = r.normalized();
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const Vec3 v1 = route.points.col(i + 1) - route.points.col(i);
    const double c1 = v1.squaredNorm();
    const Vec3 r_l = normals.col(i) - (2 / c1) * v1.dot(normals.col(i)) * v1;
    const Vec3 t_l = tangents.col(i) - (2 / c1) * v1.dot(tangents.col(i)) * v1;
    const Vec3 v2 = tangents.col(i + 1) - t_l;
    const double c2 = v2.squaredNorm();
    Vec3 next = c2 > 1e-30 ? Vec3(r_l - (2 / c2) * v2.dot(r_l) * v2) : r_l;
    next -= next.dot(tangents.col(i + 1)) * tangents.col(i + 1);
    normals.col(i + 1) = next.normalized();
  }
  return normals;
}

Vec3 NormalAt(const Polyline& route, const Eigen::Matrix3Xd& normals, double s) {
  const Eigen::Index i = Segment(route, s);
  const double w = std::clamp((s - route.s[i]) / (route.s[i + 1] - route.s[i]), 0.0, 1.0);
  const Vec3 t = RouteTangent(route, s);
  Vec3 d1 = (1 - w) * normals.col(i) + w * normals.col(i + 1);
  d1 -= d1.dot(t) * t;
  if (d1.norm() < 1e-9) d1 = t.unitOrthogonal();
  return d1.normalized();
}

namespace {

// Distance of `p` to segment i of `route` and the arc length of its nearest point there.
double SegmentDistance(const Polyline& route, Eigen::Index i, const Vec3& p, double* s) {
  const Vec3 a = route.points.col(i);
  const Vec3 ab = route.points.col(i + 1) - a;
  const double w = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  *s = route.s[i] + w * (route.s[i + 1] - route.s[i]);
  return (a + w * ab - p).norm();
}

std::vector<Eigen::AlignedBox3d> SegmentBoxes(const Polyline& route) {
  std::vector<Eigen::AlignedBox3d> boxes;
  for (Eigen::Index i = 0; i + 1 < route.size(); ++i) {
    Eigen::AlignedBox3d b(Vec3(route.points.col(i)));
    b.extend(Vec3(route.points.col(i + 1)));
    boxes.push_back(b);
  }
  return boxes;
}

}  // namespace

double NearestArcLength(const Polyline& route, const Vec3& p, double* distance) {
  double best = std::numeric_limits<double>::infinity();
  double best_s = 0.0;
  for (Eigen::Index i = 0; i + 1 < route.size(); ++i) {
    double s = 0.0;
    const double d = SegmentDistance(route, i, p, &s);
    if (d < best) {
      best = d;
      best_s = s;
    }
  }
  if (distance) *distance = best;
  return best_s;
}

RouteProjector::RouteProjector(const Polyline& route) : route_(route), tree_(SegmentBoxes(route), 8) {}

double RouteProjector::NearestArcLength(const Vec3& p, double* distance) const {
  double best_s = 0.0;
  Eigen::Index best_i = -1;
  const double best = tree_.Nearest(
      [&](const Eigen::AlignedBox3d& box) { return box.exteriorDistance(p); },
      [&](int k, double best_d) {
        double s = 0.0;
        const double d = SegmentDistance(route_, k, p, &s);
        // Ties go to the first segment, as the plain scan's strict comparison does.
        if (d < best_d || (d == best_d && k < best_i)) {
          best_i = k;
          best_s = s;
          return d;
        }
        return best_d;
      },
      std::numeric_limits<double>::infinity());
  if (distance) *distance = best;
  return best_s;
}

}  // namespace cablefit::addin
