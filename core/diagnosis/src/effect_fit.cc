#include "effect_fit.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"
#include "curve_projection.h"
#include "levenberg_marquardt.h"

namespace cablefit {
namespace {

// Accepted steps between difference Jacobians (each costs a forward solve per parameter).
constexpr int kBroydenUpdates = 3;

// `patient`: with the solver's continuation, for the evaluations a run cannot do without (its
// start, the fitted result); the others are Levenberg-Marquardt's trial steps, which fail fast.
bool Residual(const FitContext& ctx, RodSimulator* sim, const RodSpec& spec, Eigen::VectorXd* r,
              RodSolution* solution = nullptr, bool patient = false) {
  SimulationResult res;
  try {
    res = patient ? sim->ResimulatePatiently(spec) : sim->Resimulate(spec);
  } catch (const InvalidInput&) {
    return false;
  }
  if (!res.converged) return false;
  const Polyline curve =
      SampleCenterline(res.solution.centerline, UniformArcLengths(ctx.length, ctx.curve_samples));
  CurveProjection p = ProjectOntoCurve(curve, ctx.points, ctx.s, ctx.window);
  *r = Eigen::Map<const Eigen::VectorXd>(p.offset.data(), p.offset.size());
  if (solution) *solution = std::move(res.solution);
  return true;
}

}  // namespace

FitContext MakeFitContext(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& s,
                          double length) {
  FitContext ctx;
  ctx.points = points;
  ctx.s = s;
  ctx.length = length;
  // A tenth of the cable plus 2 cm: a point's closest point is near its own arc length, but
  // the recorded arc lengths are only approximate.
  ctx.window = 0.1 * length + 0.02;
  // Half-millimetre sampling keeps the chord error of the projection far below scan noise.
  ctx.curve_samples = std::max(200, static_cast<int>(length / 5e-4));
  return ctx;
}

double EvaluateFitCost(const FitContext& ctx, RodSimulator sim, const RodSpec& spec,
                       Eigen::VectorXd* offsets, RodSolution* solution) {
  Eigen::VectorXd r;
  if (!Residual(ctx, &sim, spec, &r, solution, /*patient=*/true)) return INFINITY;
  const double cost = 0.5 * r.squaredNorm();
  if (offsets) *offsets = std::move(r);
  return cost;
}

bool FitOffsets(const FitContext& ctx, RodSimulator* sim, const RodSpec& spec,
                Eigen::VectorXd* offsets) {
  return Residual(ctx, sim, spec, offsets);
}

FitPoint EvaluateFitPoint(const FitContext& ctx, RodSimulator sim, const EffectModel& model,
                          const Eigen::VectorXd& x) {
  FitPoint p{std::move(sim), {}, {}, 1, false};
  if (!Residual(ctx, &p.sim, model.apply(x), &p.offsets)) return p;
  // The differences are solved from a copy: the point's simulator stays warm at x itself.
  RodSimulator moving = p.sim;
  auto fn = [&](const Eigen::VectorXd& xp, Eigen::VectorXd* r) {
    return Residual(ctx, &moving, model.apply(xp), r);
  };
  LmOptions lm;
  p.ok = DifferenceJacobian(fn, x, p.offsets, model.scale, lm.relative_step, {},
                            &p.forward_solves, &p.jacobian);
  return p;
}

Fit FitEffect(const FitContext& ctx, const std::vector<RodSimulator>& bases, const EffectModel& m,
              const FitOptions& options) {
  const int max_iterations = options.max_iterations, threads = options.threads;
  struct Run {
    RodSimulator sim;
    LmResult lm;
    int branch = 0;
  };
  std::atomic<int> forward_solves{0}, lm_iterations{0};  // sums: the same on any thread count
  auto run = [&](Run* r, const Eigen::VectorXd& x0, int iterations,
                 bool patient_start = false, const LmStart* start = nullptr) {
    bool first = true;
    auto fn = [&](const Eigen::VectorXd& x, Eigen::VectorXd* res) {
      const bool patient = first && (options.patient_start || patient_start);
      first = false;
      return Residual(ctx, &r->sim, m.apply(x), res, nullptr, patient);
    };
    LmOptions opt;
    opt.max_iterations = iterations;
    opt.max_broyden_updates = kBroydenUpdates;
    r->lm = MinimiseLeastSquares(fn, x0, m.scale, opt, start);
    forward_solves += r->lm.evaluations;
    lm_iterations += r->lm.iterations;
  };
  // Many starts (interval and contact positions, anisotropy angles, clamp twists): a few
  // iterations each, then only the most promising ones are carried to convergence. Starts that
  // end in the same place are one basin: the survivors are distinct ones. Every run owns its
  // simulator, so the runs go in parallel and are collected in start order.
  const bool screen = m.starts.size() > 2;
  const bool coarse = screen && options.screen_bases != nullptr;
  const std::vector<RodSimulator>& screen_sims = coarse ? *options.screen_bases : bases;
  const int count = static_cast<int>(bases.size() * m.starts.size());
  std::vector<Run> started(static_cast<size_t>(count));
  ParallelFor(count, threads, [&](int j) {
    const size_t b = static_cast<size_t>(j) / m.starts.size();
    const int s = static_cast<int>(static_cast<size_t>(j) % m.starts.size());
    Run& r = started[static_cast<size_t>(j)];
    r = Run{screen_sims[b], {}, static_cast<int>(b)};
    std::optional<LmStart> known;
    if (options.known_start) known = options.known_start(s, &r.sim);
    run(&r, m.starts[static_cast<size_t>(s)], screen ? options.start_iterations : max_iterations,
        false, known ? &*known : nullptr);
  });
  std::vector<Run> runs;
  for (Run& r : started)
    if (r.lm.ok) runs.push_back(std::move(r));
  auto by_cost = [](const Run& a, const Run& b) { return a.lm.cost < b.lm.cost; };
  std::stable_sort(runs.begin(), runs.end(), by_cost);
  if (screen) {
    std::vector<Run> kept;
    for (Run& r : runs) {
      if (static_cast<int>(kept.size()) >= options.kept_starts) break;
      bool same = false;
      for (const Run& k : kept)
        same = same || (r.branch == k.branch &&
                        (r.lm.x - k.lm.x).cwiseQuotient(m.scale).cwiseAbs().maxCoeff() < 1.0);
      if (!same) kept.push_back(std::move(r));
    }
    runs = std::move(kept);
    ParallelFor(static_cast<int>(runs.size()), threads, [&](int j) {
      Run& r = runs[static_cast<size_t>(j)];
      const LmResult screened = r.lm;
      if (coarse) {
        // On the fine model, which the coarse one only approximates: its first solve may need
        // the continuation, and a coarse cost is no fallback for a fine one.
        r.sim = bases[static_cast<size_t>(r.branch)];
        run(&r, Eigen::VectorXd(screened.x), max_iterations, /*patient=*/true);
        return;
      }
      run(&r, Eigen::VectorXd(r.lm.x), max_iterations);
      if (!r.lm.ok || r.lm.cost > screened.cost) r.lm = screened;
    });
    if (coarse)
      runs.erase(std::remove_if(runs.begin(), runs.end(), [](const Run& r) { return !r.lm.ok; }),
                 runs.end());
    std::stable_sort(runs.begin(), runs.end(), by_cost);
  }
  // A best run stopped by its iteration limit while still descending is carried on: a fit that
  // has not reached its optimum would lose the comparison to a simpler model, or leave a
  // residual that fails the adequacy test, for a reason that is not in the recording.
  if (!runs.empty() && options.polish)
    for (int more = 0; more < 3 && !runs.front().lm.converged; ++more) {
      Run& r = runs.front();
      const LmResult before = r.lm;
      run(&r, Eigen::VectorXd(r.lm.x), max_iterations);
      if (!r.lm.ok || r.lm.cost > before.cost) {  // a run that could not start changes nothing
        r.lm = before;
        break;
      }
      if (!(r.lm.cost < (1.0 - 1e-3) * before.cost)) break;
    }
  Fit best;
  if (!runs.empty()) {
    best.x = runs.front().lm.x;
    best.cost = runs.front().lm.cost;
    best.branch = runs.front().branch;
    best.converged = runs.front().lm.converged;
    for (size_t k = 1; k < runs.size(); ++k) best.other_basins.push_back(runs[k].lm.x);
    best.ok = Residual(ctx, &runs.front().sim, m.apply(best.x), &best.offsets, &best.solution,
                       /*patient=*/true);
    if (!best.ok) best.cost = INFINITY;
    ++forward_solves;
  }
  best.forward_solves = forward_solves;
  best.lm_iterations = lm_iterations;
  return best;
}

}  // namespace cablefit
