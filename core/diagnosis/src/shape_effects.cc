#include "shape_effects.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace cablefit {
namespace {

Frame FrameOf(const SupportSpec& s) {
  return Frame::FromTangentNormal(
      s.tangent, s.kind == SupportKind::kClamp ? s.normal : s.tangent.unitOrthogonal());
}

}  // namespace

void RotateClampAboutTangent(int clamp, double angle, RodSpec* spec) {
  SupportSpec& sp = spec->supports[static_cast<size_t>(clamp)];
  sp.normal = Eigen::AngleAxisd(angle, sp.tangent.normalized()) * sp.normal;
}

std::vector<EffectModel> BuildEffectModels(const RodSpec& nominal,
                                           const std::vector<double>& reaction_moment) {
  const double L = nominal.length;
  auto scales = [](std::initializer_list<double> phys) {
    Eigen::VectorXd s(static_cast<int>(phys.size()));
    int i = 0;
    for (double v : phys) s[i++] = v;
    return s;
  };
  std::vector<EffectModel> models;

  {
    EffectModel m;
    m.effect = "none";
    m.scale = scales({});
    m.starts = {Eigen::VectorXd(0)};
    m.apply = [=](const Eigen::VectorXd&) { return nominal; };
    models.push_back(m);
  }
  {  // Natural curvature over [c - w/2, c + w/2], material-frame components.
    EffectModel m;
    m.effect = "intrinsic_curvature";
    m.physical_parameters = 4;
    m.names = {"centre", "width", "kappa1", "kappa2"};
    m.scale = scales({0.02 * L, 0.02 * L, 1.0, 1.0});
    for (int i = 0; i < 6; ++i)
      for (double w : {L / 8, L / 3}) {
        Eigen::VectorXd x(4);
        x << L * (i + 0.5) / 6, w, 0.0, 0.0;
        m.starts.push_back(x);
      }
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = nominal;
      const double w = std::clamp(std::abs(x[1]), 0.01 * L, L);
      NaturalCurvatureSpec nc;
      nc.s_start = std::clamp(x[0] - w / 2, 0.0, L);
      nc.s_end = std::clamp(x[0] + w / 2, 0.0, L);
      if (nc.s_end <= nc.s_start) nc.s_end = std::min(L, nc.s_start + 0.01 * L);
      nc.ramp = 0.2 * (nc.s_end - nc.s_start);
      nc.kappa = Vec3(x[2], x[3], 0.0);
      s.natural_curvature.push_back(nc);
      return s;
    };
    models.push_back(m);
  }
  for (int k = 0; k < static_cast<int>(nominal.supports.size()); ++k) {
    if (nominal.supports[k].kind == SupportKind::kPin) continue;
    EffectModel m;  // Clamp held at another angle: rotation about d1 and d2.
    m.effect = "clamp_orientation";
    m.clamp = k;
    m.physical_parameters = 2;
    m.names = {"rot_d1", "rot_d2"};
    m.scale = scales({0.02, 0.02});
    m.starts = {Eigen::VectorXd::Zero(2)};
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = nominal;
      SupportSpec& sp = s.supports[k];
      const Frame f = FrameOf(sp);
      const Vec3 rv = x[0] * f.d1 + x[1] * f.d2;
      const double a = rv.norm();
      if (a > 0) {
        const Eigen::AngleAxisd rot(a, rv / a);
        sp.tangent = rot * f.d3;
        sp.normal = rot * f.d1;
      }
      return s;
    };
    models.push_back(m);
  }
  {  // Heavier or softer: only w/EI is observable; density scaled.
    EffectModel m;
    m.effect = "weight_stiffness_ratio";
    m.physical_parameters = 1;
    m.names = {"log_ratio"};
    m.scale = scales({0.05});
    m.starts = {Eigen::VectorXd::Zero(1)};
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = nominal;
      s.material.linear_density *= std::exp(x[0]);
      return s;
    };
    models.push_back(m);
  }
  {  // Anisotropic bending: B = EI expm([[u1, u2], [u2, -u1]]) keeps sqrt(Bmax
    // Bmin) = EI and is smooth through the isotropic case.
    EffectModel m;
    m.effect = "anisotropic_bending";
    m.physical_parameters = 2;
    m.names = {"u1", "u2"};
    m.scale = scales({0.05, 0.05});
    // (u1, u2) -> -(u1, u2) is the inverse ratio at the same angle, i.e. the same ratio a
    // quarter-turn on: eight directions cover the principal angle's half-turn with both branches
    // of the ratio; two radii (ratio 1.35 and 2.2) so that a strong anisotropy starts near.
    for (double radius : {0.15, 0.4})
      for (int i = 0; i < 8; ++i) {
        Eigen::VectorXd x(2);
        x << radius * std::cos(i * M_PI / 4), radius * std::sin(i * M_PI / 4);
        m.starts.push_back(x);
      }
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = nominal;
      const double u = std::hypot(x[0], x[1]);
      s.material.bending_ratio = std::exp(2.0 * u);
      s.material.principal_angle = 0.5 * std::atan2(x[1], x[0]);
      return s;
    };
    models.push_back(m);
  }
  {  // A support the model does not have: a point force at arc length sc.
    EffectModel m;
    m.effect = "support_contact";
    m.physical_parameters = 4;
    m.names = {"s", "fx", "fy", "fz"};
    const double w = std::max(1e-6, nominal.material.linear_density * nominal.gravity.norm() * L);
    m.scale = scales({0.01 * L, 0.05 * w, 0.05 * w, 0.05 * w});
    for (int i = 0; i < 8; ++i) {
      Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
      x[0] = L * (i + 0.5) / 8;
      m.starts.push_back(x);
    }
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = nominal;
      s.point_loads.push_back({std::clamp(x[0], 0.02 * L, 0.98 * L), Vec3(x[1], x[2], x[3])});
      return s;
    };
    models.push_back(m);
  }
  for (int k = 0; k < static_cast<int>(nominal.supports.size()); ++k) {
    if (nominal.supports[k].kind != SupportKind::kClamp) continue;
    // The clamp rotated about the cable axis from the case's normal (right-hand rule about its
    // tangent). The shape is periodic and far from quadratic in the angle, so it is started
    // around the circle.
    EffectModel m;
    m.effect = "twist_preload";
    m.clamp = k;
    m.physical_parameters = 1;
    m.names = {"angle"};
    m.scale = scales({0.05});
    for (double a : {0.0, 0.8, -0.8, 1.6, -1.6, 2.4, -2.4})
      m.starts.push_back(Eigen::VectorXd::Constant(1, a));
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = nominal;
      RotateClampAboutTangent(k, x[0], &s);
      return s;
    };
    models.push_back(m);
  }
  for (int k = 0; k < static_cast<int>(nominal.supports.size()); ++k) {
    if (nominal.supports[k].kind != SupportKind::kClamp) continue;
    EffectModel m;  // Isotropic rotational compliance c = 1/k of a clamp.
    m.effect = "clamp_compliance";
    m.clamp = k;
    m.physical_parameters = 1;
    m.names = {"log_compliance"};
    m.scale = scales({0.2});
    const double moment = k < static_cast<int>(reaction_moment.size()) ? reaction_moment[k] : 0.0;
    const double c0 = 0.02 / std::max(moment, 1e-9);
    for (double f : {0.3, 3.0}) m.starts.push_back(Eigen::VectorXd::Constant(1, std::log(f * c0)));
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = nominal;
      s.supports[k].compliance = Mat3::Identity() * std::exp(std::clamp(x[0], -60.0, 20.0));
      return s;
    };
    models.push_back(m);
  }
  return models;
}

}  // namespace cablefit
