#include "curve_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace cablefit {
namespace {

// Fine segments per coarse chord of the search.
constexpr int kStride = 8;

struct SegmentHit {
  double d2 = std::numeric_limits<double>::infinity();  // squared distance
  int k = -1;                                           // fine segment
  double t = 0.0;                                       // place on it, 0..1
};

double SegmentDistance2(const Vec3& p, const Vec3& a, const Vec3& b, double* t_out) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  if (t_out) *t_out = t;
  return (p - (a + t * ab)).squaredNorm();
}

// The brute-force rule: the first segment (lowest index) of least distance.
void Refine(const Polyline& curve, const Vec3& p, int from, int to, SegmentHit* best) {
  for (int k = from; k < to; ++k) {
    double t = 0.0;
    const double d = SegmentDistance2(p, curve.points.col(k), curve.points.col(k + 1), &t);
    if (d < best->d2 || (d == best->d2 && k < best->k)) *best = {d, k, t};
  }
}

}  // namespace

// Every point scans a window of a few hundred fine segments, for every forward solve of a fit:
// this was a fifth of a diagnosis. The window is searched on chords over kStride fine segments
// first; a chord's distance minus the farthest any of its fine points lies from it bounds the
// distance to every fine segment under it from below (the distance to a segment is convex, so
// its largest value on a fine segment is at an end). Only chords whose bound can beat the best
// fine distance found are refined, so the result is the brute-force search's, exactly.
CurveProjection ProjectOntoCurve(const Polyline& curve, const Eigen::Matrix3Xd& points,
                                 const Eigen::VectorXd& s_guess, double window) {
  const int m = curve.size();
  const int n = static_cast<int>(points.cols());
  CurveProjection out;
  out.offset.resize(3, n);
  out.s.resize(n);
  const int chords = std::max(0, (m - 2) / kStride + 1);
  std::vector<double> slack(static_cast<size_t>(chords), 0.0);
  for (int c = 0; c < chords && m >= 2; ++c) {
    const int a = c * kStride, b = std::min(m - 1, a + kStride);
    double worst = 0.0;
    for (int k = a + 1; k < b; ++k)
      worst = std::max(worst, SegmentDistance2(curve.points.col(k), curve.points.col(a),
                                               curve.points.col(b), nullptr));
    slack[static_cast<size_t>(c)] = std::sqrt(worst);
  }
  const double* sb = curve.s.data();
  std::vector<double> bound(static_cast<size_t>(chords));
  for (int i = 0; i < n; ++i) {
    const Vec3 p = points.col(i);
    const int lo = std::max(0, static_cast<int>(std::lower_bound(sb, sb + m, s_guess[i] - window) - sb) - 1);
    const int hi = std::min(m - 1, static_cast<int>(std::upper_bound(sb, sb + m, s_guess[i] + window) - sb));
    SegmentHit best;
    if (lo < hi) {
      const int c_lo = lo / kStride, c_hi = (hi - 1) / kStride;
      int first = c_lo;
      for (int c = c_lo; c <= c_hi; ++c) {
        const int a = c * kStride, b = std::min(m - 1, a + kStride);
        const double d = std::sqrt(SegmentDistance2(p, curve.points.col(a), curve.points.col(b), nullptr));
        bound[static_cast<size_t>(c)] = d - slack[static_cast<size_t>(c)];
        if (bound[static_cast<size_t>(c)] < bound[static_cast<size_t>(first)]) first = c;
      }
      auto refine = [&](int c) {
        Refine(curve, p, std::max(lo, c * kStride), std::min(hi, (c + 1) * kStride), &best);
      };
      refine(first);
      for (int c = c_lo; c <= c_hi; ++c) {
        const double bd = bound[static_cast<size_t>(c)];
        // A margin far above rounding keeps the search exact in floating point too.
        if (c != first && bd <= std::sqrt(best.d2) * (1.0 + 1e-9) + 1e-15) refine(c);
      }
    }
    if (best.k < 0) {
      out.offset.col(i) = p - curve.points.col(0);
      out.s[i] = 0.0;
      continue;
    }
    const Vec3 a = curve.points.col(best.k), b = curve.points.col(best.k + 1);
    out.offset.col(i) = p - (a + best.t * (b - a));
    out.s[i] = sb[best.k] + best.t * (sb[best.k + 1] - sb[best.k]);
  }
  return out;
}

}  // namespace cablefit
