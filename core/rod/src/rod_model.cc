#include "cablefit/core/rod/rod_model.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "cablefit/core/base/distinct_numbers.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/internal/model_compiler.h"

namespace cablefit {
namespace {

std::string Num(double v) { return MessageNumber(v); }

bool Finite(const Vec3& v) { return v.allFinite(); }

void RequirePositive(double v, const char* what) {
  if (!std::isfinite(v)) throw InvalidInput(std::string(what) + " is not a finite number");
  if (v <= 0) throw InvalidInput(std::string(what) + " must be positive (got " + Num(v) + ")");
}

}  // namespace

Mat3 MaterialStiffness(const MaterialSpec& m) {
  const double root = std::sqrt(m.bending_ratio);
  const double bmax = m.bending_stiffness * root, bmin = m.bending_stiffness / root;
  const double c = std::cos(m.principal_angle), s = std::sin(m.principal_angle);
  Eigen::Matrix2d rot;
  rot << c, -s, s, c;
  Mat3 k = Mat3::Zero();
  k.topLeftCorner<2, 2>() = rot * Eigen::Vector2d(bmax, bmin).asDiagonal() * rot.transpose();
  k(2, 2) = m.torsional_stiffness;
  return k;
}

RodSupport MakeRodSupport(const SupportSpec& sp, double s, int node) {
  RodSupport rs;
  rs.kind = sp.kind;
  rs.s = s;
  rs.node = node;
  rs.position = sp.position;
  rs.sliding = sp.sliding;
  if (sp.kind == SupportKind::kClamp)
    rs.frame = Frame::FromTangentNormal(sp.tangent, sp.normal);
  else if (sp.kind == SupportKind::kClip)
    rs.frame = Frame::FromTangentNormal(sp.tangent, sp.tangent.unitOrthogonal());
  return rs;
}

RodItem MakeSupportItem(const SupportSpec& sp, int support, double s, double cable_stiffness) {
  RodItem it;
  it.is_element = false;
  it.support = support;
  it.s = s;
  if (sp.kind == SupportKind::kClip) {
    it.masked[0] = it.masked[1] = true;
  } else if (sp.compliance) {
    // Rigid directions (zero compliance) would need infinite stiffness: give them a stiffness
    // far above the cable's own so they act rigid without ruining conditioning.
    Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (*sp.compliance + sp.compliance->transpose()));
    Eigen::Vector3d k;
    for (int d = 0; d < 3; ++d) {
      const double c = eig.eigenvalues()[d];
      k[d] = c > 1e-12 / cable_stiffness ? 1.0 / c : 1e8 * cable_stiffness;
    }
    it.has_spring = true;
    it.spring_stiffness = eig.eigenvectors() * k.asDiagonal() * eig.eigenvectors().transpose();
  } else {
    it.masked[0] = it.masked[1] = it.masked[2] = true;
  }
  return it;
}

void ValidateRodSpec(const RodSpec& spec, bool require_support) {
  RequirePositive(spec.length, "cable length");
  const MaterialSpec& m = spec.material;
  RequirePositive(m.bending_stiffness, "bending stiffness");
  RequirePositive(m.torsional_stiffness, "torsional stiffness");
  if (!std::isfinite(m.linear_density) || m.linear_density < 0)
    throw InvalidInput("linear density must be a finite number >= 0");
  if (!std::isfinite(m.diameter) || m.diameter < 0)
    throw InvalidInput("diameter must be a finite number >= 0");
  if (!std::isfinite(m.bending_ratio) || m.bending_ratio < 1.0)
    throw InvalidInput("bending ratio B_max/B_min must be a finite number >= 1");
  if (!std::isfinite(m.principal_angle)) throw InvalidInput("principal angle is not finite");
  if (!std::isfinite(m.axial_stiffness) || m.axial_stiffness < 0)
    throw InvalidInput("axial stiffness EA must be a finite number >= 0");
  if (!Finite(spec.gravity)) throw InvalidInput("gravity is not finite");
  // Magnitudes no cable set-up has: refused here, since the solver's scales (the Hessian's size,
  // the force scale) overflow on them and no answer could be trusted. Each bound is orders
  // beyond the physical range (a 10 km cable, 1000 g, a 100 t/m bundle, a steel bar's EI).
  if (spec.length > 1e4) throw InvalidInput("cable length " + Num(spec.length) + " m is beyond 10 km");
  if (spec.gravity.norm() > 1e4)
    throw InvalidInput("gravity " + Num(spec.gravity.norm()) + " m/s^2 is beyond 1000 g");
  if (m.linear_density > 1e5)
    throw InvalidInput("linear density " + Num(m.linear_density) + " kg/m is beyond 100 t/m");
  if (m.bending_stiffness > 1e9 || m.torsional_stiffness > 1e9)
    throw InvalidInput("bending or torsional stiffness beyond 1e9 N m^2");
  if (require_support && spec.supports.empty()) throw InvalidInput("the cable has no support");
  const double tol = 1e-9 * spec.length;
  for (size_t i = 0; i < spec.supports.size(); ++i) {
    const SupportSpec& sp = spec.supports[i];
    const std::string name = std::string(ToString(sp.kind)) + " " + std::to_string(i);
    if (!std::isfinite(sp.s) || sp.s < -tol || sp.s > spec.length + tol)
      throw InvalidInput(name + " at s=" + Num(sp.s) + " lies outside the cable [0, " +
                         Num(spec.length) + "]");
    if (!Finite(sp.position)) throw InvalidInput(name + ": position is not finite");
    if (sp.kind != SupportKind::kPin) {
      try {
        (void)Frame::FromTangentNormal(sp.tangent,
                                       sp.kind == SupportKind::kClamp ? sp.normal
                                                                      : sp.tangent.unitOrthogonal());
      } catch (const InvalidInput& e) {
        throw InvalidInput(name + ": " + e.what());
      }
    }
    if (sp.sliding && sp.kind == SupportKind::kPin)
      throw InvalidInput(name + ": a pin cannot slide (it has no axis)");
    if (sp.compliance) {
      if (!sp.compliance->allFinite()) throw InvalidInput(name + ": compliance is not finite");
      if (sp.kind != SupportKind::kClamp)
        throw InvalidInput(name + ": only a clamp can be compliant");
      Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (*sp.compliance + sp.compliance->transpose()));
      if (eig.eigenvalues().minCoeff() < 0)
        throw InvalidInput(name + ": compliance must be positive semi-definite");
    }
    if (i > 0) {
      const SupportSpec& prev = spec.supports[i - 1];
      if (sp.s <= prev.s + tol)
        throw InvalidInput("supports " + std::to_string(i - 1) + " and " + std::to_string(i) +
                           " are not in increasing arc length (s=" + Num(prev.s) + ", " +
                           Num(sp.s) + ")");
      const double dist = (sp.position - prev.position).norm();
      const double arc = sp.s - prev.s;
      const bool slides = sp.sliding || prev.sliding;
      // An extensible cable (EA > 0) a little shorter than the span is stretched across it:
      // solved, and its tension says how taut.
      const double stretch = spec.material.axial_stiffness > 0 ? kMaxAxialStrain : 1e-9;
      if (!slides && dist > arc * (1 + stretch)) {
        const auto [dist_text, arc_text] = DistinctNumbers(dist, arc);
        throw InvalidInput("supports " + std::to_string(i - 1) + " and " + std::to_string(i) +
                           " are " + dist_text + " m apart but only " + arc_text +
                           " m of cable lies between them");
      }
    }
  }
  for (const NaturalCurvatureSpec& nc : spec.natural_curvature) {
    if (!std::isfinite(nc.s_start) || !std::isfinite(nc.s_end) || !Finite(nc.kappa) ||
        !std::isfinite(nc.ramp))
      throw InvalidInput("natural curvature has a non-finite value");
    if (nc.s_start < -tol || nc.s_end > spec.length + tol || nc.s_end < nc.s_start)
      throw InvalidInput("natural curvature interval [" + Num(nc.s_start) + ", " + Num(nc.s_end) +
                         "] is not inside the cable");
    if (nc.ramp < 0) throw InvalidInput("natural curvature ramp must be >= 0");
  }
  for (const SleeveSpec& sl : spec.sleeves) {
    if (!std::isfinite(sl.s_begin) || !std::isfinite(sl.s_end) || sl.s_begin < -tol ||
        sl.s_end > spec.length + tol || !(sl.s_end > sl.s_begin))
      throw InvalidInput("sleeve [" + Num(sl.s_begin) + ", " + Num(sl.s_end) +
                         "] is not an interval inside the cable [0, " + Num(spec.length) + "]");
    for (const double v : {sl.bending_stiffness, sl.torsional_stiffness, sl.linear_density})
      if (!std::isfinite(v) || v < 0)
        throw InvalidInput("sleeve [" + Num(sl.s_begin) + ", " + Num(sl.s_end) +
                           "]: stiffness and mass per length must be finite numbers >= 0");
    if (sl.bending_stiffness > 1e9 || sl.torsional_stiffness > 1e9)
      throw InvalidInput("sleeve bending or torsional stiffness beyond 1e9 N m^2");
    if (sl.linear_density > 1e5)
      throw InvalidInput("sleeve mass per length " + Num(sl.linear_density) +
                         " kg/m is beyond 100 t/m");
  }
  for (const PointLoadSpec& pl : spec.point_loads) {
    if (!std::isfinite(pl.s) || pl.s < -tol || pl.s > spec.length + tol)
      throw InvalidInput("point load at s=" + Num(pl.s) + " lies outside the cable");
    if (!Finite(pl.force)) throw InvalidInput("point load is not finite");
  }
}

std::vector<double> SpanBreakpoints(const RodSpec& spec) {
  std::vector<double> b = {0.0, spec.length};
  for (const auto& sp : spec.supports) b.push_back(std::clamp(sp.s, 0.0, spec.length));
  for (const auto& pl : spec.point_loads) b.push_back(std::clamp(pl.s, 0.0, spec.length));
  // A sleeve's ends are element boundaries: each element is then all sleeve or none of it.
  for (const SleeveSpec& sl : spec.sleeves) {
    b.push_back(std::clamp(sl.s_begin, 0.0, spec.length));
    b.push_back(std::clamp(sl.s_end, 0.0, spec.length));
  }
  std::sort(b.begin(), b.end());
  const double tol = 1e-9 * spec.length;
  std::vector<double> out;
  for (double v : b)
    if (out.empty() || v > out.back() + tol) out.push_back(v);
  out.back() = spec.length;
  return out;
}

RodModel CompileRodModel(const RodSpec& spec, const Discretisation& disc) {
  ValidateRodSpec(spec);
  internal::ModelBranch branch;
  branch.spec = &spec;
  branch.node_s = internal::BranchNodeArcLengths(spec, disc);
  return internal::CompileModelLayout({branch}, {}, spec.gravity, spec.name).model;
}

}  // namespace cablefit
