#include "cablefit/core/rod/initial_shape.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/support_targets.h"

namespace cablefit {
namespace {

Vec3 Hermite(const Vec3& p0, const Vec3& m0, const Vec3& p1, const Vec3& m1, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 +
         (t3 - t2) * m1;
}

// Root of an increasing f on [lo, hi] with f(lo) <= 0 <= f(hi), to a residual of 1e-13 * scale:
// regula falsi with the Illinois halving (superlinear, never leaves the bracket). Each f here
// is a curve length summed over hundreds of points, and the start of every simulate computes
// several: 60 bisection steps cost a visible share of a millisecond solve.
template <typename F>
double MonotoneRoot(const F& f, double lo, double hi, double scale) {
  double flo = f(lo), fhi = f(hi);
  if (flo >= 0) return lo;
  if (fhi <= 0) return hi;
  int side = 0;
  for (int it = 0; it < 100 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
    const double x = hi - fhi * (hi - lo) / (fhi - flo);
    const double fx = f(x);
    if (std::abs(fx) <= 1e-13 * scale) return x;
    if (fx < 0) {
      lo = x;
      flo = fx;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = x;
      fhi = fx;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

// Rotation taking unit vector a to unit vector b with the least angle.
Eigen::Matrix3d MinimalRotation(const Vec3& a, const Vec3& b) {
  return Eigen::Quaterniond::FromTwoVectors(a, b).toRotationMatrix();
}

}  // namespace

Vec3 PointAt(const Polyline& c, double s) {
  const int n = c.size();
  if (s <= c.s[0]) {
    const Vec3 d = (c.points.col(1) - c.points.col(0)).normalized();
    return c.points.col(0) + (s - c.s[0]) * d;
  }
  if (s >= c.s[n - 1]) {
    const Vec3 d = (c.points.col(n - 1) - c.points.col(n - 2)).normalized();
    return c.points.col(n - 1) + (s - c.s[n - 1]) * d;
  }
  const int i = static_cast<int>(std::upper_bound(c.s.data(), c.s.data() + n, s) - c.s.data()) - 1;
  const double span = c.s[i + 1] - c.s[i];
  const double w = span > 0 ? (s - c.s[i]) / span : 0.0;
  return (1 - w) * c.points.col(i) + w * c.points.col(i + 1);
}

Vec3 SmoothPointAt(const Polyline& c, double s) {
  const int n = c.size();
  if (n < 3 || s <= c.s[0] || s >= c.s[n - 1]) return PointAt(c, s);
  const int i = static_cast<int>(std::upper_bound(c.s.data(), c.s.data() + n, s) - c.s.data()) - 1;
  const double h = c.s[i + 1] - c.s[i];
  if (!(h > 0)) return PointAt(c, s);
  // Tangent (d point / ds) at sample k: central difference, one-sided at the ends.
  auto tangent = [&](int k) -> Vec3 {
    const int a = std::max(k - 1, 0), b = std::min(k + 1, n - 1);
    const double ds = c.s[b] - c.s[a];
    return ds > 0 ? Vec3((c.points.col(b) - c.points.col(a)) / ds) : Vec3::Zero();
  };
  const double t = (s - c.s[i]) / h, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * c.points.col(i) + (t3 - 2 * t2 + t) * h * tangent(i) +
         (-2 * t3 + 3 * t2) * c.points.col(i + 1) + (t3 - t2) * h * tangent(i + 1);
}

Polyline ReparameteriseToLength(const Polyline& curve, double length) {
  if (curve.size() < 2) throw InvalidInput("a shape needs at least 2 points");
  if (!curve.points.allFinite()) throw InvalidInput("the shape has non-finite coordinates");
  Polyline out = curve;
  if (out.s.size() != out.size() || !out.s.allFinite()) out.ParameteriseByChords(0.0);
  const double s0 = out.s[0], s1 = out.s[out.size() - 1];
  if (!(s1 > s0)) throw InvalidInput("the shape has zero length");
  for (int i = 1; i < out.size(); ++i)
    if (out.s[i] < out.s[i - 1]) throw InvalidInput("the shape's arc length decreases");
  out.s = (out.s.array() - s0) * (length / (s1 - s0));
  return out;
}

Polyline DefaultInitialCurve(const RodSpec& spec, int samples_per_span) {
  const auto& sup = spec.supports;
  const int ns = static_cast<int>(sup.size());
  const Vec3 down = spec.gravity.norm() > 0 ? Vec3(spec.gravity.normalized()) : Vec3(-Vec3::UnitZ());
  // Tangent at each support: its own, or Catmull-Rom from the neighbours, or hanging down.
  std::vector<Vec3> tan(ns);
  for (int k = 0; k < ns; ++k) {
    if (sup[k].kind != SupportKind::kPin) {
      tan[k] = sup[k].tangent.normalized();
    } else if (ns > 1) {
      const Vec3 a = sup[std::max(0, k - 1)].position, b = sup[std::min(ns - 1, k + 1)].position;
      tan[k] = (b - a).norm() > 0 ? Vec3((b - a).normalized()) : down;
    } else {
      tan[k] = down;
    }
  }
  std::vector<Vec3> pts;
  std::vector<double> ss;
  auto push = [&](const Vec3& p, double s) {
    if (!ss.empty() && s <= ss.back()) return;
    pts.push_back(p);
    ss.push_back(s);
  };
  // Straight free end before the first support.
  if (sup[0].s > 0) {
    for (int i = 0; i < samples_per_span; ++i) {
      const double s = sup[0].s * i / samples_per_span;
      push(sup[0].position - (sup[0].s - s) * tan[0], s);
    }
  }
  for (int k = 0; k + 1 < ns; ++k) {
    const Vec3 p0 = sup[k].position, p1 = sup[k + 1].position;
    const double arc = sup[k + 1].s - sup[k].s;
    const double chord = (p1 - p0).norm();
    const int fine = 8 * samples_per_span;
    // Bulge direction: gravity across the chord (a drawn cable sags), else any perpendicular.
    const Vec3 axis = chord > 0 ? Vec3((p1 - p0) / chord) : tan[k];
    Vec3 bulge = down - down.dot(axis) * axis;
    if (bulge.norm() < 1e-6) bulge = axis.unitOrthogonal();
    bulge.normalize();
    auto curve = [&](double a, double beta, double t) {
      const double b = 16 * t * t * (1 - t) * (1 - t);  // zero value and slope at both ends
      return Vec3(Hermite(p0, a * tan[k], p1, a * tan[k + 1], t) + beta * b * bulge);
    };
    auto length = [&](double a, double beta) {
      double len = 0.0;
      Vec3 prev = p0;
      for (int i = 1; i <= fine; ++i) {
        const Vec3 p = curve(a, beta, static_cast<double>(i) / fine);
        len += (p - prev).norm();
        prev = p;
      }
      return len;
    };
    // Tangent scale a = chord is the natural one; a shorter span shrinks a, a longer one bulges.
    // (Lengthening by a alone can fold the curve back onto a line when the tangents lie along
    // the chord.)
    double a = chord, beta = 0.0;
    if (chord >= arc * (1 - 1e-12)) {
      a = chord;
    } else if (length(chord, 0.0) >= arc) {
      a = MonotoneRoot([&](double x) { return length(x, 0.0) - arc; }, 0.0, chord, arc);
    } else {
      double hi = std::max(arc, 1e-9);
      int guard = 0;
      while (length(chord, hi) < arc && guard++ < 60) hi *= 2;
      beta = MonotoneRoot([&](double x) { return length(chord, x) - arc; }, 0.0, hi, arc);
    }
    // Sample by the curve's own arc length so s is right within the span.
    std::vector<Vec3> dense(fine + 1);
    std::vector<double> cum(fine + 1, 0.0);
    for (int i = 0; i <= fine; ++i) {
      dense[i] = curve(a, beta, static_cast<double>(i) / fine);
      if (i > 0) cum[i] = cum[i - 1] + (dense[i] - dense[i - 1]).norm();
    }
    const double scale = cum[fine] > 0 ? arc / cum[fine] : 0.0;
    for (int i = 0; i <= fine; i += 8) push(dense[i], sup[k].s + cum[i] * scale);
  }
  // Straight free end after the last support.
  const SupportSpec& last = sup[ns - 1];
  push(last.position, last.s);
  if (last.s < spec.length) {
    for (int i = 1; i <= samples_per_span; ++i) {
      const double s = last.s + (spec.length - last.s) * i / samples_per_span;
      push(last.position + (s - last.s) * tan[ns - 1], s);
    }
  }
  Polyline out;
  out.points.resize(3, static_cast<int>(pts.size()));
  out.s.resize(static_cast<int>(pts.size()));
  for (size_t i = 0; i < pts.size(); ++i) {
    out.points.col(i) = pts[i];
    out.s[i] = ss[i];
  }
  return out;
}

RodState MakeInitialState(const RodModel& model, const Polyline& curve) {
  const int ne = model.num_elements;
  const int ni = static_cast<int>(model.items.size());
  // Element tangents from the curve's chords.
  std::vector<Vec3> d3(ne);
  for (int j = 0; j < ne; ++j) {
    Vec3 d = PointAt(curve, model.node_s[j + 1]) - PointAt(curve, model.node_s[j]);
    if (d.norm() < 1e-15) d = j > 0 ? d3[j - 1] : Vec3::UnitX();
    d3[j] = d.normalized();
  }
  // Frames by parallel transport along the chain of items, restarting at every clamp and
  // spreading the twist mismatch found at the next clamp linearly over the elements before it.
  std::vector<Eigen::Matrix3d> frame(ni);
  auto item_tangent = [&](int i) -> Vec3 {
    const RodItem& it = model.items[i];
    if (it.is_element) return d3[it.element];
    return model.supports[it.support].frame.d3;
  };
  int seg_start = 0;  // first item of the current transport segment
  for (int i = 0; i < ni; ++i) {
    const RodItem& it = model.items[i];
    const bool is_clamp = !it.is_element && model.supports[it.support].kind == SupportKind::kClamp;
    const Vec3 t = item_tangent(i);
    if (i == 0) {
      if (!it.is_element) {
        frame[i] = model.supports[it.support].frame.Matrix();
      } else {
        const Vec3 d1 = t.unitOrthogonal();
        frame[i].col(0) = d1;
        frame[i].col(1) = t.cross(d1);
        frame[i].col(2) = t;
      }
      continue;
    }
    frame[i] = MinimalRotation(frame[i - 1].col(2), t) * frame[i - 1];
    if (is_clamp) {
      const Eigen::Matrix3d target = model.supports[it.support].frame.Matrix();
      // Twist mismatch about the tangent, spread over the items since seg_start.
      const Vec3 d1 = frame[i].col(0), d1t = target.col(0);
      const double mismatch = std::atan2(t.dot(d1.cross(d1t)), d1.dot(d1t));
      const double s0 = model.items[seg_start].s, s1 = it.s;
      for (int k = seg_start + 1; k <= i; ++k) {
        const double w = s1 > s0 ? (model.items[k].s - s0) / (s1 - s0) : 1.0;
        frame[k] = Eigen::AngleAxisd(w * mismatch, frame[k].col(2)).toRotationMatrix() * frame[k];
      }
      seg_start = i;
    }
  }
  RodState st;
  st.q.resize(ni);
  for (int i = 0; i < ni; ++i) st.q[i] = internal::quat::FromMatrix(frame[i]);
  internal::AlignQuaternionSigns(model, &st);
  st.lambda.setZero(model.num_constraints);
  // Continuation start: the supports where this shape has them.
  st.support_position.resize(model.supports.size());
  st.support_q.resize(model.supports.size());
  st.support_position[model.anchor_support] = PointAt(curve, model.supports[model.anchor_support].s);
  const Eigen::Matrix3Xd r = st.NodePositions(model);
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const RodSupport& sp = model.supports[k];
    st.support_position[k] = r.col(sp.node);
    if (sp.item >= 0) {
      st.support_q[k] = st.q[sp.item];
    } else {
      st.support_q[k] = internal::SupportTargetQuaternion(sp);
    }
  }
  return st;
}

RodState TransferState(const RodModel& from_model, const RodState& from, const RodModel& to_model) {
  RodState st;
  const int ni = static_cast<int>(to_model.items.size());
  st.q.resize(ni);
  // Element frames at the source's element midpoints, interpolated by slerp.
  std::vector<double> mids;
  std::vector<Eigen::Quaterniond> qs;
  for (int j = 0; j < from_model.num_elements; ++j) {
    const Eigen::Vector4d& q = from.q[from_model.element_item[j]];
    mids.push_back(from_model.items[from_model.element_item[j]].s);
    qs.emplace_back(q[0], q[1], q[2], q[3]);
  }
  for (int i = 0; i < ni; ++i) {
    const RodItem& it = to_model.items[i];
    if (!it.is_element) {
      // Same support, same frame (a support new to this model starts at its target).
      const bool known = it.support < static_cast<int>(from_model.supports.size()) &&
                         from_model.supports[it.support].item >= 0;
      st.q[i] = known ? from.q[from_model.supports[it.support].item]
                      : internal::SupportTargetQuaternion(to_model.supports[it.support]);
      continue;
    }
    const double s = it.s;
    const auto up = std::upper_bound(mids.begin(), mids.end(), s);
    const int k = std::clamp(static_cast<int>(up - mids.begin()) - 1, 0, static_cast<int>(mids.size()) - 1);
    Eigen::Quaterniond q = qs[k];
    if (k + 1 < static_cast<int>(mids.size()) && s > mids[k]) {
      const double w = (s - mids[k]) / (mids[k + 1] - mids[k]);
      q = qs[k].slerp(w, qs[k + 1]);
    }
    st.q[i] = Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
  }
  internal::AlignQuaternionSigns(to_model, &st);
  st.lambda = from.lambda.size() == to_model.num_constraints
                  ? from.lambda
                  : Eigen::VectorXd(Eigen::VectorXd::Zero(to_model.num_constraints));
  if (from.support_position.size() == to_model.supports.size()) {
    st.support_position = from.support_position;
    st.support_q = from.support_q;
  } else {
    for (const RodSupport& sp : to_model.supports) {
      st.support_position.push_back(sp.position);
      st.support_q.push_back(internal::SupportTargetQuaternion(sp));
    }
  }
  st.load_factor = from.load_factor;
  st.natural_factor = from.natural_factor;
  return st;
}

}  // namespace cablefit
