#include "shape_nominal.h"

#include <Eigen/Geometry>
#include <cmath>

#include "cablefit/core/base/solver_failure.h"
#include "cablefit/core/base/errors.h"

namespace cablefit {

namespace {
constexpr int kFitWarmIterations = 30;
}  // namespace

SimulationOptions FitSimulationOptions(const RodSpec& nominal) {
  SimulationOptions fit_opt;
  fit_opt.coarse_element_length = nominal.length / 40;
  fit_opt.min_levels = fit_opt.max_levels = 2;
  // Warm re-solves: a direct Newton solve only (no continuation, no load ramp), and a limit
  // far above the 2-6 iterations a fit's step usually takes. A failed step costs the fit one
  // cheap evaluation and a smaller step, instead of seconds of continuation.
  StaticsOptions warm = fit_opt.statics;
  warm.max_iterations = kFitWarmIterations;
  warm.max_continuation_steps = 0;
  warm.ramp_loads = true;
  fit_opt.resimulate_statics = warm;
  return fit_opt;
}

SimulationOptions ScreenSimulationOptions(const RodSpec& nominal) {
  SimulationOptions o = FitSimulationOptions(nominal);
  o.min_levels = o.max_levels = 1;
  return o;
}

NominalBranches SolveNominalBranches(const RodSpec& nominal, const PreparedRecording& recording) {
  const SimulationOptions fit_opt = FitSimulationOptions(nominal);
  const double L = nominal.length;
  const Polyline& initial = recording.initial;
  RodSimulator base(fit_opt);
  const SimulationResult nominal_fit_solution = base.Simulate(nominal, &initial);
  if (!nominal_fit_solution.converged)
    throw SolverFailure("the nominal set-up could not be solved from the recorded shape: " +
                       nominal_fit_solution.solution.summary.message);
  NominalBranches out;
  for (const auto& re : nominal_fit_solution.solution.reactions)
    out.reaction_moment.push_back(re.moment.norm());
  // Other equilibria of the nominal. A cable that sags little, or hangs near a fold, can rest in
  // another equilibrium than the one the recorded shape leads the solver to (an effect can tip
  // it over): the fits also start from the solver's own start (clamps joined smoothly, loads
  // continued) and from the recorded sag mirrored through the chord, when those settle visibly
  // elsewhere (20 noise sigmas: far beyond the recording's scatter).
  out.bases = {base};
  out.starts = {NominalStart::kRecordedShape};
  // The coarse twin of each equilibrium, solved from the fine one's shape; the fine one itself
  // where the coarse level alone does not settle there.
  auto add_coarse = [&](const Polyline& shape, const RodSimulator& fine) {
    RodSimulator coarse(ScreenSimulationOptions(nominal));
    bool settled = false;
    try {
      settled = coarse.Simulate(nominal, &shape).converged;
    } catch (const InvalidInput&) {
    }
    out.coarse.push_back(settled ? coarse : fine);
  };
  add_coarse(nominal_fit_solution.solution.centerline, base);
  std::vector<Polyline> shapes{nominal_fit_solution.solution.centerline};
  const Eigen::VectorXd at = UniformArcLengths(L, 101);
  const double noise_sigma = recording.observation.noise_sigma;
  auto try_branch = [&](const Polyline* start, NominalStart how) {
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
      if ((SampleCenterline(q, at).points - p).colwise().norm().maxCoeff() < 20.0 * noise_sigma)
        return;
    shapes.push_back(r.solution.centerline);
    out.bases.push_back(sim);
    out.starts.push_back(how);
    add_coarse(r.solution.centerline, sim);
  };
  try_branch(nullptr, NominalStart::kSolverStart);
  if (nominal.supports.size() > 1) {
    const Vec3 a = nominal.supports.front().position, b = nominal.supports.back().position;
    if ((b - a).norm() > 1e-9) {
      const Eigen::AngleAxisd half_turn(M_PI, (b - a).normalized());
      Polyline mirrored = initial;
      for (int i = 0; i < mirrored.size(); ++i)
        mirrored.points.col(i) = a + half_turn * (Vec3(initial.points.col(i)) - a);
      try_branch(&mirrored, NominalStart::kMirroredSag);
    }
  }
  return out;
}

}  // namespace cablefit
