// Shape diagnosis (issue 4). Method:
// 1. Simulate the nominal set-up from the recorded shape (selects the branch),
// then fit the one
//    nuisance parameter every model shares: the twist the far clamp imposes. A
//    bench sets a clamp's rotation about the cable axis by eye, and a case's
//    far normal is often not the one its cable has (measured on the public
//    reference data: it is the start normal projected, and the cable is held
//    near its torque-free twist instead). So the twist is fitted in every model
//    under a prior: within twist_sigma of the case's normal or of the
//    torque-free twist (the far clamp released about its axis). twist_preload
//    is the same rotation without the prior, so it wins only when the shape
//    demands a twist far from both.
// 2. Fit every catalogue effect by Levenberg-Marquardt on the seen points
// (residual = offset of
//    each point from its closest point on the simulated curve), warm-starting
//    every forward solve from the last, multi-start where the problem is not
//    convex (interval position, contact position, anisotropy angle, both
//    clamps).
// 3. Select by BIC with the noise estimated from the best model's residual
// (floored by the
//    recording's own noise): chi^2 + k ln n. `none` unless an effect wins by
//    min_bic_gain.
#include "cablefit/core/diagnosis/shape_diagnosis.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "curve_projection.h"
#include "levenberg_marquardt.h"
#include "shape_effects.h"

namespace cablefit {
namespace {

using Clock = std::chrono::steady_clock;

struct FitContext {
  const ShapeObservation* obs = nullptr;
  Eigen::Matrix3Xd points;  // thinned
  Eigen::VectorXd s;        // thinned arc lengths
  double length = 0.0;
  double window = 0.0;
  int curve_samples = 0;
  // Prior on the nuisance twist (far clamp's rotation about its tangent from
  // the case's normal).
  bool twist_prior = false;
  double twist_free = 0.0;    // [rad] the torque-free rotation
  double twist_sigma = 0.25;  // [rad] ShapeDiagnosisOptions::twist_sigma
  double prior_scale = 1e-4;  // [m] the offset one prior standard deviation weighs in the fits
};

double WrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

// Signed distance of the nuisance rotation from the nearer nominal twist, in
// prior sigmas.
double TwistPriorDeviation(const FitContext& ctx, double rotation) {
  const double a = WrapAngle(rotation), b = WrapAngle(rotation - ctx.twist_free);
  return (std::abs(a) <= std::abs(b) ? a : b) / ctx.twist_sigma;
}

// Rotation about the clamp's tangent from its normal to the frame the solution
// holds there.
double RotationAtClamp(const SupportSpec& clamp, const RodSolution& sol) {
  const Vec3 t = clamp.tangent.normalized();
  int k = 0;
  for (int i = 1; i < sol.frame_s.size(); ++i)
    if (std::abs(sol.frame_s[i] - clamp.s) < std::abs(sol.frame_s[k] - clamp.s)) k = i;
  const Frame& f = sol.frames[static_cast<size_t>(k)];
  // The element's d1 carried onto the clamp's tangent by the smallest rotation.
  const Vec3 d1 = Eigen::Quaterniond::FromTwoVectors(f.d3, t) * f.d1;
  const Vec3 n = (clamp.normal - clamp.normal.dot(t) * t).normalized();
  return std::atan2(n.cross(d1).dot(t), n.dot(d1));
}

bool Residual(const FitContext& ctx, RodSimulator* sim, const RodSpec& spec, Eigen::VectorXd* r,
              CurveProjection* proj = nullptr) {
  SimulationResult res;
  try {
    res = sim->Resimulate(spec);
  } catch (const InvalidInput&) {
    return false;
  }
  if (!res.converged) return false;
  const Polyline curve =
      SampleCenterline(res.solution.centerline, UniformArcLengths(ctx.length, ctx.curve_samples));
  CurveProjection p = ProjectOntoCurve(curve, ctx.points, ctx.s, ctx.window);
  *r = Eigen::Map<const Eigen::VectorXd>(p.offset.data(), p.offset.size());
  if (proj) *proj = std::move(p);
  return true;
}

struct Fit {
  const EffectModel* model = nullptr;
  Eigen::VectorXd x;
  double cost = INFINITY;  // 1/2 |offsets|^2 [m^2]
  double prior = 0.0;      // squared prior deviation of the nuisance twist [-]
  bool ok = false;
};

Fit FitModel(const FitContext& ctx, const RodSimulator& base, const EffectModel& m,
             const Eigen::VectorXd& nuisance, int max_iterations) {
  const int np = m.physical_parameters;
  const int nn = static_cast<int>(m.scale.size()) - np;
  const bool prior = m.has_nuisance && nn > 0 && ctx.twist_prior;
  struct Run {
    RodSimulator sim;
    LmResult lm;
  };
  auto run = [&](Run* r, const Eigen::VectorXd& x0, int iterations) {
    auto fn = [&](const Eigen::VectorXd& x, Eigen::VectorXd* res) {
      if (!Residual(ctx, &r->sim, m.apply(x), res)) return false;
      if (prior) {
        res->conservativeResize(res->size() + 1);
        (*res)[res->size() - 1] = ctx.prior_scale * TwistPriorDeviation(ctx, x[np]);
      }
      return true;
    };
    LmOptions opt;
    opt.max_iterations = iterations;
    r->lm = MinimiseLeastSquares(fn, x0, m.scale, opt);
  };
  // Many starts (interval and contact positions, anisotropy angles): a few
  // iterations each, then only the most promising ones are carried to
  // convergence.
  const bool screen = m.starts.size() > 2;
  std::vector<Run> runs;
  for (const Eigen::VectorXd& start : m.starts) {
    Eigen::VectorXd x0(np + nn);
    x0.head(np) = start;
    if (nn) x0.tail(nn) = nuisance;
    Run r{base, {}};
    run(&r, x0, screen ? 4 : max_iterations);
    if (r.lm.ok) runs.push_back(std::move(r));
  }
  std::sort(runs.begin(), runs.end(),
            [](const Run& a, const Run& b) { return a.lm.cost < b.lm.cost; });
  if (screen) {
    if (runs.size() > 2) runs.resize(2);
    for (Run& r : runs) run(&r, Eigen::VectorXd(r.lm.x), max_iterations);
    std::sort(runs.begin(), runs.end(),
              [](const Run& a, const Run& b) { return a.lm.cost < b.lm.cost; });
  }
  Fit best;
  best.model = &m;
  if (!runs.empty()) {
    best.x = runs.front().lm.x;
    if (prior) best.prior = std::pow(TwistPriorDeviation(ctx, best.x[np]), 2);
    best.cost = runs.front().lm.cost - 0.5 * std::pow(ctx.prior_scale, 2) * best.prior;
    best.ok = true;
  }
  return best;
}

// The span where the deviation exceeds half its maximum (seen points only).
std::pair<double, double> MismatchInterval(const Eigen::VectorXd& s, const Eigen::VectorXd& dev) {
  if (s.size() == 0) return {0.0, 0.0};
  Eigen::Index imax;
  const double mx = dev.maxCoeff(&imax);
  double lo = s[imax], hi = s[imax];
  for (int i = 0; i < s.size(); ++i)
    if (dev[i] >= 0.5 * mx) lo = std::min(lo, s[i]), hi = std::max(hi, s[i]);
  return {lo, hi};
}

std::string Mm(double metres) {
  std::ostringstream os;
  os.precision(metres < 1e-3 ? 2 : 3);
  os << metres * 1e3 << " mm";
  return os.str();
}

std::string Fixed(double v, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}

}  // namespace

bool ShapeDiagnosisOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(accuracy > 0)) return fail("accuracy must be > 0");
  if (max_iterations < 1) return fail("max_iterations must be >= 1");
  if (max_points < 10) return fail("max_points must be >= 10");
  if (!(twist_sigma >= 0)) return fail("twist_sigma must be >= 0");
  return true;
}

ShapeDiagnosis DiagnoseShape(const RodSpec& nominal, const ShapeObservation& obs,
                             const ShapeDiagnosisOptions& options) {
  const auto t0 = Clock::now();
  std::string why;
  if (!options.IsValid(&why)) throw InvalidInput("diagnosis options: " + why);
  ValidateRodSpec(nominal);
  const int n_all = static_cast<int>(obs.points.cols());
  if (n_all < 5) throw InvalidInput("the recording has only " + std::to_string(n_all) + " points");
  if (!obs.points.allFinite()) throw InvalidInput("the recording has non-finite points");
  const double L = nominal.length;
  auto progress = [&](double f, const char* stage) {
    if (options.progress && !options.progress(f, stage)) throw InvalidInput("cancelled");
  };

  // Thin the points to a spacing of about two diameters: neighbouring centre
  // points of a scan share errors, and treating them as independent would
  // overstate the evidence.
  FitContext ctx;
  ctx.obs = &obs;
  ctx.length = L;
  Eigen::VectorXd s_obs = obs.s;
  if (s_obs.size() != n_all || !s_obs.allFinite()) {
    Polyline p;
    p.points = obs.points;
    p.ParameteriseByChords(0.0);
    s_obs = p.s * (L / std::max(p.s[n_all - 1], 1e-12));
  }
  const double spacing = std::max(L / options.max_points, 2.0 * nominal.material.diameter);
  std::vector<int> keep;
  for (int i = 0; i < n_all; ++i)
    if (keep.empty() || s_obs[i] - s_obs[keep.back()] >= spacing) keep.push_back(i);
  ctx.points.resize(3, static_cast<int>(keep.size()));
  ctx.s.resize(static_cast<int>(keep.size()));
  for (size_t k = 0; k < keep.size(); ++k) {
    ctx.points.col(k) = obs.points.col(keep[k]);
    ctx.s[k] = s_obs[keep[k]];
  }
  const int n = static_cast<int>(keep.size());
  ctx.window = 0.1 * L + 0.02;
  ctx.curve_samples = std::max(200, static_cast<int>(L / 5e-4));

  // Starting shape: the clamps' own positions plus the recorded points.
  Polyline initial;
  {
    std::vector<std::pair<double, Vec3>> pts;
    pts.emplace_back(0.0, nominal.supports.front().position);
    for (int i = 0; i < n_all; ++i)
      if (s_obs[i] > 0.005 * L && s_obs[i] < 0.995 * L)
        pts.emplace_back(s_obs[i], obs.points.col(i));
    if (nominal.supports.back().s >= L * (1 - 1e-9))
      pts.emplace_back(L, nominal.supports.back().position);
    std::sort(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.first < b.first; });
    initial.points.resize(3, static_cast<int>(pts.size()));
    initial.s.resize(static_cast<int>(pts.size()));
    for (size_t i = 0; i < pts.size(); ++i) {
      initial.s[i] = pts[i].first;
      initial.points.col(i) = pts[i].second;
    }
  }

  // Forward model for the fits: two levels with extrapolation.
  SimulationOptions fit_opt;
  fit_opt.coarse_element_length = L / 40;
  fit_opt.min_levels = fit_opt.max_levels = 2;
  RodSimulator base(fit_opt);
  const SimulationResult nominal_fit_solution = base.Simulate(nominal, &initial);
  if (!nominal_fit_solution.converged)
    throw InvalidInput("the nominal set-up could not be solved from the recorded shape: " +
                       nominal_fit_solution.solution.summary.message);
  progress(0.05, "nominal");

  // The torque-free twist: the nominal with the far clamp released about its
  // axis.
  const int nuis = NuisanceClampIndex(nominal);
  ctx.twist_sigma = options.twist_sigma;
  if (nuis >= 0 && options.twist_sigma > 0) {
    RodSpec released = nominal;
    released.supports[static_cast<size_t>(nuis)].kind = SupportKind::kClip;
    RodSimulator sim = base;
    const SimulationResult r = sim.Simulate(released, &initial);
    if (r.converged) {
      ctx.twist_prior = true;
      ctx.twist_free = RotationAtClamp(nominal.supports[static_cast<size_t>(nuis)], r.solution);
      ctx.prior_scale = std::max(obs.noise_sigma, 1e-6);
    }
  }

  // Nuisance twist: coarse scan, then it is refined inside every model's fit.
  Eigen::VectorXd nuisance(nuis >= 0 ? 1 : 0);
  if (nuis >= 0) {
    double best = INFINITY, best_a = 0.0;
    for (int k = -12; k < 12; ++k) {
      RodSimulator sim = base;
      RodSpec s = nominal;
      const double a = k * M_PI / 12;
      ApplyNuisanceTwist(nuis, a, &s);
      Eigen::VectorXd r;
      if (Residual(ctx, &sim, s, &r) && r.squaredNorm() < best) best = r.squaredNorm(), best_a = a;
    }
    nuisance[0] = best_a;
  }
  {
    // Re-base the warm start on the nuisance-corrected nominal.
    RodSpec s = nominal;
    if (nuis >= 0) ApplyNuisanceTwist(nuis, nuisance[0], &s);
    Eigen::VectorXd r;
    RodSimulator sim = base;
    if (Residual(ctx, &sim, s, &r)) base = sim;
  }
  progress(0.1, "twist");

  std::vector<double> moments;
  for (const auto& re : nominal_fit_solution.solution.reactions)
    moments.push_back(re.moment.norm());
  std::vector<EffectModel> models = BuildEffectModels(nominal, moments);
  std::vector<Fit> fits;
  for (size_t i = 0; i < models.size(); ++i) {
    if (models[i].effect == "twist_preload") {
      if (!ctx.twist_prior) {  // without the prior it is the nuisance itself:
                               // not a candidate
        fits.emplace_back();
        continue;
      }
      models[i].starts = {nuisance};
    }
    Fit f = FitModel(ctx, base, models[i], nuisance, options.max_iterations);
    if (models[i].effect == "none" && f.ok && f.x.size()) nuisance = f.x.tail(f.x.size());
    fits.push_back(f);
    progress(0.1 + 0.8 * (i + 1) / models.size(), models[i].effect.c_str());
  }

  // Selection: BIC with the noise of the best model (floored by the recording's
  // noise).
  double best_cost = INFINITY;
  for (const Fit& f : fits)
    if (f.ok) best_cost = std::min(best_cost, f.cost);
  if (!std::isfinite(best_cost)) throw InvalidInput("no model could be fitted to the recording");
  const int dof = 2 * n;  // a point's offset from the curve has two free components
  double sigma2 = 2.0 * best_cost / std::max(1, dof - 6);
  sigma2 = std::max(sigma2, obs.noise_sigma * obs.noise_sigma);
  const double log_n = std::log(static_cast<double>(dof));
  auto bic = [&](size_t i) {
    return 2.0 * fits[i].cost / sigma2 + fits[i].prior + models[i].physical_parameters * log_n;
  };
  ShapeDiagnosis out;
  std::vector<std::pair<double, size_t>> order;
  // Best fit per effect name (clamp effects keep their best clamp).
  std::map<std::string, size_t> best_of;
  for (size_t i = 0; i < fits.size(); ++i) {
    if (!fits[i].ok) continue;
    auto it = best_of.find(models[i].effect);
    if (it == best_of.end() || bic(i) < bic(it->second)) best_of[models[i].effect] = i;
  }
  for (auto& [name, i] : best_of) order.emplace_back(bic(i), i);
  std::sort(order.begin(), order.end());
  const size_t none_index = best_of.at("none");
  const double none_bic = bic(none_index);
  size_t chosen = none_index;
  if (order.front().second != none_index && order.front().first < none_bic - options.min_bic_gain)
    chosen = order.front().second;
  double wsum = 0.0;
  for (auto& [bic, i] : order) wsum += std::exp(-0.5 * (bic - order.front().first));
  for (auto& [bic, i] : order) {
    EffectCandidate c;
    c.effect = models[i].effect;
    c.bic = bic;
    c.score = std::exp(-0.5 * (bic - order.front().first)) / wsum;
    c.parameter_count = models[i].physical_parameters;
    c.clamp = models[i].clamp;
    for (int k = 0; k < models[i].physical_parameters; ++k)
      c.parameters[models[i].names[k]] = fits[i].x[k];
    out.candidates.push_back(c);
  }
  // Final solves at full accuracy: nominal (with the fitted twist) and the
  // chosen model.
  const EffectModel& cm = models[chosen];
  const Eigen::VectorXd& cx = fits[chosen].x;
  RodSpec nominal_twisted = nominal;
  const Eigen::VectorXd& none_x = fits[none_index].x;
  // The nominal shown against the recording holds the twist the nominal fit
  // found, so that the deviation is the effect's; a twist preload is measured
  // from the torque-free hold.
  const bool preload = cm.effect == "twist_preload";
  if (nuis >= 0 && none_x.size())
    ApplyNuisanceTwist(nuis, preload && ctx.twist_prior ? ctx.twist_free : none_x[0],
                       &nominal_twisted);
  out.fitted_spec = cm.apply(cx);
  RodSimulator fine_nominal, fine_fitted;
  const SimulationResult rn = fine_nominal.Simulate(nominal_twisted, &initial);
  const SimulationResult rf = fine_fitted.Simulate(out.fitted_spec, &initial);
  out.nominal_solution = rn.solution;
  out.fitted_solution = rf.solution;
  const Eigen::VectorXd samples = UniformArcLengths(L, ctx.curve_samples);
  const CurveProjection pn = ProjectOntoCurve(SampleCenterline(rn.solution.centerline, samples),
                                              obs.points, s_obs, ctx.window);
  const CurveProjection pf = ProjectOntoCurve(SampleCenterline(rf.solution.centerline, samples),
                                              obs.points, s_obs, ctx.window);
  out.observation_s = pn.s;
  out.baseline_deviation = pn.offset.colwise().norm();
  out.fitted_deviation = pf.offset.colwise().norm();
  out.baseline_max = out.baseline_deviation.maxCoeff();
  out.baseline_rms = std::sqrt(out.baseline_deviation.squaredNorm() / n_all);
  out.fitted_max = out.fitted_deviation.maxCoeff();
  out.fitted_rms = std::sqrt(out.fitted_deviation.squaredNorm() / n_all);

  // Result in the spec's terms.
  out.effect = cm.effect;
  for (const auto& c : out.candidates)
    if (c.effect == out.effect) out.confidence = c.score;
  if (chosen == none_index) {
    // Confidence that nothing is missing: the weight of `none` against the best
    // alternative.
    const double alt = order.front().second == none_index
                           ? (order.size() > 1 ? order[1].first : INFINITY)
                           : order.front().first;
    out.confidence = 1.0 / (1.0 + std::exp(-0.5 * (alt - none_bic)));
  }
  out.clamp = cm.clamp;
  const auto mismatch = MismatchInterval(out.observation_s, out.baseline_deviation);
  std::ostringstream ex;
  const std::string improve = "; fitting it reduces the max deviation from " +
                              Mm(out.baseline_max) + " to " + Mm(out.fitted_max) + ".";
  if (cm.effect == "none") {
    out.interval.reset();
    ex << "The nominal model explains the recording within its noise (max "
          "deviation "
       << Mm(out.baseline_max) << ", rms " << Mm(out.baseline_rms) << "); no effect improves it "
       << "enough to justify its parameters.";
  } else if (cm.effect == "intrinsic_curvature") {
    const double w = std::clamp(std::abs(cx[1]), 0.01 * L, L);
    out.interval =
        std::make_pair(std::clamp(cx[0] - w / 2, 0.0, L), std::clamp(cx[0] + w / 2, 0.0, L));
    const double kappa = std::hypot(cx[2], cx[3]);
    out.parameters["curvature"] = kappa;
    out.parameters["direction"] = std::atan2(cx[3], cx[2]);
    out.parameters["total_bend_angle"] = kappa * (out.interval->second - out.interval->first);
    ex << "The cable has a natural curvature of " << Fixed(kappa, 2) << " 1/m (bend radius "
       << Fixed(kappa > 0 ? 1e3 / kappa : 0, 0)
       << " mm) between s=" << Fixed(out.interval->first, 3)
       << " m and s=" << Fixed(out.interval->second, 3)
       << " m — a set from coiling, transport or a "
       << "kink" << improve;
  } else if (cm.effect == "clamp_orientation") {
    out.interval = mismatch;
    const double angle = std::hypot(cx[0], cx[1]);
    const Frame f = Frame::FromTangentNormal(
        nominal_twisted.supports[*cm.clamp].tangent,
        nominal_twisted.supports[*cm.clamp].kind == SupportKind::kClamp
            ? nominal_twisted.supports[*cm.clamp].normal
            : nominal_twisted.supports[*cm.clamp].tangent.unitOrthogonal());
    const Vec3 axis = angle > 0 ? Vec3((cx[0] * f.d1 + cx[1] * f.d2) / angle) : Vec3(f.d1);
    out.parameters["angle"] = angle;
    out.vectors["axis"] = axis;
    ex << "The clamp at s=" << Fixed(nominal.supports[*cm.clamp].s, 3) << " m holds the cable "
       << Fixed(angle * 180 / M_PI, 1) << " deg off its nominal direction, about axis ("
       << Fixed(axis[0], 2) << ", " << Fixed(axis[1], 2) << ", " << Fixed(axis[2], 2) << ")"
       << improve;
  } else if (cm.effect == "weight_stiffness_ratio") {
    out.interval = mismatch;
    const double ratio = std::exp(cx[0]);
    out.parameters["ratio"] = ratio;
    ex << "The cable is " << (ratio > 1 ? "heavier or softer" : "lighter or stiffer")
       << " than specified: its weight-to-bending-stiffness ratio is " << Fixed(ratio, 2)
       << " times the nominal one" << improve;
  } else if (cm.effect == "anisotropic_bending") {
    out.interval = mismatch;
    const double u = std::hypot(cx[0], cx[1]);
    double ang = 0.5 * std::atan2(cx[1], cx[0]);
    if (ang < 0) ang += M_PI;
    out.parameters["ratio"] = std::exp(2 * u);
    out.parameters["principal_angle"] = ang;
    ex << "The cable bends more easily one way than the other: principal "
          "bending stiffnesses differ "
       << "by a factor " << Fixed(std::exp(2 * u), 2) << ", the stiff axis at "
       << Fixed(ang * 180 / M_PI, 0) << " deg from the normal d1" << improve;
  } else if (cm.effect == "support_contact") {
    const double sc = std::clamp(cx[0], 0.02 * L, 0.98 * L);
    const Vec3 force(cx[1], cx[2], cx[3]);
    const double half = std::max(2.0 * nominal.material.diameter, 0.01 * L);
    out.interval = std::make_pair(std::max(0.0, sc - half), std::min(L, sc + half));
    out.parameters["s"] = sc;
    out.parameters["force"] = force.norm();
    out.vectors["force_vector"] = force;
    ex << "Something the model does not have pushes the cable at s=" << Fixed(sc, 3) << " m with "
       << Fixed(force.norm() * 1e3, 1) << " mN (direction "
       << Fixed(force[0] / std::max(force.norm(), 1e-30), 2) << ", "
       << Fixed(force[1] / std::max(force.norm(), 1e-30), 2) << ", "
       << Fixed(force[2] / std::max(force.norm(), 1e-30), 2) << ")" << improve;
  } else if (cm.effect == "twist_preload") {
    out.interval = mismatch;
    const SupportSpec& clamp = nominal.supports[static_cast<size_t>(*cm.clamp)];
    const double from_case = WrapAngle(cx[0]);
    // The twist the clamp imposes against the torque-free hold when that is
    // known (the case's normal is the less reliable reference, see the method
    // above): the total twist of the fitted cable, whose torque-free state has
    // none.
    const double angle = ctx.twist_prior ? rf.solution.twist_angle : from_case;
    const double torque = rf.solution.reactions[static_cast<size_t>(*cm.clamp)].moment.dot(
        clamp.tangent.normalized());
    out.parameters["angle"] = angle;
    out.parameters["angle_from_case_normal"] = from_case;
    out.parameters["torque"] = torque;
    ex << "The clamp at s=" << Fixed(clamp.s, 3) << " m is rotated " << Fixed(angle * 180 / M_PI, 1)
       << " deg about the cable axis from a twist-free hold (" << Fixed(from_case * 180 / M_PI, 1)
       << " deg from the normal in the case): the cable carries a torque of "
       << Fixed(torque * 1e3, 2) << " mN m" << improve;
  } else if (cm.effect == "clamp_compliance") {
    out.interval = mismatch;
    const double k = std::exp(-cx[0]);
    out.parameters["stiffness"] = k;
    ex << "The clamp at s=" << Fixed(nominal.supports[*cm.clamp].s, 3)
       << " m is not rigid: it lets "
       << "the cable rotate against a rotational stiffness of about " << Fixed(k, 3) << " N m/rad"
       << improve;
  }
  if (nuis >= 0 && cx.size() > cm.physical_parameters)
    out.parameters["far_clamp_twist"] = cx[cx.size() - 1];
  out.explanation = ex.str();
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  progress(1.0, "done");
  return out;
}

}  // namespace cablefit
