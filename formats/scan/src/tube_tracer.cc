// Slice-wise tube tracing. The known-radius circle fit to a partial arc follows the cylinder
// fitting literature (Lukacs, Martin & Marshall, "Faithful least-squares fitting of spheres,
// cylinders, cones and tori", ECCV 1998) reduced to planar slices; seeding by local PCA as in
// Hoppe et al., "Surface reconstruction from unorganized points" (SIGGRAPH 1992).
#include "tube_tracer.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/formats/internal/circle_fit.h"

namespace cablefit::scan {
namespace {

// Orthonormal e1, e2 spanning the plane perpendicular to unit t.
void PlaneBasis(const Eigen::Vector3d& t, Eigen::Vector3d* e1, Eigen::Vector3d* e2) {
  const Eigen::Vector3d helper =
      std::abs(t.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  *e1 = t.cross(helper).normalized();
  *e2 = t.cross(*e1);
}

constexpr double kMaxTurnCos = 0.7;  // a trace never turns by more than ~45 degrees per step

}  // namespace

bool FitSlice(const Eigen::Matrix3Xd& points, const PointIndex& index, const Eigen::Vector3d& guess,
              const Eigen::Vector3d& tangent, const Eigen::Vector3d& curvature,
              const SliceParams& params, SliceFit* fit) {
  const double r = params.radius;
  const double reach = r + params.window;
  std::vector<int> near;
  index.WithinRadius(guess, std::hypot(params.half_width, reach), &near);
  if (static_cast<int>(near.size()) < params.min_support) return false;
  Eigen::Vector3d e1, e2;
  PlaneBasis(tangent, &e1, &e2);
  std::vector<int> ids;
  std::vector<double> axial;
  Eigen::Matrix2Xd q(2, static_cast<Eigen::Index>(near.size()));
  for (int i : near) {
    const Eigen::Vector3d d = points.col(i) - guess;
    const double a = tangent.dot(d);
    if (std::abs(a) > params.half_width) continue;
    // Straighten the bent slab: remove the axis' own offset at this axial position.
    const Eigen::Vector3d p = d - 0.5 * a * a * curvature;
    const Eigen::Vector2d pq(e1.dot(p), e2.dot(p));
    if (pq.norm() > reach) continue;
    q.col(static_cast<Eigen::Index>(ids.size())) = pq;
    ids.push_back(i);
    axial.push_back(a);
  }
  const auto m = static_cast<Eigen::Index>(ids.size());
  if (m < params.min_support) return false;
  q.conservativeResize(2, m);
  const internal::CircleFitResult c =
      internal::FitCircleKnownRadius(q, Eigen::Vector2d::Zero(), r, params.scale_floor);
  if (!c.converged || c.centre.norm() > params.window) return false;
  const double cutoff = params.inlier_cutoff * std::max(c.scale, params.scale_floor);
  fit->inliers.clear();
  fit->central_residuals.clear();
  fit->axial_min = std::numeric_limits<double>::infinity();
  fit->axial_max = -std::numeric_limits<double>::infinity();
  Eigen::Matrix2Xd inl(2, m);
  Eigen::VectorXd weights(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const double res = (q.col(k) - c.centre).norm() - r;
    const auto ks = static_cast<std::size_t>(k);
    if (std::abs(axial[ks]) <= 0.5 * params.step) fit->central_residuals.push_back(res);
    if (std::abs(res) > cutoff) continue;
    inl.col(static_cast<Eigen::Index>(fit->inliers.size())) = q.col(k);
    weights(static_cast<Eigen::Index>(fit->inliers.size())) =
        internal::TukeyWeight(res / (1.5 * cutoff));
    fit->inliers.push_back(ids[ks]);
    fit->axial_min = std::min(fit->axial_min, axial[ks]);
    fit->axial_max = std::max(fit->axial_max, axial[ks]);
  }
  const auto n_in = static_cast<Eigen::Index>(fit->inliers.size());
  if (n_in < params.min_support) return false;
  inl.conservativeResize(2, n_in);
  fit->span = internal::ArcSpan(inl, c.centre);
  if (fit->span < params.min_span) return false;
  fit->centre = guess + e1 * c.centre.x() + e2 * c.centre.y();
  fit->tangent = tangent;
  fit->scale = c.scale;
  fit->free_radius = std::numeric_limits<double>::quiet_NaN();
  // A free radius is only meaningful on a wide arc (its variance explodes below ~150 degrees).
  if (fit->span > 2.6) {
    const internal::CircleFitResult f = internal::FitCircleFree(inl, weights.head(n_in));
    if (f.converged && std::abs(f.radius - r) < 0.5 * r) fit->free_radius = f.radius;
  }
  return true;
}

namespace {

class Tracer {
 public:
  Tracer(const Eigen::Matrix3Xd& points, const PointIndex& index, const std::vector<char>& usable,
         const SliceParams& params)
      : points_(points),
        index_(index),
        usable_(usable),
        params_(params),
        claimed_(static_cast<std::size_t>(points.cols()), 0),
        owner_(static_cast<std::size_t>(points.cols()), -1),
        owner_slice_(static_cast<std::size_t>(points.cols()), 0) {}

  std::vector<Trace> Run(double min_length) {
    std::vector<Trace> traces;
    for (Eigen::Index i = 0; i < points_.cols(); ++i) {
      const auto is = static_cast<std::size_t>(i);
      if (!usable_[is] || claimed_[is]) continue;
      CheckCancelled();  // a batch item's --timeout (every seed fits slices)
      SliceFit seed;
      if (!Seed(static_cast<int>(i), &seed)) {
        ClaimAround(points_.col(i), params_.radius);
        claimed_[is] = 1;
        continue;
      }
      const int id = next_id_++;
      Own(seed, id, 0);
      Trace forward = Follow(seed, 1.0, id);
      Trace backward = Follow(seed, -1.0, id);
      Trace trace(backward.rbegin(), backward.rend());
      trace.push_back(seed);
      trace.insert(trace.end(), forward.begin(), forward.end());
      // Orient every slice tangent along the trace (backward slices were fitted reversed).
      for (std::size_t k = 0; k < trace.size(); ++k) {
        const std::size_t a = k == 0 ? 0 : k - 1;
        const std::size_t b = std::min(k + 1, trace.size() - 1);
        if (a != b && trace[k].tangent.dot(trace[b].centre - trace[a].centre) < 0)
          trace[k].tangent = -trace[k].tangent;
      }
      if (static_cast<double>(trace.size() - 1) * params_.step >= min_length) {
        traces.push_back(std::move(trace));
      }
    }
    return traces;
  }

 private:
  bool Seed(int i, SliceFit* fit) {
    const Eigen::Vector3d p = points_.col(i);
    std::vector<int> near;
    index_.WithinRadius(p, std::max(3.0 * params_.radius, 2.0 * params_.step), &near);
    if (static_cast<int>(near.size()) < 2 * params_.min_support) return false;
    Eigen::Matrix3Xd local(3, static_cast<Eigen::Index>(near.size()));
    for (std::size_t k = 0; k < near.size(); ++k) local.col(static_cast<Eigen::Index>(k)) = points_.col(near[k]);
    const Eigen::Vector3d mean = local.rowwise().mean();
    local.colwise() -= mean;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(local * local.transpose());
    const Eigen::Vector3d axis = eig.eigenvectors().col(2);
    // Guess the centre from a free circle through the seed slab (any arc side is fine for it).
    Eigen::Vector3d e1, e2;
    PlaneBasis(axis, &e1, &e2);
    std::vector<Eigen::Vector2d> slab;
    for (int k : near) {
      const Eigen::Vector3d d = points_.col(k) - p;
      if (std::abs(axis.dot(d)) <= params_.half_width) slab.emplace_back(e1.dot(d), e2.dot(d));
    }
    if (static_cast<int>(slab.size()) < params_.min_support) return false;
    Eigen::Matrix2Xd q(2, static_cast<Eigen::Index>(slab.size()));
    for (std::size_t k = 0; k < slab.size(); ++k) q.col(static_cast<Eigen::Index>(k)) = slab[k];
    const internal::CircleFitResult free =
        internal::FitCircleFree(q, Eigen::VectorXd::Ones(q.cols()));
    if (!free.converged || free.radius > 4.0 * params_.radius) return false;
    const Eigen::Vector3d guess = p + e1 * free.centre.x() + e2 * free.centre.y();
    if (!FitSlice(points_, index_, guess, axis, Eigen::Vector3d::Zero(), params_, fit)) return false;
    // A second pass centred on the fitted axis position removes the guess' bias.
    SliceFit again;
    if (!FitSlice(points_, index_, fit->centre, axis, Eigen::Vector3d::Zero(), params_, &again))
      return false;
    *fit = std::move(again);
    return true;
  }

  Trace Follow(const SliceFit& seed, double direction, int id) {
    Trace out;
    std::vector<Eigen::Vector3d> centres{seed.centre};
    Eigen::Vector3d t = direction * seed.tangent;
    const int max_steps = 1 + static_cast<int>(50.0 / params_.step);  // 50 m of cable: a bug guard
    for (int k = 1; k < max_steps; ++k) {
      if (k % 64 == 0) CheckCancelled();
      const Eigen::Vector3d guess = centres.back() + params_.step * t;
      SliceFit fit;
      if (!FitSlice(points_, index_, guess, t, Eigen::Vector3d::Zero(), params_, &fit)) break;
      const int slice = static_cast<int>(direction) * k;
      if (ForeignFraction(fit, id, slice) > 0.5) break;
      const Eigen::Vector3d chord = fit.centre - centres.back();
      if (chord.norm() < 0.25 * params_.step || chord.normalized().dot(t) < kMaxTurnCos) break;
      centres.push_back(fit.centre);
      const std::size_t n = centres.size();
      Eigen::Vector3d next = centres[n - 1] - centres[n - 2];
      if (n >= 3) next = 1.5 * next - 0.5 * (centres[n - 2] - centres[n - 3]);
      t = next.normalized();
      Own(fit, id, slice);
      out.push_back(std::move(fit));
    }
    return out;
  }

  double ForeignFraction(const SliceFit& fit, int id, int slice) const {
    int foreign = 0;
    for (int i : fit.inliers) {
      const auto is = static_cast<std::size_t>(i);
      if (owner_[is] < 0) continue;
      if (owner_[is] != id || std::abs(owner_slice_[is] - slice) > 3) ++foreign;
    }
    return fit.inliers.empty() ? 1.0 : static_cast<double>(foreign) / static_cast<double>(fit.inliers.size());
  }

  void Own(const SliceFit& fit, int id, int slice) {
    for (int i : fit.inliers) {
      const auto is = static_cast<std::size_t>(i);
      if (owner_[is] < 0) {
        owner_[is] = id;
        owner_slice_[is] = slice;
      }
    }
    // Claim the slab generously (stray points near the surface must not seed new traces).
    ClaimSlab(fit);
  }

  void ClaimSlab(const SliceFit& fit) {
    std::vector<int> near;
    const double reach = 2.0 * params_.radius + params_.window;
    index_.WithinRadius(fit.centre, std::hypot(params_.half_width, reach), &near);
    for (int i : near) {
      const Eigen::Vector3d d = points_.col(i) - fit.centre;
      const double a = fit.tangent.dot(d);
      if (std::abs(a) <= params_.half_width && (d - a * fit.tangent).norm() <= reach)
        claimed_[static_cast<std::size_t>(i)] = 1;
    }
  }

  void ClaimAround(const Eigen::Vector3d& p, double radius) {
    std::vector<int> near;
    index_.WithinRadius(p, radius, &near);
    for (int i : near) claimed_[static_cast<std::size_t>(i)] = 1;
  }

  const Eigen::Matrix3Xd& points_;
  const PointIndex& index_;
  const std::vector<char>& usable_;
  SliceParams params_;
  std::vector<char> claimed_;
  std::vector<int> owner_;
  std::vector<int> owner_slice_;
  int next_id_ = 0;
};

}  // namespace

std::vector<Trace> TraceTube(const Eigen::Matrix3Xd& points, const PointIndex& index,
                             const std::vector<char>& usable, const SliceParams& params,
                             double min_length) {
  Tracer tracer(points, index, usable, params);
  return tracer.Run(min_length);
}

}  // namespace cablefit::scan
