// Shape diagnosis. Method:
// 1. Check that the recording belongs between its clamps (an inextensible cable cannot reach
//    farther from a clamp than its length; a recording running from the last clamp to the first
//    is reversed, with a note), then simulate the nominal set-up from the recorded shape (this
//    selects the equilibrium branch). The clamp frames of the case are taken as given.
// 2. Fit every catalogue effect by Levenberg-Marquardt on the seen points (residual = offset of
//    each point from its closest point on the simulated curve), warm-starting every forward solve
//    from the last, multi-start where the problem is not convex (interval position, contact
//    position, anisotropy angle and ratio, clamp twist, every clamp).
// 3. Select by BIC with the noise estimated from the best model's residual (floored by the
//    recording's own noise): chi^2 + k ln n. `none` unless an effect wins by min_bic_gain,
//    which enters the scores as prior odds for `none`.
// 4. Test whether the best fit explains the recording at all: its residual against the
//    recording's own noise (with an allowance for errors a noise estimate misses) is a
//    chi-square with 2n - k degrees of freedom. When it exceeds the 99.9 % quantile, nothing in
//    the catalogue explains the recording and the diagnosis says so.
#include "cablefit/core/diagnosis/shape_diagnosis.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/solver_failure.h"
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
};

double WrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

bool Residual(const FitContext& ctx, RodSimulator* sim, const RodSpec& spec, Eigen::VectorXd* r,
              Polyline* shape = nullptr) {
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
  if (shape) *shape = res.solution.centerline;
  return true;
}

struct Fit {
  const EffectModel* model = nullptr;
  Eigen::VectorXd x;
  double cost = INFINITY;  // 1/2 |offsets|^2 [m^2]
  Polyline shape;          // the fitted centreline (warm start of the final solve)
  int branch = 0;          // which equilibrium of the nominal the fit started from
  bool ok = false;
};

Fit FitModel(const FitContext& ctx, const std::vector<RodSimulator>& bases, const EffectModel& m,
             int max_iterations) {
  struct Run {
    RodSimulator sim;
    LmResult lm;
    int branch = 0;
  };
  auto run = [&](Run* r, const Eigen::VectorXd& x0, int iterations) {
    auto fn = [&](const Eigen::VectorXd& x, Eigen::VectorXd* res) {
      return Residual(ctx, &r->sim, m.apply(x), res);
    };
    LmOptions opt;
    opt.max_iterations = iterations;
    r->lm = MinimiseLeastSquares(fn, x0, m.scale, opt);
  };
  // Many starts (interval and contact positions, anisotropy angles, clamp twists): a few
  // iterations each, then only the most promising ones are carried to convergence. Starts that
  // end in the same place are one basin: the survivors are distinct ones.
  const bool screen = m.starts.size() > 2;
  std::vector<Run> runs;
  for (size_t b = 0; b < bases.size(); ++b)
    for (const Eigen::VectorXd& start : m.starts) {
      Run r{bases[b], {}, static_cast<int>(b)};
      run(&r, start, screen ? 4 : max_iterations);
      if (r.lm.ok) runs.push_back(std::move(r));
    }
  auto by_cost = [](const Run& a, const Run& b) { return a.lm.cost < b.lm.cost; };
  std::sort(runs.begin(), runs.end(), by_cost);
  if (screen) {
    std::vector<Run> kept;
    for (Run& r : runs) {
      if (kept.size() >= 3) break;
      bool same = false;
      for (const Run& k : kept)
        same = same || (r.branch == k.branch &&
                        (r.lm.x - k.lm.x).cwiseQuotient(m.scale).cwiseAbs().maxCoeff() < 1.0);
      if (!same) kept.push_back(std::move(r));
    }
    runs = std::move(kept);
    for (Run& r : runs) run(&r, Eigen::VectorXd(r.lm.x), max_iterations);
    std::sort(runs.begin(), runs.end(), by_cost);
  }
  Fit best;
  best.model = &m;
  if (!runs.empty()) {
    best.x = runs.front().lm.x;
    best.cost = runs.front().lm.cost;
    best.branch = runs.front().branch;
    Eigen::VectorXd r;
    Residual(ctx, &runs.front().sim, m.apply(best.x), &r, &best.shape);
    best.ok = true;
  }
  return best;
}

// Upper 99.9 % quantile of chi-square with `dof` degrees of freedom (Wilson-Hilferty; relative
// error below 1e-3 for dof >= 10).
double ChiSquareQuantile999(double dof) {
  const double z = 3.0902, a = 2.0 / (9.0 * dof);
  return dof * std::pow(1.0 - a + z * std::sqrt(a), 3);
}

// How far the recording is from fitting between the clamps: for every clamp, the largest
// distance of a recorded point from it minus the farthest the cable could reach from it [m].
struct Reach {
  double excess = -INFINITY;  // > 0: some point is out of reach
  int clamp = 0;
  double distance = 0.0;
};
Reach ReachExcess(const RodSpec& spec, const Eigen::Matrix3Xd& pts) {
  Reach out;
  for (size_t k = 0; k < spec.supports.size(); ++k) {
    const SupportSpec& c = spec.supports[k];
    const double reach = std::max(c.s, spec.length - c.s);
    const double d = (pts.colwise() - c.position).colwise().norm().maxCoeff();
    if (d - reach > out.excess) out = {d - reach, static_cast<int>(k), d};
  }
  return out;
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
  if (!(noise_allowance >= 1.0)) return fail("noise_allowance must be >= 1");
  return true;
}

ShapeDiagnosis DiagnoseShape(const RodSpec& nominal, const ShapeObservation& recorded,
                             const ShapeDiagnosisOptions& options) {
  const auto t0 = Clock::now();
  std::string why;
  if (!options.IsValid(&why)) throw InvalidInput("diagnosis options: " + why);
  ValidateRodSpec(nominal);
  const int n_all = static_cast<int>(recorded.points.cols());
  if (n_all < 5) throw InvalidInput("the recording has only " + std::to_string(n_all) + " points");
  if (!recorded.points.allFinite()) throw InvalidInput("the recording has non-finite points");
  const double L = nominal.length;
  auto progress = [&](double f, const char* stage) {
    ReportProgress(options.progress, f, stage);
  };
  ShapeDiagnosis out;

  // Does the recording belong between these clamps? How far a point may stray beyond the
  // cable's reach: its radius, the noise, and the uncertainty of where the clamps hold it.
  const double reach_tolerance =
      nominal.material.diameter + 10.0 * recorded.noise_sigma + 0.01 * L;
  ShapeObservation obs = recorded;
  {
    const SupportSpec& c0 = nominal.supports.front();
    const SupportSpec& c1 = nominal.supports.back();
    const Vec3 first = obs.points.col(0), last = obs.points.col(n_all - 1);
    // A recording's ends lie at its end clamps (less the unseen margins); a recording listed from
    // the last clamp to the first has them swapped.
    double forward = 0.0, reverse = 0.0;
    if (c0.s <= 1e-6 * L) {
      forward += (first - c0.position).norm();
      reverse += (last - c0.position).norm();
    }
    if (nominal.supports.size() > 1 && c1.s >= (1 - 1e-6) * L &&
        (c1.position - c0.position).norm() > reach_tolerance) {
      forward += (last - c1.position).norm();
      reverse += (first - c1.position).norm();
    }
    if (forward > reach_tolerance && reverse < 0.5 * forward) {
      obs.points = recorded.points.rowwise().reverse();
      if (recorded.s.size() == n_all) obs.s = (L - recorded.s.reverse().array()).matrix();
      obs.coverage.clear();
      for (auto it = recorded.coverage.rbegin(); it != recorded.coverage.rend(); ++it)
        obs.coverage.emplace_back(L - it->second, L - it->first);
      out.notes.push_back(
          "the recording runs from the last clamp to the first (its ends are " + Mm(forward) +
          " from their clamps as listed, " + Mm(reverse) + " reversed); it was reversed");
    }
  }
  const Reach reach = ReachExcess(nominal, obs.points);
  if (reach.excess > reach_tolerance) {
    const SupportSpec& c = nominal.supports[static_cast<size_t>(reach.clamp)];
    std::ostringstream os;
    os << "the recording does not fit its set-up: a recorded point lies "
       << Fixed(reach.distance, 3) << " m from the clamp at s=" << Fixed(c.s, 3) << " m, but "
       << Fixed(std::max(c.s, L - c.s), 3)
       << " m of cable cannot reach farther; check the units (metres), the clamp positions and "
          "that the recording belongs to this case";
    throw RecordingMismatch(os.str());
  }

  // Thin the points to a spacing of about two diameters: neighbouring centre points of a scan
  // share errors, and treating them as independent would overstate the evidence.
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
    throw SolverFailure("the nominal set-up could not be solved from the recorded shape: " +
                       nominal_fit_solution.solution.summary.message);
  // Other equilibria of the nominal. A cable that sags little, or hangs near a fold, can rest in
  // another equilibrium than the one the recorded shape leads the solver to (an effect can tip
  // it over): the fits also start from the solver's own start (clamps joined smoothly, loads
  // continued) and from the recorded sag mirrored through the chord, when those settle visibly
  // elsewhere (20 noise sigmas: far beyond the recording's scatter).
  std::vector<RodSimulator> bases{base};
  std::vector<std::string> branch_names{"the recorded shape"};
  {
    std::vector<Polyline> shapes{nominal_fit_solution.solution.centerline};
    const Eigen::VectorXd at = UniformArcLengths(L, 101);
    auto try_branch = [&](const Polyline* start, const char* name) {
      RodSimulator sim(fit_opt);
      SimulationResult r;
      try {
        r = sim.Simulate(nominal, start);
      } catch (const InvalidInput&) {
        return;
      }
      if (!r.converged || !r.solution.summary.stable) return;
      const Eigen::Matrix3Xd p = SampleCenterline(r.solution.centerline, at).points;
      for (const Polyline& q : shapes)
        if ((SampleCenterline(q, at).points - p).colwise().norm().maxCoeff() <
            20.0 * obs.noise_sigma)
          return;
      shapes.push_back(r.solution.centerline);
      bases.push_back(sim);
      branch_names.push_back(name);
    };
    try_branch(nullptr, "the solver's own start");
    if (nominal.supports.size() > 1) {
      const Vec3 a = nominal.supports.front().position, b = nominal.supports.back().position;
      if ((b - a).norm() > 1e-9) {
        const Eigen::AngleAxisd half_turn(M_PI, (b - a).normalized());
        Polyline mirrored = initial;
        for (int i = 0; i < mirrored.size(); ++i)
          mirrored.points.col(i) = a + half_turn * (Vec3(initial.points.col(i)) - a);
        try_branch(&mirrored, "the recorded sag mirrored through the chord");
      }
    }
  }
  progress(0.05, "nominal");

  std::vector<double> moments;
  for (const auto& re : nominal_fit_solution.solution.reactions)
    moments.push_back(re.moment.norm());
  std::vector<EffectModel> models = BuildEffectModels(nominal, moments);
  std::vector<Fit> fits;
  for (size_t i = 0; i < models.size(); ++i) {
    fits.push_back(FitModel(ctx, bases, models[i], options.max_iterations));
    progress(0.05 + 0.85 * (i + 1) / models.size(), models[i].effect.c_str());
  }

  // Selection: BIC with the noise of the best model (floored by the recording's noise).
  double best_cost = INFINITY;
  for (size_t i = 0; i < fits.size(); ++i)
    if (fits[i].ok) best_cost = std::min(best_cost, fits[i].cost);
  if (!std::isfinite(best_cost)) throw SolverFailure("no model could be fitted to the recording");
  const int dof = 2 * n;  // a point's offset from the curve has two free components
  const double noise2 = obs.noise_sigma * obs.noise_sigma;
  double sigma2 = 2.0 * best_cost / std::max(1, dof - 6);
  sigma2 = std::max(sigma2, noise2);
  const double log_n = std::log(static_cast<double>(dof));
  auto bic = [&](size_t i) {
    return 2.0 * fits[i].cost / sigma2 + models[i].physical_parameters * log_n;
  };
  std::vector<std::pair<double, size_t>> order;
  // Best fit per effect name (clamp effects keep their best clamp).
  std::map<std::string, size_t> best_of;
  for (size_t i = 0; i < fits.size(); ++i) {
    if (!fits[i].ok) continue;
    auto it = best_of.find(models[i].effect);
    if (it == best_of.end() || bic(i) < bic(it->second)) best_of[models[i].effect] = i;
  }
  if (!best_of.count("none")) throw SolverFailure("the nominal set-up could not be re-solved");
  // The margin an effect must win by is prior odds for `none`: scores, order and choice all
  // include it, so the reported effect is always the best-scored candidate.
  auto criterion = [&](size_t i) {
    return bic(i) + (models[i].effect == "none" ? 0.0 : options.min_bic_gain);
  };
  for (auto& [name, i] : best_of) order.emplace_back(criterion(i), i);
  std::sort(order.begin(), order.end());
  const size_t none_index = best_of.at("none");
  size_t chosen = order.front().second;
  double wsum = 0.0;
  for (auto& [b, i] : order) wsum += std::exp(-0.5 * (b - order.front().first));
  for (auto& [b, i] : order) {
    EffectCandidate c;
    c.effect = models[i].effect;
    c.bic = bic(i);
    c.score = std::exp(-0.5 * (b - order.front().first)) / wsum;
    c.parameter_count = models[i].physical_parameters;
    c.clamp = models[i].clamp;
    for (int k = 0; k < models[i].physical_parameters; ++k)
      c.parameters[models[i].names[k]] = fits[i].x[k];
    out.candidates.push_back(c);
  }

  // Does anything explain the recording? The best fit's residual against the recording's own
  // noise is chi-square with 2n - k degrees of freedom when the model is right. Fits set aside
  // below (they did not hold in the accurate solve) do not count.
  std::vector<bool> rejected(fits.size(), false);
  auto assess = [&] {
    size_t best = none_index;
    for (size_t i = 0; i < fits.size(); ++i)
      if (fits[i].ok && !rejected[i] && fits[i].cost < fits[best].cost) best = i;
    ShapeAdequacy& a = out.adequacy;
    a.noise_sigma = obs.noise_sigma;
    a.best_effect = models[best].effect;
    a.points = n;
    a.degrees_of_freedom = dof - models[best].physical_parameters;
    a.noise_allowance = options.noise_allowance;
    a.chi_square =
        2.0 * fits[best].cost / (noise2 * options.noise_allowance * options.noise_allowance);
    a.limit = ChiSquareQuantile999(a.degrees_of_freedom);
    out.explained = a.chi_square <= a.limit;
  };
  assess();

  // Final solves at full accuracy: the nominal from the recorded shape, the chosen model from
  // its fit's shape (the branch the fit found).
  RodSimulator fine_nominal;
  const SimulationResult rn = fine_nominal.Simulate(nominal, &initial);
  const Eigen::VectorXd samples = UniformArcLengths(L, ctx.curve_samples);
  const Polyline nominal_curve = SampleCenterline(rn.solution.centerline, samples);
  const CurveProjection pn = ProjectOntoCurve(nominal_curve, obs.points, s_obs, ctx.window);
  // Half the squared offsets of the thinned points from a curve (the fits' cost) [m^2].
  auto thinned_cost = [&](const Polyline& curve) {
    return 0.5 * ProjectOntoCurve(curve, ctx.points, ctx.s, ctx.window).offset.squaredNorm();
  };
  const double nominal_cost = thinned_cost(nominal_curve);
  // A fit whose accurate solve loses most of what it gained over the nominal (another branch, a
  // solve that failed) is not a result: it is reported and the next candidate is taken.
  SimulationResult rf;
  for (;;) {
    out.fitted_spec = models[chosen].apply(fits[chosen].x);
    RodSimulator fine_fitted;
    rf = fine_fitted.Simulate(out.fitted_spec,
                              fits[chosen].shape.size() > 1 ? &fits[chosen].shape : &initial);
    if (!rf.converged) rf = RodSimulator().Simulate(out.fitted_spec, &initial);
    if (chosen == none_index) break;
    const double gained = fits[none_index].cost - fits[chosen].cost;
    const double cost = rf.converged ? thinned_cost(SampleCenterline(rf.solution.centerline, samples))
                                     : INFINITY;
    if (cost <= nominal_cost - 0.5 * gained) break;
    rejected[chosen] = true;
    out.notes.push_back("the " + models[chosen].effect +
                        " fit did not hold in the accurate solve (" +
                        (rf.converged ? "it gave back most of its improvement" : "not solved") +
                        "); the next candidate was taken");
    assess();
    size_t next = none_index;
    for (auto& [b, i] : order)
      if (!rejected[i]) {
        next = i;
        break;
      }
    chosen = next;
  }
  if (std::find(rejected.begin(), rejected.end(), true) != rejected.end()) {
    // Scores among the fits that held: a set-aside fit weighs nothing.
    double best_held = INFINITY, sum = 0.0;
    for (auto& [b, i] : order)
      if (!rejected[i]) best_held = std::min(best_held, b);
    for (EffectCandidate& c : out.candidates) {
      const size_t i = best_of.at(c.effect);
      c.score = rejected[i] ? 0.0 : std::exp(-0.5 * (criterion(i) - best_held));
      sum += c.score;
    }
    for (EffectCandidate& c : out.candidates) c.score /= sum;
    std::stable_sort(out.candidates.begin(), out.candidates.end(),
                     [](const EffectCandidate& a, const EffectCandidate& b) {
                       return a.score > b.score;
                     });
  }
  const EffectModel& cm = models[chosen];
  const Eigen::VectorXd& cx = fits[chosen].x;
  if (fits[chosen].branch > 0)
    out.notes.push_back("the " + cm.effect + " fit started from another equilibrium of the " +
                        "nominal set-up (solved from " +
                        branch_names[static_cast<size_t>(fits[chosen].branch)] +
                        ") than the one the recorded shape leads to");
  out.nominal_solution = rn.solution;
  out.fitted_solution = rf.solution;
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
    const SupportSpec& sp = nominal.supports[static_cast<size_t>(*cm.clamp)];
    const Frame f = Frame::FromTangentNormal(
        sp.tangent, sp.kind == SupportKind::kClamp ? sp.normal : sp.tangent.unitOrthogonal());
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
    const double angle = WrapAngle(cx[0]);
    const double torque = rf.solution.reactions[static_cast<size_t>(*cm.clamp)].moment.dot(
        clamp.tangent.normalized());
    out.parameters["angle"] = angle;
    out.parameters["torque"] = torque;
    ex << "The clamp at s=" << Fixed(clamp.s, 3) << " m is rotated " << Fixed(angle * 180 / M_PI, 1)
       << " deg about the cable axis from the normal in the case: the cable carries a torque of "
       << Fixed(torque * 1e3, 2) << " mN m" << improve;
    // For a cable that bends alike in every direction and has no natural curvature, the
    // centreline depends on the clamps' twist only through the twist between them (the twisting
    // moment is constant along it; pins and clips pass it on): with exactly two clamps that hold
    // the twist, turning the other one the opposite way gives the same shape, exactly. Which of
    // them was turned cannot be told from the shape, and the diagnosis says so.
    std::vector<int> holding;
    for (size_t k = 0; k < nominal.supports.size(); ++k)
      if (nominal.supports[k].kind == SupportKind::kClamp) holding.push_back(static_cast<int>(k));
    if (holding.size() == 2 && nominal.material.bending_ratio == 1.0 &&
        nominal.natural_curvature.empty()) {
      const int other = holding[0] == *cm.clamp ? holding[1] : holding[0];
      ex << " The shape cannot tell which clamp was turned: the clamp at s="
         << Fixed(nominal.supports[static_cast<size_t>(other)].s, 3) << " m turned "
         << Fixed(-angle * 180 / M_PI, 1)
         << " deg gives the same shape (it depends only on the twist between the clamps).";
      out.parameters["alternative_clamp"] = other;
      out.parameters["alternative_angle"] = -angle;
    }
  } else if (cm.effect == "clamp_compliance") {
    out.interval = mismatch;
    const double k = std::exp(-cx[0]);
    out.parameters["stiffness"] = k;
    ex << "The clamp at s=" << Fixed(nominal.supports[*cm.clamp].s, 3)
       << " m is not rigid: it lets "
       << "the cable rotate against a rotational stiffness of about " << Fixed(k, 3) << " N m/rad"
       << improve;
  }
  if (!out.explained) {
    // A best fit that leaves far more than the noise is not a diagnosis: say what it leaves and
    // what to check instead of a confident story.
    out.confidence = std::min(out.confidence, 0.1);
    std::ostringstream nx;
    nx << "No effect of the catalogue explains the recording: the best fit (" << cm.effect
       << ") leaves a max deviation of " << Mm(out.fitted_max) << " (rms " << Mm(out.fitted_rms)
       << ") against a noise of " << Mm(obs.noise_sigma) << " (chi-square with "
       << Fixed(options.noise_allowance, 1) << " times that noise: "
       << Fixed(out.adequacy.chi_square, 0) << " for " << out.adequacy.degrees_of_freedom
       << " degrees of freedom, 99.9 % limit " << Fixed(out.adequacy.limit, 0)
       << "). Check the set-up: the clamps (positions, directions, whether every clamp is "
          "listed), the units of the recording and that it belongs to this case. Best candidate: "
       << ex.str();
    out.explanation = nx.str();
  } else {
    // A close runner-up is part of the answer: the scores alone do not separate them.
    for (const EffectCandidate& c : out.candidates) {
      if (c.effect == out.effect || c.score < 0.25) continue;
      ex << " The recording hardly separates it from " << c.effect << " (scores "
         << Fixed(out.confidence, 2) << " and " << Fixed(c.score, 2) << ").";
      break;
    }
    out.explanation = ex.str();
  }
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  progress(1.0, "done");
  return out;
}

}  // namespace cablefit
