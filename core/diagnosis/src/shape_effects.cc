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

int NuisanceClampIndex(const RodSpec& nominal) {
  for (int k = static_cast<int>(nominal.supports.size()) - 1; k > 0; --k)
    if (nominal.supports[k].kind == SupportKind::kClamp) return k;
  return -1;
}

void ApplyNuisanceTwist(int clamp, double angle, RodSpec* spec) {
  if (clamp < 0) return;
  SupportSpec& sp = spec->supports[clamp];
  sp.normal = Eigen::AngleAxisd(angle, sp.tangent.normalized()) * sp.normal;
}

std::vector<EffectModel> BuildEffectModels(const RodSpec& nominal,
                                           const std::vector<double>& reaction_moment) {
  const double L = nominal.length;
  const int nuis = NuisanceClampIndex(nominal);
  const int nn = nuis >= 0 ? 1 : 0;
  auto with_nuisance = [nominal, nuis](const Eigen::VectorXd& x, int k) {
    RodSpec s = nominal;
    if (nuis >= 0) ApplyNuisanceTwist(nuis, x[k], &s);
    return s;
  };
  auto scales = [nn](std::initializer_list<double> phys) {
    Eigen::VectorXd s(static_cast<int>(phys.size()) + nn);
    int i = 0;
    for (double v : phys) s[i++] = v;
    if (nn) s[i] = 0.05;
    return s;
  };
  std::vector<EffectModel> models;

  {  // none: only the nuisance.
    EffectModel m;
    m.effect = "none";
    m.scale = scales({});
    m.starts = {Eigen::VectorXd(0)};
    m.apply = [=](const Eigen::VectorXd& x) { return with_nuisance(x, 0); };
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
      RodSpec s = with_nuisance(x, 4);
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
      RodSpec s = with_nuisance(x, 2);
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
      RodSpec s = with_nuisance(x, 1);
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
    for (int i = 0; i < 8; ++i) {
      Eigen::VectorXd x(2);
      x << 0.25 * std::cos(i * M_PI / 4), 0.25 * std::sin(i * M_PI / 4);
      m.starts.push_back(x);
    }
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = with_nuisance(x, 2);
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
      RodSpec s = with_nuisance(x, 4);
      s.point_loads.push_back({std::clamp(x[0], 0.02 * L, 0.98 * L), Vec3(x[1], x[2], x[3])});
      return s;
    };
    models.push_back(m);
  }
  if (nuis >= 0) {  // The far clamp's twist itself, free of the prior on the nuisance.
    EffectModel m;
    m.effect = "twist_preload";
    m.clamp = nuis;
    m.physical_parameters = 1;
    m.has_nuisance = false;
    m.names = {"rotation"};
    m.scale = Eigen::VectorXd::Constant(1, 0.05);
    m.starts = {Eigen::VectorXd::Zero(1)};  // DiagnoseShape starts it from the fitted nuisance
    m.apply = [=](const Eigen::VectorXd& x) {
      RodSpec s = nominal;
      ApplyNuisanceTwist(nuis, x[0], &s);
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
      RodSpec s = with_nuisance(x, 1);
      s.supports[k].compliance = Mat3::Identity() * std::exp(std::clamp(x[0], -60.0, 20.0));
      return s;
    };
    models.push_back(m);
  }
  return models;
}

}  // namespace cablefit
