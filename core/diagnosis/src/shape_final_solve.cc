#include "shape_final_solve.h"

#include <algorithm>
#include <cmath>

#include "cablefit/core/solver/rod_simulation.h"
#include "curve_projection.h"

namespace cablefit {

FinalSolves SolveFinal(const RodSpec& nominal, const PreparedRecording& recording,
                       const FitContext& ctx, const std::vector<EffectModel>& models,
                       const std::vector<Fit>& fits, std::size_t none_index,
                       const std::function<std::size_t(const std::vector<bool>&)>& choose) {
  FinalSolves out;
  out.rejected.assign(fits.size(), false);
  const Polyline& initial = recording.initial;
  // The nominal from the recorded shape, the chosen model from its fit's shape (the branch the
  // fit found).
  RodSimulator fine_nominal;
  const SimulationResult rn = fine_nominal.Simulate(nominal, &initial);
  const Eigen::VectorXd samples = UniformArcLengths(ctx.length, ctx.curve_samples);
  // Half the squared offsets of the thinned points from a curve (the fits' cost) [m^2].
  auto thinned_cost = [&](const Polyline& curve) {
    return 0.5 * ProjectOntoCurve(curve, ctx.points, ctx.s, ctx.window).offset.squaredNorm();
  };
  const double nominal_cost = thinned_cost(SampleCenterline(rn.solution.centerline, samples));
  // A fit whose accurate solve loses most of what it gained over the nominal (another branch, a
  // solve that failed) is not a result: it is reported and the next candidate is taken.
  std::size_t chosen = choose(out.rejected);
  SimulationResult rf;
  for (;;) {
    out.fitted_spec = models[chosen].apply(fits[chosen].x);
    const Polyline& shape = fits[chosen].solution.centerline;
    RodSimulator fine_fitted;
    rf = fine_fitted.Simulate(out.fitted_spec, shape.size() > 1 ? &shape : &initial);
    if (!rf.converged) rf = RodSimulator().Simulate(out.fitted_spec, &initial);
    if (chosen == none_index) break;
    const double gained = fits[none_index].cost - fits[chosen].cost;
    const double cost = rf.converged ? thinned_cost(SampleCenterline(rf.solution.centerline, samples))
                                     : INFINITY;
    if (cost <= nominal_cost - 0.5 * gained) break;
    out.rejected[chosen] = true;
    DiagnosisNote note;
    note.kind = DiagnosisNote::Kind::kFitDidNotHold;
    note.effect = models[chosen].effect;
    note.solved = rf.converged;
    out.notes.push_back(note);
    chosen = choose(out.rejected);
  }
  out.chosen = chosen;
  out.nominal = rn.solution;
  out.fitted = rf.solution;
  return out;
}

CurveDeviation MeasureDeviation(const PreparedRecording& recording, const FitContext& ctx,
                                const Polyline& centerline) {
  const Eigen::VectorXd samples = UniformArcLengths(ctx.length, ctx.curve_samples);
  const CurveProjection p = ProjectOntoCurve(SampleCenterline(centerline, samples),
                                             recording.observation.points, recording.s, ctx.window);
  CurveDeviation d;
  d.s = p.s;
  d.distance = p.offset.colwise().norm();
  d.max = d.distance.maxCoeff();
  d.rms = std::sqrt(d.distance.squaredNorm() / static_cast<double>(d.distance.size()));
  return d;
}

void OffsetStatistics(const Eigen::VectorXd& offsets, double* max, double* rms) {
  *max = *rms = 0.0;
  const Eigen::Index n = offsets.size() / 3;
  if (n == 0) return;
  const Eigen::Map<const Eigen::Matrix3Xd> o(offsets.data(), 3, n);
  *max = o.colwise().norm().maxCoeff();
  *rms = std::sqrt(o.squaredNorm() / static_cast<double>(n));
}

std::pair<double, double> MismatchInterval(const Eigen::VectorXd& s, const Eigen::VectorXd& dev) {
  if (s.size() == 0) return {0.0, 0.0};
  Eigen::Index imax;
  const double mx = dev.maxCoeff(&imax);
  double lo = s[imax], hi = s[imax];
  for (int i = 0; i < s.size(); ++i)
    if (dev[i] >= 0.5 * mx) lo = std::min(lo, s[i]), hi = std::max(hi, s[i]);
  return {lo, hi};
}

}  // namespace cablefit
