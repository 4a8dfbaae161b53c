#include "cablefit/core/base/cubic_spline_fit.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>

namespace cablefit {
namespace {

constexpr int kDegree = 3;

// The span of u in the full knot vector (4 zeros, interior, 4 ones): index s with
// knots[s] <= u < knots[s + 1], the last span for u = 1.
int FindSpan(const std::vector<double>& knots, int poles, double u) {
  if (u >= knots[poles]) return poles - 1;
  const auto it = std::upper_bound(knots.begin() + kDegree, knots.begin() + poles + 1, u);
  return static_cast<int>(it - knots.begin()) - 1;
}

// The p + 1 non-zero basis functions of degree p at u in span `span` (The NURBS Book, A2.2).
template <int P>
std::array<double, P + 1> Basis(const std::vector<double>& knots, int span, double u) {
  std::array<double, P + 1> n{};
  n[0] = 1.0;
  std::array<double, P + 1> left{}, right{};
  for (int j = 1; j <= P; ++j) {
    left[j] = u - knots[span + 1 - j];
    right[j] = knots[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double t = n[r] / (right[r + 1] + left[j - r]);
      n[r] = saved + right[r + 1] * t;
      saved = left[j - r] * t;
    }
    n[j] = saved;
  }
  return n;
}

std::vector<double> FullKnots(const std::vector<double>& interior) {
  std::vector<double> knots(kDegree + 1, 0.0);
  knots.insert(knots.end(), interior.begin(), interior.end());
  knots.insert(knots.end(), kDegree + 1, 1.0);
  return knots;
}

// The poles of the least-squares fit of `q` at parameters `u` on `knots` (m poles), the end
// poles held on the end points: minimises sum_k |M_k^(1/2) (C(u_k) - q_k)|^2, M_k the metric of
// point k (`metrics`, 3 x 3 each; the identity when empty). False when the normal equations are
// singular.
bool SolvePoles(const Eigen::Matrix3Xd& q, const std::vector<double>& u,
                const std::vector<double>& knots, int m, const std::vector<Eigen::Matrix3d>& metrics,
                Eigen::Matrix3Xd* poles) {
  const int n = static_cast<int>(q.cols());
  poles->resize(3, m);
  poles->col(0) = q.col(0);
  poles->col(m - 1) = q.col(n - 1);
  // Normal equations for the interior poles 1 .. m-2: banded (3 x 3 blocks, 7 block diagonals),
  // so sparse; a long cable's thousands of poles would make a dense matrix hundreds of MB.
  const int unknowns = m - 2;
  if (unknowns == 0) return true;
  std::vector<Eigen::Triplet<double>> ntn;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(3 * unknowns);
  for (int k = 1; k + 1 < n; ++k) {
    const int span = FindSpan(knots, m, u[k]);
    const std::array<double, 4> b = Basis<3>(knots, span, u[k]);
    const Eigen::Matrix3d metric = metrics.empty() ? Eigen::Matrix3d::Identity() : metrics[k];
    // The point less what the held end poles give.
    Eigen::Vector3d r = q.col(k);
    for (int a = 0; a < 4; ++a) {
      const int pole = span - kDegree + a;
      if (pole == 0) r -= b[a] * q.col(0);
      if (pole == m - 1) r -= b[a] * q.col(n - 1);
    }
    const Eigen::Vector3d mr = metric * r;
    for (int a = 0; a < 4; ++a) {
      const int i = span - kDegree + a - 1;
      if (i < 0 || i >= unknowns) continue;
      rhs.segment<3>(3 * i) += b[a] * mr;
      for (int c = 0; c < 4; ++c) {
        const int j = span - kDegree + c - 1;
        if (j < 0 || j >= unknowns) continue;
        for (int x = 0; x < 3; ++x)
          for (int y = 0; y < 3; ++y)
            if (metric(x, y) != 0.0) ntn.emplace_back(3 * i + x, 3 * j + y, b[a] * b[c] * metric(x, y));
      }
    }
  }
  Eigen::SparseMatrix<double> a(3 * unknowns, 3 * unknowns);
  a.setFromTriplets(ntn.begin(), ntn.end());
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
      llt(a);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::VectorXd inner = llt.solve(rhs);
  if (!inner.allFinite()) return false;
  for (int i = 0; i < unknowns; ++i) poles->col(1 + i) = inner.segment<3>(3 * i);
  return true;
}

// The curve's point and first derivative at u.
void PointAndTangent(const Eigen::Matrix3Xd& poles, const std::vector<double>& knots, double u,
                     Eigen::Vector3d* point, Eigen::Vector3d* tangent) {
  const int m = static_cast<int>(poles.cols());
  const int span = FindSpan(knots, m, u);
  const std::array<double, 4> b = Basis<3>(knots, span, u);
  point->setZero();
  for (int a = 0; a < 4; ++a) *point += b[a] * poles.col(span - kDegree + a);
  // The derivative is the quadratic spline with poles 3 (P_i+1 - P_i) / (t_i+4 - t_i+1) on
  // the same knots, pole i weighted by N_i+1,2 (The NURBS Book, eqs. 3.7-3.8).
  const std::array<double, 3> d = Basis<2>(knots, span, u);
  tangent->setZero();
  for (int a = 0; a < 3; ++a) {
    const int i = span - kDegree + a;
    *tangent += d[a] * 3.0 * (poles.col(i + 1) - poles.col(i)) / (knots[i + 4] - knots[i + 1]);
  }
}

// After the first fit (chord-length parameters), rounds of tangent distance minimisation:
// each point's parameter moves to the foot of its perpendicular on the curve (Gauss-Newton
// steps), and the poles are fitted again weighting only the error across the curve there in
// full, along it by kAlongWeight (Wang, Pottmann & Liu, "Fitting B-spline curves to point
// clouds by curvature-based squared distance minimization", ACM TOG 25(2), 2006, the TDM step;
// the small weight along keeps the system definite). Chord-length parameters alone make the
// fit chase the parametrisation: a gravity-bent arch a single cubic holds to 0.6 um took 7
// poles, and its end tangent tilted by 3e-4 rad.
constexpr int kDistanceRounds = 5;
constexpr double kAlongWeight = 0.01;
// Gauss-Newton steps of each projection of a point on the curve.
constexpr int kProjectionSteps = 3;
constexpr double kRoundsTarget = 0.25;
// A round that brings the error down by less than this factor ends the rounds.
constexpr double kStallRatio = 0.8;

// Moves u[k] (interior points) to the foot of q_k's perpendicular on the curve; the unit
// tangent there in `tangents` and the distance in `distance`.
void Project(const Eigen::Matrix3Xd& q, const Eigen::Matrix3Xd& poles,
             const std::vector<double>& knots, std::vector<double>* u,
             std::vector<Eigen::Vector3d>* tangents, double* distance) {
  const int n = static_cast<int>(q.cols());
  tangents->assign(static_cast<size_t>(n), Eigen::Vector3d::Zero());
  *distance = 0.0;
  for (int k = 0; k < n; ++k) {
    Eigen::Vector3d c, t;
    double& uk = (*u)[k];
    PointAndTangent(poles, knots, uk, &c, &t);
    for (int step = 0; step < kProjectionSteps && k > 0 && k + 1 < n; ++step) {
      const double tt = t.squaredNorm();
      if (!(tt > 0)) break;
      uk = std::clamp(uk + (q.col(k) - c).dot(t) / tt, 0.0, 1.0);
      PointAndTangent(poles, knots, uk, &c, &t);
    }
    if (t.squaredNorm() > 0) (*tangents)[k] = t.normalized();
    *distance = std::max(*distance, (c - q.col(k)).norm());
  }
}

// Least squares with `m` poles; the largest distance of a point from its curve point in `error`.
std::optional<CubicSpline> FitWithPoles(const Eigen::Matrix3Xd& q, std::vector<double> u, int m,
                                        double tolerance, double* error) {
  const int n = static_cast<int>(q.cols());
  CubicSpline s;
  // Interior knots by eq. 9.69: every span between them holds at least one parameter. As many
  // poles as points is interpolation, which needs the averaged knots of eq. 9.8 instead: 9.69's
  // leave a span whose parameters pin no pole (Schoenberg-Whitney fails), and the curve through
  // every point looped metres away between two of them.
  const double d = static_cast<double>(n) / (m - kDegree);
  for (int j = 1; j < m - kDegree; ++j) {
    if (m == n) {
      s.interior_knots.push_back((u[j] + u[j + 1] + u[j + 2]) / 3.0);
      continue;
    }
    const int i = static_cast<int>(j * d);
    const double alpha = j * d - i;
    s.interior_knots.push_back((1.0 - alpha) * u[i - 1] + alpha * u[i]);
  }
  for (size_t k = 1; k < s.interior_knots.size(); ++k)
    if (!(s.interior_knots[k] > s.interior_knots[k - 1])) return std::nullopt;
  const std::vector<double> knots = FullKnots(s.interior_knots);
  if (!SolvePoles(q, u, knots, m, {}, &s.poles)) return std::nullopt;
  std::vector<Eigen::Vector3d> tangents;
  std::vector<Eigen::Matrix3d> metrics(static_cast<size_t>(n));
  Project(q, s.poles, knots, &u, &tangents, error);
  // Rounds only while they still pay (each costs a projection of every point), and on to a
  // quarter of the tolerance: just within it, the end tangents (a reader's clamp directions)
  // were still 2e-4 rad off on a shallow arc.
  for (int round = 0; round < kDistanceRounds && *error > kRoundsTarget * tolerance; ++round) {
    for (int k = 0; k < n; ++k) {
      const Eigen::Matrix3d along = tangents[k] * tangents[k].transpose();
      metrics[k] = Eigen::Matrix3d::Identity() - (1.0 - kAlongWeight) * along;
    }
    Eigen::Matrix3Xd poles;
    if (!SolvePoles(q, u, knots, m, metrics, &poles)) break;
    std::vector<double> moved = u;
    std::vector<Eigen::Vector3d> moved_tangents;
    double distance = 0.0;
    Project(q, poles, knots, &moved, &moved_tangents, &distance);
    u = std::move(moved);
    tangents = std::move(moved_tangents);
    const bool stalled = !(distance < kStallRatio * *error);
    if (distance < *error) {
      s.poles = std::move(poles);
      *error = distance;
    }
    if (stalled) break;
  }
  // Every point can lie on the curve while a pole that few points pin swings the curve far
  // away between two of them (a relaxed harness segment's spine once looped 3 m out between
  // points 22 mm apart, and no sweep could follow it). Between neighbours the curve may bulge
  // by at most a half circle over their chord; more counts as the fit's error.
  std::vector<Eigen::Vector3d> final_tangents;
  double at_points = 0.0;
  Project(q, s.poles, knots, &u, &final_tangents, &at_points);
  for (int k = 0; k + 1 < n; ++k) {
    Eigen::Vector3d c, t;
    PointAndTangent(s.poles, knots, 0.5 * (u[k] + u[k + 1]), &c, &t);
    const double bulge = (c - 0.5 * (q.col(k) + q.col(k + 1))).norm() -
                         0.5 * (q.col(k + 1) - q.col(k)).norm();
    *error = std::max(*error, bulge);
  }
  return s;
}

}  // namespace

Eigen::Vector3d CubicSpline::At(double u) const {
  const int m = static_cast<int>(poles.cols());
  const std::vector<double> knots = FullKnots(interior_knots);
  u = std::clamp(u, 0.0, 1.0);
  const int span = FindSpan(knots, m, u);
  const std::array<double, 4> b = Basis<3>(knots, span, u);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) c += b[a] * poles.col(span - kDegree + a);
  return c;
}

std::optional<CubicSpline> FitCubicSpline(const Eigen::Matrix3Xd& points, double tolerance,
                                          int max_poles) {
  const int n = static_cast<int>(points.cols());
  if (n < 4 || !points.allFinite() || !(tolerance > 0)) return std::nullopt;
  std::vector<double> u(static_cast<size_t>(n), 0.0);
  for (int k = 1; k < n; ++k) u[k] = u[k - 1] + (points.col(k) - points.col(k - 1)).norm();
  if (!(u.back() > 0)) return std::nullopt;
  for (int k = 1; k < n; ++k) {
    if (!(u[k] > u[k - 1])) return std::nullopt;
    u[k] /= u.back();
  }
  u.back() = 1.0;
  const int most = std::min(n, max_poles);
  if (most < 4) return std::nullopt;
  // Doubling, then bisection between the last count that failed and the first that held.
  std::optional<CubicSpline> best;
  int failed = 3, held = -1;
  for (int m = 4;; m = std::min(most, 2 * m)) {
    double error = 0.0;
    std::optional<CubicSpline> fit = FitWithPoles(points, u, m, tolerance, &error);
    if (fit && error <= tolerance) {
      best = std::move(fit);
      held = m;
      break;
    }
    failed = m;
    if (m == most) return std::nullopt;
  }
  while (held - failed > 1) {
    const int m = (held + failed) / 2;
    double error = 0.0;
    std::optional<CubicSpline> fit = FitWithPoles(points, u, m, tolerance, &error);
    if (fit && error <= tolerance) {
      best = std::move(fit);
      held = m;
    } else {
      failed = m;
    }
  }
  return best;
}

}  // namespace cablefit
