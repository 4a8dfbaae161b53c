#include "shape_effects.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "contact_frame.h"

namespace cablefit {
namespace {

Frame FrameOf(const SupportSpec& s) {
  return Frame::FromTangentNormal(
      s.tangent, s.kind == SupportKind::kClamp ? s.normal : s.tangent.unitOrthogonal());
}

// The span a natural curvature (centre, width) covers on a cable of length L: at least 1 % of
// the cable wide and inside it [m].
std::pair<double, double> CurvedSpan(const Eigen::VectorXd& x, double L) {
  const double w = std::clamp(std::abs(x[1]), 0.01 * L, L);
  return {std::clamp(x[0] - w / 2, 0.0, L), std::clamp(x[0] + w / 2, 0.0, L)};
}

// Where an unmodelled contact may push: not on the clamps' own 2 % at either end [m].
double ContactPosition(const Eigen::VectorXd& x, double L) {
  return std::clamp(x[0], 0.02 * L, 0.98 * L);
}

// A clamp's rotation vector from its (rot_d1, rot_d2) [rad, world].
Vec3 ClampRotation(const Frame& f, const Eigen::VectorXd& x) { return x[0] * f.d1 + x[1] * f.d2; }

// Anisotropy (u1, u2) -> (B_max / B_min, principal angle [rad]).
std::pair<double, double> Anisotropy(const Eigen::VectorXd& x) {
  return {std::exp(2.0 * std::hypot(x[0], x[1])), 0.5 * std::atan2(x[1], x[0])};
}

// A clamp's log rotational compliance, bounded so that the solver sees a finite, positive
// compliance.
double LogCompliance(const Eigen::VectorXd& x) { return std::clamp(x[0], -60.0, 20.0); }

double WrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

}  // namespace

void RotateClampAboutTangent(int clamp, double angle, RodSpec* spec) {
  SupportSpec& sp = spec->supports[static_cast<size_t>(clamp)];
  sp.normal = Eigen::AngleAxisd(angle, sp.tangent.normalized()) * sp.normal;
}

std::vector<EffectModel> BuildEffectModels(const RodSpec& nominal,
                                           const std::vector<double>& reaction_moment,
                                           const Eigen::Matrix3Xd& recorded,
                                           const Eigen::VectorXd& recorded_s) {
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
    m.effect = ShapeEffect::kNone;
    m.scale = scales({});
    m.starts = {Eigen::VectorXd(0)};
    m.change = [](const Eigen::VectorXd&, RodSpec*) {};
    m.describe = [](const Eigen::VectorXd&, const EffectDescriptionContext&) {
      return EffectDescription{};
    };
    models.push_back(m);
  }
  {  // Natural curvature over [c - w/2, c + w/2], material-frame components.
    EffectModel m;
    m.effect = ShapeEffect::kIntrinsicCurvature;
    m.physical_parameters = 4;
    // x = (centre, width, kappa1, kappa2)
    m.scale = scales({0.02 * L, 0.02 * L, 1.0, 1.0});
    m.amplitudes = {2, 3};
    for (int i = 0; i < 6; ++i)
      for (double w : {L / 8, L / 3}) {
        Eigen::VectorXd x(4);
        x << L * (i + 0.5) / 6, w, 0.0, 0.0;
        m.starts.push_back(x);
      }
    // A bend of the residual is the span itself (a step of curvature over it): as wide as the
    // bend, within the grid's widths.
    m.starts_at_bends = [=](const std::vector<ResidualBend>& bends) {
      std::vector<Eigen::VectorXd> starts;
      for (const ResidualBend& b : bends) {
        Eigen::VectorXd x(4);
        x << b.s, std::clamp(b.width, L / 8, L / 3), 0.0, 0.0;
        starts.push_back(x);
      }
      return starts;
    };
    m.change = [=](const Eigen::VectorXd& x, RodSpec* s) {
      NaturalCurvatureSpec nc;
      std::tie(nc.s_start, nc.s_end) = CurvedSpan(x, L);
      if (nc.s_end <= nc.s_start) nc.s_end = std::min(L, nc.s_start + 0.01 * L);
      nc.ramp = 0.2 * (nc.s_end - nc.s_start);
      nc.kappa = Vec3(x[2], x[3], 0.0);
      s->natural_curvature.push_back(nc);
    };
    m.describe = [=](const Eigen::VectorXd& x, const EffectDescriptionContext&) {
      EffectDescription d;
      d.interval = CurvedSpan(x, L);
      const double kappa = std::hypot(x[2], x[3]);
      d.parameters["curvature"] = kappa;
      d.parameters["direction"] = std::atan2(x[3], x[2]);
      d.parameters["total_bend_angle"] = kappa * (d.interval->second - d.interval->first);
      d.units = {{"curvature", "1/m"}, {"direction", "rad"}, {"total_bend_angle", "rad"}};
      return d;
    };
    models.push_back(m);
  }
  for (int k = 0; k < static_cast<int>(nominal.supports.size()); ++k) {
    if (nominal.supports[k].kind == SupportKind::kPin) continue;
    EffectModel m;  // Clamp held at another angle: rotation about d1 and d2.
    m.effect = ShapeEffect::kClampOrientation;
    m.clamp = k;
    m.physical_parameters = 2;
    // x = (rot_d1, rot_d2)
    m.scale = scales({0.02, 0.02});
    m.amplitudes = {0, 1};
    m.starts = {Eigen::VectorXd::Zero(2)};
    // The rotation's axes are the nominal clamp's, also when another effect (a twist preload)
    // has turned the clamp already, so that the parameters mean the same in every combination.
    const Frame nominal_frame = FrameOf(nominal.supports[static_cast<size_t>(k)]);
    m.change = [=](const Eigen::VectorXd& x, RodSpec* s) {
      SupportSpec& sp = s->supports[static_cast<size_t>(k)];
      const Frame f = FrameOf(sp);
      const Vec3 rv = ClampRotation(nominal_frame, x);
      const double a = rv.norm();
      if (a > 0) {
        const Eigen::AngleAxisd rot(a, rv / a);
        sp.tangent = rot * f.d3;
        sp.normal = rot * f.d1;
      }
    };
    m.describe = [=](const Eigen::VectorXd& x, const EffectDescriptionContext& c) {
      EffectDescription d;
      d.interval = c.mismatch;
      const Frame f = FrameOf(nominal.supports[static_cast<size_t>(k)]);
      const double angle = std::hypot(x[0], x[1]);
      d.parameters["angle"] = angle;
      d.vectors["axis"] = angle > 0 ? Vec3(ClampRotation(f, x) / angle) : Vec3(f.d1);
      d.units = {{"angle", "rad"}, {"axis", "-"}};
      return d;
    };
    models.push_back(m);
  }
  {  // Heavier or softer: only w/EI is observable; density scaled.
    EffectModel m;
    m.effect = ShapeEffect::kWeightStiffnessRatio;
    m.physical_parameters = 1;
    // x = (log_ratio)
    m.scale = scales({0.05});
    m.amplitudes = {0};
    m.starts = {Eigen::VectorXd::Zero(1)};
    m.change = [](const Eigen::VectorXd& x, RodSpec* s) {
      s->material.linear_density *= std::exp(x[0]);
    };
    m.describe = [](const Eigen::VectorXd& x, const EffectDescriptionContext& c) {
      EffectDescription d;
      d.interval = c.mismatch;
      d.parameters["ratio"] = std::exp(x[0]);
      d.units = {{"ratio", "-"}};
      return d;
    };
    models.push_back(m);
  }
  {  // Anisotropic bending: B = EI expm([[u1, u2], [u2, -u1]]) keeps sqrt(Bmax
    // Bmin) = EI and is smooth through the isotropic case.
    EffectModel m;
    m.effect = ShapeEffect::kAnisotropicBending;
    m.physical_parameters = 2;
    // x = (u1, u2)
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
    m.change = [](const Eigen::VectorXd& x, RodSpec* s) {
      std::tie(s->material.bending_ratio, s->material.principal_angle) = Anisotropy(x);
    };
    m.describe = [](const Eigen::VectorXd& x, const EffectDescriptionContext& c) {
      EffectDescription d;
      d.interval = c.mismatch;
      auto [ratio, angle] = Anisotropy(x);
      if (angle < 0) angle += M_PI;  // the stiff axis as a direction: [0, pi)
      d.parameters["ratio"] = ratio;
      d.parameters["principal_angle"] = angle;
      d.units = {{"ratio", "-"}, {"principal_angle", "rad"}};
      return d;
    };
    models.push_back(m);
  }
  {  // A support the model does not have: a point force at arc length sc, normal to the cable
     // as recorded there (contact_frame.h).
    EffectModel m;
    m.effect = ShapeEffect::kSupportContact;
    m.physical_parameters = 3;
    // x = (s, f_up, f_side)
    const double w = std::max(1e-6, nominal.material.linear_density * nominal.gravity.norm() * L);
    m.scale = scales({0.01 * L, 0.05 * w, 0.05 * w});
    m.amplitudes = {1, 2};
    for (int i = 0; i < 8; ++i) {
      Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
      x[0] = L * (i + 0.5) / 8;
      m.starts.push_back(x);
      if (i == 0) continue;
      x[0] = L * i / 8.0;
      m.residual_starts.push_back(x);
    }
    // Every fortieth of the cable between the clamps' own 2 %: finer than a contact's basin,
    // which is several hundredths of the cable wide.
    for (int i = 1; i < 40; ++i) m.scan_places.push_back(Eigen::Vector3d(L * i / 40.0, 0.0, 0.0));
    // A point force bends the residual most where it pushes.
    m.starts_at_bends = [](const std::vector<ResidualBend>& bends) {
      std::vector<Eigen::VectorXd> starts;
      for (const ResidualBend& b : bends) starts.push_back(Eigen::Vector3d(b.s, 0.0, 0.0));
      return starts;
    };
    const Vec3 gravity = nominal.gravity;
    auto force = [=](const Eigen::VectorXd& x) {
      const internal::ContactFrame f = internal::RecordedContactFrame(
          recorded, recorded_s, ContactPosition(x, L), 0.03 * L, gravity);
      return Vec3(x[1] * f.up + x[2] * f.side);
    };
    m.change = [=](const Eigen::VectorXd& x, RodSpec* s) {
      s->point_loads.push_back({ContactPosition(x, L), force(x)});
    };
    // The contact is reported as a short span: a few diameters, at least 1 % of the cable.
    const double half = std::max(2.0 * nominal.material.diameter, 0.01 * L);
    m.describe = [=](const Eigen::VectorXd& x, const EffectDescriptionContext&) {
      EffectDescription d;
      const double sc = ContactPosition(x, L);
      const Vec3 f = force(x);
      d.interval = std::make_pair(std::max(0.0, sc - half), std::min(L, sc + half));
      d.parameters["s"] = sc;
      d.parameters["force"] = f.norm();
      d.vectors["force_vector"] = f;
      d.units = {{"s", "m"}, {"force", "N"}, {"force_vector", "N"}};
      return d;
    };
    models.push_back(m);
  }
  for (int k = 0; k < static_cast<int>(nominal.supports.size()); ++k) {
    if (nominal.supports[k].kind != SupportKind::kClamp) continue;
    // The clamp rotated about the cable axis from the case's normal (right-hand rule about its
    // tangent). The shape is periodic and far from quadratic in the angle, so it is started
    // around the circle.
    EffectModel m;
    m.effect = ShapeEffect::kTwistPreload;
    m.clamp = k;
    m.physical_parameters = 1;
    // x = (angle)
    m.scale = scales({0.05});
    m.amplitudes = {0};
    for (double a : {0.0, 0.8, -0.8, 1.6, -1.6, 2.4, -2.4})
      m.starts.push_back(Eigen::VectorXd::Constant(1, a));
    m.change = [=](const Eigen::VectorXd& x, RodSpec* s) { RotateClampAboutTangent(k, x[0], s); };
    // For a cable that bends alike in every direction and has no natural curvature, the
    // centreline depends on the clamps' twist only through the twist between them (the twisting
    // moment is constant along it; pins and clips pass it on): with exactly two clamps that hold
    // the twist, turning the other one the opposite way gives the same shape, exactly. Which of
    // them was turned cannot be told from the shape; the description names the alternative.
    // This holds beside a fitted natural curvature or anisotropy too: the two twists differ by a
    // constant turn of every cross-section, which their fitted direction takes up.
    std::optional<int> other;
    {
      std::vector<int> holding;
      for (size_t j = 0; j < nominal.supports.size(); ++j)
        if (nominal.supports[j].kind == SupportKind::kClamp) holding.push_back(static_cast<int>(j));
      if (holding.size() == 2 && nominal.material.bending_ratio == 1.0 &&
          nominal.natural_curvature.empty())
        other = holding[0] == k ? holding[1] : holding[0];
    }
    m.describe = [=](const Eigen::VectorXd& x, const EffectDescriptionContext& c) {
      EffectDescription d;
      d.interval = c.mismatch;
      const double angle = WrapAngle(x[0]);
      d.parameters["angle"] = angle;
      d.units["angle"] = "rad";
      if (c.solution && static_cast<size_t>(k) < c.solution->reactions.size()) {
        d.parameters["torque"] = c.solution->reactions[static_cast<size_t>(k)].moment.dot(
            nominal.supports[static_cast<size_t>(k)].tangent.normalized());
        d.units["torque"] = "N m";
      }
      if (other) {
        d.parameters["alternative_clamp"] = *other;
        d.parameters["alternative_angle"] = -angle;
        d.units["alternative_clamp"] = "-";
        d.units["alternative_angle"] = "rad";
      }
      return d;
    };
    models.push_back(m);
  }
  for (int k = 0; k < static_cast<int>(nominal.supports.size()); ++k) {
    if (nominal.supports[k].kind != SupportKind::kClamp) continue;
    EffectModel m;  // Isotropic rotational compliance c = 1/k of a clamp.
    m.effect = ShapeEffect::kClampCompliance;
    m.clamp = k;
    m.physical_parameters = 1;
    // x = (log_compliance)
    m.scale = scales({0.2});
    const double moment = k < static_cast<int>(reaction_moment.size()) ? reaction_moment[k] : 0.0;
    const double c0 = 0.02 / std::max(moment, 1e-9);
    for (double f : {0.3, 3.0}) m.starts.push_back(Eigen::VectorXd::Constant(1, std::log(f * c0)));
    m.change = [=](const Eigen::VectorXd& x, RodSpec* s) {
      s->supports[static_cast<size_t>(k)].compliance =
          Mat3::Identity() * std::exp(LogCompliance(x));
    };
    m.describe = [](const Eigen::VectorXd& x, const EffectDescriptionContext& c) {
      EffectDescription d;
      d.interval = c.mismatch;
      d.parameters["stiffness"] = std::exp(-LogCompliance(x));
      d.units = {{"stiffness", "N m/rad"}};
      return d;
    };
    models.push_back(m);
  }
  const auto base = std::make_shared<const RodSpec>(nominal);
  for (EffectModel& m : models) m.base = base;
  return models;
}

bool EffectModel::is_neutral(const Eigen::VectorXd& x) const {
  if (amplitudes.empty()) return false;
  for (int i : amplitudes)
    if (x[i] != 0.0) return false;
  return true;
}

RodSpec EffectModel::apply(const Eigen::VectorXd& x) const {
  RodSpec s = *base;
  change(x, &s);
  return s;
}

}  // namespace cablefit
