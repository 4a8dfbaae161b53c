#include "cablefit/core/rod/rod_model.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "cablefit/core/base/distinct_numbers.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/internal/natural_curvature.h"
#include "cablefit/core/rod/internal/rod_topology.h"

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
      if (!slides && dist > arc * (1 + 1e-9)) {
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
  RodModel model;
  model.spec = spec;
  const double L = spec.length;
  const std::vector<double> bp = SpanBreakpoints(spec);
  const int spans = static_cast<int>(bp.size()) - 1;
  if (!disc.elements_per_span.empty() && static_cast<int>(disc.elements_per_span.size()) != spans)
    throw InvalidInput("discretisation has " + std::to_string(disc.elements_per_span.size()) +
                       " span counts for " + std::to_string(spans) + " spans");
  if (disc.elements_per_span.empty() && !(disc.element_length > 0))
    throw InvalidInput("element length must be positive");

  // Nodes.
  std::vector<double> nodes = {0.0};
  std::vector<int> breakpoint_node = {0};
  for (int k = 0; k < spans; ++k) {
    const double len = bp[k + 1] - bp[k];
    int n = disc.elements_per_span.empty()
                ? std::max(1, static_cast<int>(std::ceil(len / disc.element_length - 1e-9)))
                : disc.elements_per_span[k];
    n <<= disc.refinement;
    if (n < 1) throw InvalidInput("a span needs at least one element");
    for (int i = 1; i <= n; ++i) nodes.push_back(bp[k] + len * i / n);
    nodes.back() = bp[k + 1];
    breakpoint_node.push_back(static_cast<int>(nodes.size()) - 1);
  }
  const int ne = static_cast<int>(nodes.size()) - 1;
  model.num_elements = ne;
  model.node_s = Eigen::Map<Eigen::VectorXd>(nodes.data(), nodes.size());
  model.element_length = model.node_s.tail(ne) - model.node_s.head(ne);
  auto node_at = [&](double s) {
    const auto it = std::min_element(bp.begin(), bp.end(), [s](double a, double b) {
      return std::abs(a - s) < std::abs(b - s);
    });
    return breakpoint_node[it - bp.begin()];
  };

  // Supports.
  const Mat3 k_material = MaterialStiffness(spec.material);
  for (size_t i = 0; i < spec.supports.size(); ++i) {
    const SupportSpec& sp = spec.supports[i];
    const double s = std::clamp(sp.s, 0.0, L);
    model.supports.push_back(MakeRodSupport(sp, s, node_at(s)));
  }
  model.anchor_support = 0;
  for (size_t i = 0; i < model.supports.size(); ++i)
    if (!model.supports[i].sliding) {
      model.anchor_support = static_cast<int>(i);
      break;
    }
  if (model.supports[model.anchor_support].sliding)
    throw InvalidInput("every support slides: nothing fixes the cable's position along itself");
  model.anchor_node = model.supports[model.anchor_support].node;
  for (size_t i = 0; i < model.supports.size(); ++i) {
    if (static_cast<int>(i) == model.anchor_support) continue;
    RodSupport& rs = model.supports[i];
    rs.constraint_row = model.num_constraints;
    rs.constraint_rows = rs.sliding ? 2 : 3;
    model.num_constraints += rs.constraint_rows;
  }

  // Items: support frames are inserted at their node, between the neighbouring elements.
  auto add_support_items_at_node = [&](int node) {
    for (size_t i = 0; i < model.supports.size(); ++i) {
      RodSupport& rs = model.supports[i];
      if (rs.node != node || rs.kind == SupportKind::kPin) continue;
      const RodItem it = MakeSupportItem(spec.supports[i], static_cast<int>(i), rs.s,
                                         k_material.diagonal().maxCoeff() / L);
      rs.item = static_cast<int>(model.items.size());
      model.items.push_back(it);
    }
  };
  model.element_item.resize(ne);
  for (int e = 0; e < ne; ++e) {
    add_support_items_at_node(e);
    RodItem it;
    it.element = e;
    it.length = model.element_length[e];
    it.s = 0.5 * (nodes[e] + nodes[e + 1]);
    model.element_item[e] = static_cast<int>(model.items.size());
    model.items.push_back(it);
  }
  add_support_items_at_node(ne);

  // Edges with cell-averaged natural curvature.
  for (size_t a = 0; a + 1 < model.items.size(); ++a) {
    RodEdge edge;
    edge.a = static_cast<int>(a);
    edge.b = static_cast<int>(a + 1);
    const RodItem& ia = model.items[a];
    const RodItem& ib = model.items[a + 1];
    edge.ds = ib.s - ia.s;
    CABLEFIT_CHECK(edge.ds > 0, "frame samples must advance along the cable");
    edge.s = 0.5 * (ia.s + ib.s);
    edge.stiffness = k_material;
    edge.natural = AverageNaturalCurvature(spec.natural_curvature, ia.s, ib.s);
    model.edges.push_back(edge);
  }

  // Lumped node masses, dead loads, and their per-element potential coefficients.
  const double rho = spec.material.linear_density;
  model.node_mass = Eigen::VectorXd::Zero(ne + 1);
  for (int e = 0; e < ne; ++e) {
    model.node_mass[e] += 0.5 * rho * model.element_length[e];
    model.node_mass[e + 1] += 0.5 * rho * model.element_length[e];
  }
  std::vector<Vec3> node_force(ne + 1);
  for (int i = 0; i <= ne; ++i) node_force[i] = model.node_mass[i] * spec.gravity;
  double load_sum = 0.0;
  for (const PointLoadSpec& pl : spec.point_loads) {
    const int n = node_at(std::clamp(pl.s, 0.0, L));
    node_force[n] += pl.force;
    model.node_loads.emplace_back(n, pl.force);
    load_sum += pl.force.norm();
  }
  model.element_nodes.resize(ne);
  for (int e = 0; e < ne; ++e) model.element_nodes[e] = {e, e + 1};
  BuildNodeTree(&model);
  BuildItemTree(&model);
  model.element_axial_stiffness = Eigen::VectorXd::Constant(ne, spec.material.axial_stiffness);
  AssignConstraintReferences(&model);
  ComputeLoadCoefficients(node_force, &model);
  model.force_scale = std::max({rho * spec.gravity.norm() * L, load_sum,
                                spec.material.bending_stiffness / (L * L)});
  return model;
}

}  // namespace cablefit
