#include "tolerance/tolerance_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"
#include "cablefit/core/solver/centerline_sampling.h"
#include "cablefit/core/solver/tolerance_corners.h"

namespace cablefit::addin {
namespace {

// Points per branch compared, linearised and kept as a varied shape.
constexpr int kShapeSamples = 201;

double Length(const Polyline& p) { return p.size() > 1 ? p.s[p.size() - 1] - p.s[0] : 0.0; }

Polyline Uniform(const Polyline& nodes, int n) {
  return SampleCenterline(nodes, UniformArcLengths(Length(nodes), n));
}

// Displacements of every branch's samples between two solved set-ups, at the same relative arc
// length, without their component along the nominal cable: a point sliding along the cable
// (a fixing shifted, a longer cable) does not take it anywhere new.
Eigen::Matrix3Xd Displacement(const std::vector<Polyline>& nominal, const std::vector<Polyline>& a,
                              const std::vector<Polyline>& b) {
  Eigen::Matrix3Xd d(3, kShapeSamples * static_cast<Eigen::Index>(nominal.size()));
  for (size_t br = 0; br < nominal.size(); ++br) {
    const Polyline n = Uniform(nominal[br], kShapeSamples);
    const Eigen::Matrix3Xd diff =
        Uniform(a[br], kShapeSamples).points - Uniform(b[br], kShapeSamples).points;
    for (int j = 0; j < kShapeSamples; ++j) {
      const int j0 = std::max(0, j - 1), j1 = std::min(kShapeSamples - 1, j + 1);
      Vec3 t = n.points.col(j1) - n.points.col(j0);
      Vec3 v = diff.col(j);
      if (t.norm() > 0) v -= v.dot(t.normalized()) * t.normalized();
      d.col(static_cast<Eigen::Index>(br) * kShapeSamples + j) = v;
    }
  }
  return d;
}

// Distance of p to segment [a, b] and the segment parameter of the nearest point.
double SegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b, double* t) {
  const Vec3 ab = b - a;
  const double l2 = ab.squaredNorm();
  *t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + *t * ab)).norm();
}

}  // namespace

// Kept whole: corners, sensitivities and interior checks share the one solve-and-walk closure
// and its thread slots, which split functions would have to pass around.
ToleranceSearch SearchToleranceBox(int k, const std::vector<Polyline>& nominal,
                                   const ToleranceSolver& solve, int threads) {
  ToleranceSearch out;
  // One solve from `start` at `from`; false (and why) when it failed or cannot be built.
  auto attempt = [&solve](const Eigen::VectorXd& eps, const Eigen::VectorXd& from,
                          const std::vector<Polyline>& start, ToleranceOutcome* o) {
    o->shapes.clear();
    try {
      o->converged = solve(eps, from, start, &o->shapes, &o->why);
    } catch (const InvalidInput& e) {
      o->converged = false;
      o->buildable = false;
      o->why = e.what();
    } catch (const std::exception& e) {
      o->converged = false;
      o->why = e.what();
    }
    return o->converged;
  };
  auto run = [&](const Eigen::VectorXd& eps) {
    ToleranceOutcome o;
    o.eps = eps;
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(eps.size());
    if (attempt(eps, zero, nominal, &o) || !o.buildable) return o;
    const std::string direct = o.why;
    for (int steps : {2, 4}) {
      std::vector<Polyline> at = nominal;
      Eigen::VectorXd from = zero;
      bool ok = true;
      for (int i = 1; i <= steps && ok; ++i) {
        const Eigen::VectorXd to = eps * (static_cast<double>(i) / steps);
        ok = attempt(to, from, at, &o);
        if (ok) {
          at = o.shapes;
          from = to;
        }
      }
      if (ok) return o;
      if (!o.buildable) return o;
    }
    o.why = direct + " (also in 2 and 4 steps from the nominal shape)";
    o.shapes.clear();
    return o;
  };
  // Every set-up on its own thread; results by index, so the threads change nothing.
  auto run_all = [&](const std::vector<Eigen::VectorXd>& list) {
    std::vector<ToleranceOutcome> done(list.size());
    ParallelFor(static_cast<int>(list.size()), threads,
                [&](int i) { done[static_cast<size_t>(i)] = run(list[static_cast<size_t>(i)]); });
    return done;
  };
  std::vector<Eigen::VectorXd> corners;
  if (k <= kExhaustiveQuantities) {
    corners = AllCorners(k);
  } else {
    out.all_corners = false;
    std::vector<Eigen::VectorXd> probes;
    for (int q = 0; q < k; ++q) {
      probes.push_back(Eigen::VectorXd::Unit(k, q));
      probes.push_back(-Eigen::VectorXd::Unit(k, q));
    }
    const std::vector<ToleranceOutcome> probed = run_all(probes);
    out.sensitivity_solves = static_cast<int>(probes.size());
    std::vector<Eigen::Matrix3Xd> sensitivity;
    for (int q = 0; q < k; ++q) {
      const ToleranceOutcome& plus = probed[static_cast<size_t>(2 * q)];
      const ToleranceOutcome& minus = probed[static_cast<size_t>(2 * q + 1)];
      // Central difference; one-sided where one side failed; nothing known where both did
      // (its corners are then chosen by the other quantities alone).
      if (plus.converged && minus.converged)
        sensitivity.push_back(0.5 * Displacement(nominal, plus.shapes, minus.shapes));
      else if (plus.converged)
        sensitivity.push_back(Displacement(nominal, plus.shapes, nominal));
      else if (minus.converged)
        sensitivity.push_back(Displacement(nominal, nominal, minus.shapes));
      else
        sensitivity.push_back(Eigen::Matrix3Xd::Zero(
            3, kShapeSamples * static_cast<Eigen::Index>(nominal.size())));
    }
    corners = WorstCorners(sensitivity, kChosenCorners);
  }
  // Fixed seed: every run and thread count solves the same interior set-ups.
  std::mt19937 rng(25);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::VectorXd> inside;
  for (int i = 0; i < kInteriorChecks && k > 0; ++i) {
    Eigen::VectorXd eps(k);
    for (int q = 0; q < k; ++q) eps[q] = u(rng);
    inside.push_back(eps);
  }
  std::vector<Eigen::VectorXd> all = corners;
  all.insert(all.end(), inside.begin(), inside.end());
  std::vector<ToleranceOutcome> solved = run_all(all);
  out.corners.assign(solved.begin(), solved.begin() + static_cast<std::ptrdiff_t>(corners.size()));
  out.interior.assign(solved.begin() + static_cast<std::ptrdiff_t>(corners.size()), solved.end());
  return out;
}

CurveExcursion MeasureExcursion(const Polyline& nominal, const Polyline& varied) {
  CurveExcursion ex;
  if (nominal.size() < 2 || varied.size() < 1) return ex;
  // The nominal curve about every millimetre (its node polyline's chords would read a bend
  // as up to h^2 / 8R too close), in chunks with bounding spheres so a point only looks at the
  // chunks that can hold its nearest point.
  const double length = Length(nominal);
  const int n = std::clamp(static_cast<int>(std::ceil(length / 1e-3)) + 1, kShapeSamples, 4001);
  const Polyline dense = Uniform(nominal, n);
  constexpr int kChunk = 16;
  struct Chunk { int first, last; Vec3 centre; double radius; };
  std::vector<Chunk> chunks;
  for (int a = 0; a + 1 < n; a += kChunk) {
    Chunk c{a, std::min(n - 1, a + kChunk), Vec3::Zero(), 0.0};
    const auto block = dense.points.middleCols(c.first, c.last - c.first + 1);
    c.centre = block.rowwise().mean();
    c.radius = (block.colwise() - c.centre).colwise().norm().maxCoeff();
    chunks.push_back(c);
  }
  for (Eigen::Index j = 0; j < varied.points.cols(); ++j) {
    const Vec3 p = varied.points.col(j);
    double best = std::numeric_limits<double>::infinity(), best_s = 0.0;
    for (const Chunk& c : chunks) {
      if ((p - c.centre).norm() - c.radius >= best) continue;
      for (int i = c.first; i < c.last; ++i) {
        double t = 0.0;
        const double d = SegmentDistance(p, dense.points.col(i), dense.points.col(i + 1), &t);
        if (d < best) {
          best = d;
          best_s = dense.s[i] + t * (dense.s[i + 1] - dense.s[i]);
        }
      }
    }
    if (best > ex.distance || j == 0) {
      ex.distance = best;
      ex.s = best_s;
      ex.point = p;
    }
  }
  return ex;
}

void MeasureCases(const ToleranceSearch& search, int branch, const Polyline& nominal,
                  double yardstick,
                  const std::function<ToleranceCase(const Eigen::VectorXd&)>& describe,
                  CableTolerance* ct) {
  auto measure = [&](const ToleranceOutcome& o) {
    ToleranceCase c = describe(o.eps);
    c.converged = o.converged;
    c.why = o.why;
    c.buildable = o.buildable;
    if (o.converged) {
      c.centreline = Uniform(o.shapes[static_cast<size_t>(branch)], kShapeSamples);
      const CurveExcursion ex = MeasureExcursion(nominal, c.centreline);
      c.excursion = ex.distance;
      c.s = ex.s;
      c.point = ex.point;
    }
    return c;
  };
  for (const ToleranceOutcome& o : search.corners) ct->corners.push_back(measure(o));
  for (size_t k = 0; k < ct->corners.size(); ++k)
    if (ct->corners[k].converged &&
        (ct->worst_corner < 0 ||
         ct->corners[k].excursion > ct->corners[static_cast<size_t>(ct->worst_corner)].excursion))
      ct->worst_corner = static_cast<int>(k);
  const double worst =
      ct->worst_corner >= 0 ? ct->corners[static_cast<size_t>(ct->worst_corner)].excursion : 0.0;
  for (const ToleranceOutcome& o : search.interior) {
    ct->interior.push_back(measure(o));
    const ToleranceCase& c = ct->interior.back();
    if (c.converged && c.excursion > worst + yardstick) ct->interior_within = false;
  }
  ct->all_corners = search.all_corners;
  ct->sensitivity_solves = search.sensitivity_solves;
}

}  // namespace cablefit::addin
