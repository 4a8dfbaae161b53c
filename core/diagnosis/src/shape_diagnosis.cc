// Shape diagnosis, in stages:
// 1. PrepareRecording (shape_recording): the recording checked against its clamps, reversed if
//    listed from the last clamp, thinned; the recorded shape is the nominal solve's start.
// 2. SolveNominalBranches (shape_nominal): the nominal set-up for the fits, from the recorded
//    shape (this selects the equilibrium branch) and from starts that settle elsewhere.
// 3. FitEffect (effect_fit) for every model of the catalogue (shape_effects): Levenberg-Marquardt
//    on the seen points, screening many starts where the problem is not convex.
// 4. SearchEffectPairs (effect_pair_search), when the best single fit leaves more than the
//    recording's noise: every allowed pair screened on the coarse level from many starts, the
//    best few fitted jointly on the fine model.
// 5. RankModels (model_selection): BIC with the noise estimated from the best model's residual
//    (floored by the recording's own noise); `none` unless an effect wins by min_bic_gain. The
//    best fit's residual against the recording's noise tells whether anything explains it.
// 6. SolveFinal (shape_final_solve): nominal and chosen model at full accuracy, the next
//    candidate when a fit does not hold there; deviations; each candidate described in the
//    catalogue's terms by its model's `describe`; the chosen model's effects, each with its
//    share of the mismatch (found_effects).
#include "cablefit/core/diagnosis/shape_diagnosis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/solver_failure.h"
#include "effect_fit.h"
#include "effect_pair_search.h"
#include "found_effects.h"
#include "model_selection.h"
#include "placed_part_relocation.h"
#include "shape_effects.h"
#include "shape_final_solve.h"
#include "shape_nominal.h"
#include "shape_recording.h"

namespace cablefit {
namespace {

using Clock = std::chrono::steady_clock;

// Fits of one group compete for one candidate: an effect at any clamp, a pair of effects (in
// either order, at any clamps).
int GroupOf(const std::vector<EffectModel>& models, const EffectModel& m) {
  if (!m.is_combination()) return static_cast<int>(m.effect);
  int a = static_cast<int>(models[static_cast<size_t>(m.parts[0])].effect);
  int b = static_cast<int>(models[static_cast<size_t>(m.parts[1])].effect);
  if (a > b) std::swap(a, b);
  return 1000 + 100 * a + b;
}

std::vector<internal::ModelFit> SelectionInput(const std::vector<EffectModel>& models,
                                               const std::vector<Fit>& fits) {
  std::vector<internal::ModelFit> in;
  for (size_t i = 0; i < fits.size(); ++i) {
    internal::ModelFit m;
    m.group = GroupOf(models, models[i]);
    m.parameters = models[i].physical_parameters;
    m.cost = fits[i].cost;
    m.ok = fits[i].ok;
    m.effects = models[i].is_combination() ? static_cast<int>(models[i].parts.size())
                : models[i].effect == ShapeEffect::kNone ? 0
                                                          : 1;
    in.push_back(m);
  }
  return in;
}

// Whether the best fit that held explains the recording (see model_selection.h).
ShapeAdequacy Assess(const std::vector<EffectModel>& models, const std::vector<Fit>& fits,
                     const std::vector<bool>& rejected, size_t none_index, int points,
                     double noise_sigma, double noise_allowance) {
  size_t best = none_index;
  for (size_t i = 0; i < fits.size(); ++i)
    if (fits[i].ok && !rejected[i] && fits[i].cost < fits[best].cost) best = i;
  ShapeAdequacy a;
  a.noise_sigma = noise_sigma;
  a.best_effect = models[best].effect;
  a.points = points;
  a.degrees_of_freedom = 2 * points - models[best].physical_parameters;
  a.noise_allowance = noise_allowance;
  const internal::AdequacyTest t =
      internal::TestAdequacy(fits[best].cost, a.degrees_of_freedom, noise_sigma, noise_allowance);
  a.chi_square = t.chi_square;
  a.limit = t.limit;
  return a;
}

// Whether the best fit of the model lists leaves more than `allowance` times the recording's
// noise; `residual` receives its rms offset component over the noise.
bool LeavesMoreThanNoise(
    std::initializer_list<std::pair<const std::vector<EffectModel>*, const std::vector<Fit>*>> lists,
    int points, double noise_sigma, double allowance, double* residual) {
  const EffectModel* model = nullptr;
  const Fit* best = nullptr;
  for (const auto& [models, fits] : lists)
    for (size_t i = 0; i < fits->size(); ++i)
      if ((*fits)[i].ok && (!best || (*fits)[i].cost < best->cost)) {
        best = &(*fits)[i];
        model = &(*models)[i];
      }
  if (!best) return false;
  const int dof = 2 * points - model->physical_parameters;
  *residual = std::sqrt(2.0 * best->cost / std::max(1, dof)) / noise_sigma;
  if (!(allowance > 0)) return false;
  return !internal::TestAdequacy(best->cost, dof, noise_sigma, allowance).passed;
}

// Whether the best single model leaves more than `allowance` times the recording's noise, so
// that a second effect could have something to explain; `residual` receives its rms offset
// component over the noise.
bool NeedsPairSearch(const std::vector<EffectModel>& models, const std::vector<Fit>& fits,
                     int points, double noise_sigma, double allowance, double* residual) {
  return LeavesMoreThanNoise({{&models, &fits}}, points, noise_sigma, allowance, residual);
}

EffectCandidate Candidate(const EffectModel& model, const Fit& fit,
                          const internal::RankedModel& rank,
                          const EffectDescriptionContext& context) {
  EffectCandidate c;
  c.effect = model.effect;
  c.bic = rank.bic;
  c.score = rank.score;
  c.parameter_count = model.physical_parameters;
  c.clamp = model.clamp;
  c.converged = fit.converged;
  OffsetStatistics(fit.offsets, &c.max_deviation, &c.rms_deviation);
  EffectDescription d = model.describe(fit.x, context);
  c.parameters = std::move(d.parameters);
  c.vectors = std::move(d.vectors);
  c.interval = d.interval;
  return c;
}

CombinationCandidate Combination(const std::vector<EffectModel>& models, const Fit& fit,
                                 const internal::RankedModel& rank) {
  const EffectModel& m = models[rank.fit];
  CombinationCandidate c;
  for (int part : m.parts) {
    c.effects.push_back(models[static_cast<size_t>(part)].effect);
    c.clamps.push_back(models[static_cast<size_t>(part)].clamp);
  }
  c.score = rank.score;
  c.bic = rank.bic;
  c.parameter_count = m.physical_parameters;
  c.converged = fit.converged;
  OffsetStatistics(fit.offsets, &c.max_deviation, &c.rms_deviation);
  return c;
}

// The selection over the fits, asked again when a fit is set aside.
class Selection {
 public:
  Selection(const std::vector<EffectModel>& models, const std::vector<Fit>& fits, int points,
            double noise_sigma, double min_bic_gain)
      : input_(SelectionInput(models, fits)),
        residuals_(2 * points),  // a point's offset from the curve has two free components
        noise_sigma_(noise_sigma),
        min_bic_gain_(min_bic_gain) {
    const internal::ModelRanking first = Rank({});
    if (first.ranked.empty()) throw SolverFailure("no model could be fitted to the recording");
    const auto none = std::find_if(first.ranked.begin(), first.ranked.end(), [&](auto& r) {
      return models[r.fit].effect == ShapeEffect::kNone;
    });
    if (none == first.ranked.end()) throw SolverFailure("the nominal set-up could not be re-solved");
    none_index_ = none->fit;
  }
  internal::ModelRanking Rank(const std::vector<bool>& rejected) const {
    return internal::RankModels(input_, residuals_, noise_sigma_, min_bic_gain_, rejected);
  }
  size_t Best(const std::vector<bool>& rejected) const { return Rank(rejected).ranked.front().fit; }
  size_t none_index() const { return none_index_; }

 private:
  std::vector<internal::ModelFit> input_;
  int residuals_;
  double noise_sigma_, min_bic_gain_;
  size_t none_index_ = 0;
};

// The result in the catalogue's terms: deviations from nominal and chosen model on every seen
// point, every candidate described by its model (the chosen one from its accurate solve).
void DescribeResult(const PreparedRecording& rec, const FitContext& ctx,
                    const std::vector<EffectModel>& models, const std::vector<Fit>& fits,
                    const internal::ModelRanking& ranking, const FinalSolves& final_solves,
                    ShapeDiagnosis* out) {
  const size_t chosen = final_solves.chosen;
  out->fitted_spec = final_solves.fitted_spec;
  out->nominal_solution = final_solves.nominal;
  out->fitted_solution = final_solves.fitted;
  const CurveDeviation baseline = MeasureDeviation(rec, ctx, out->nominal_solution.centerline);
  const CurveDeviation fitted = MeasureDeviation(rec, ctx, out->fitted_solution.centerline);
  out->observation_s = baseline.s;
  out->baseline_deviation = baseline.distance;
  out->fitted_deviation = fitted.distance;
  out->baseline_max = baseline.max;
  out->baseline_rms = baseline.rms;
  out->fitted_max = fitted.max;
  out->fitted_rms = fitted.rms;

  EffectDescriptionContext context;
  context.mismatch = MismatchInterval(out->observation_s, out->baseline_deviation);
  for (const internal::RankedModel& r : ranking.ranked) {
    if (r.fit == chosen) out->confidence = r.score;
    if (models[r.fit].is_combination()) {
      out->combinations.push_back(Combination(models, fits[r.fit], r));
      continue;
    }
    context.solution = r.fit == chosen ? &out->fitted_solution : &fits[r.fit].solution;
    out->candidates.push_back(Candidate(models[r.fit], fits[r.fit], r, context));
  }
  out->effects = DescribeFoundEffects(rec, ctx, models, chosen, fits[chosen].x, final_solves,
                                      context.mismatch);
  if (out->effects.empty()) return;
  FoundEffect dominant = out->effects.front();
  out->effect = dominant.effect;
  out->clamp = dominant.clamp;
  out->parameters = std::move(dominant.parameters);
  out->vectors = std::move(dominant.vectors);
  out->units = std::move(dominant.units);
  out->interval = dominant.interval;
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
  if (threads < 1) return fail("threads must be >= 1");
  if (!(pair_search_allowance >= 0)) return fail("pair_search_allowance must be >= 0");
  return true;
}

ShapeDiagnosis DiagnoseShape(const RodSpec& nominal, const ShapeObservation& recorded,
                             const ShapeDiagnosisOptions& options) {
  const auto t0 = Clock::now();
  std::string why;
  if (!options.IsValid(&why)) throw UsageError("diagnosis options: " + why);
  ValidateRodSpec(nominal);
  auto progress = [&](double f, const char* stage) {
    ReportProgress(options.progress, f, stage);
  };
  ShapeDiagnosis out;

  auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  auto stage = Clock::now();
  const PreparedRecording rec = PrepareRecording(nominal, recorded, options.max_points);
  out.notes = rec.notes;
  const FitContext ctx = MakeFitContext(rec.fit_points, rec.fit_s, nominal.length);
  const int n = static_cast<int>(rec.fit_s.size());
  const double noise_sigma = rec.observation.noise_sigma;

  out.cost.recording_seconds = since(stage);
  stage = Clock::now();
  const NominalBranches branches = SolveNominalBranches(nominal, rec);
  out.cost.nominal_seconds = since(stage);
  stage = Clock::now();
  progress(0.05, "nominal");

  std::vector<EffectModel> models =
      BuildEffectModels(nominal, branches.reaction_moment, ctx.points, ctx.s);
  std::vector<Fit> fits;
  for (size_t i = 0; i < models.size(); ++i) {
    FitOptions fo{options.max_iterations, options.threads, true, true};
    fo.screen_bases = &branches.coarse;
    fits.push_back(FitEffect(ctx, branches.bases, models[i], fo));
    progress(0.05 + 0.55 * (i + 1) / models.size(), ToString(models[i].effect));
    out.cost.forward_solves += fits.back().forward_solves;
    out.cost.lm_iterations += fits.back().lm_iterations;
  }
  out.cost.fits_seconds = since(stage);
  stage = Clock::now();

  double single_residual = 0.0;
  const bool search_pairs = NeedsPairSearch(models, fits, n, noise_sigma,
                                            options.pair_search_allowance, &single_residual);
  if (search_pairs) {
    PairSearchOptions po;
    po.max_iterations = options.max_iterations;
    po.threads = options.threads;
    PairSearch pairs = SearchEffectPairs(ctx, branches.bases, branches.coarse, nominal, models,
                                         fits, po);
    double pair_residual = 0.0;
    if (LeavesMoreThanNoise({{&models, &fits}, {&pairs.models, &pairs.fits}}, n, noise_sigma,
                            options.noise_allowance, &pair_residual))
      DeepenPairSearch(ctx, branches.bases, branches.coarse, &pairs, po);
    // A contact moved to where its share of the residual says it belongs is shared with the
    // best pair's rivals too.
    RelocatePlacedParts(ctx, branches.bases, branches.coarse, models, &pairs, po);
    SharePartsOfTheBest(ctx, branches.bases, models, &pairs, po);
    CheckPartsAlone(ctx, branches.bases, models, &pairs, &fits, po);
    out.cost.forward_solves += pairs.forward_solves;
    out.cost.lm_iterations += pairs.lm_iterations;
    for (size_t i = 0; i < pairs.models.size(); ++i) {
      models.push_back(std::move(pairs.models[i]));
      fits.push_back(std::move(pairs.fits[i]));
    }
  }
  out.cost.pairs_seconds = since(stage);
  progress(0.9, "pairs");
  stage = Clock::now();

  const Selection selection(models, fits, n, noise_sigma, options.min_bic_gain);
  const FinalSolves final_solves =
      SolveFinal(nominal, rec, ctx, models, fits, selection.none_index(),
                 [&](const std::vector<bool>& rejected) { return selection.Best(rejected); });
  const size_t chosen = final_solves.chosen;
  out.adequacy = Assess(models, fits, final_solves.rejected, selection.none_index(), n,
                        noise_sigma, options.noise_allowance);
  out.adequacy.single_residual = single_residual;
  out.adequacy.pairs_searched = search_pairs;
  out.explained = out.adequacy.chi_square <= out.adequacy.limit;
  out.notes.insert(out.notes.end(), final_solves.notes.begin(), final_solves.notes.end());
  if (fits[chosen].branch > 0) {
    DiagnosisNote note;
    note.kind = DiagnosisNote::Kind::kFitFromOtherEquilibrium;
    note.effect = models[chosen].effect;
    note.start = branches.starts[static_cast<size_t>(fits[chosen].branch)];
    out.notes.push_back(note);
  }

  DescribeResult(rec, ctx, models, fits, selection.Rank(final_solves.rejected), final_solves,
                 &out);
  out.cost.final_seconds = since(stage);
  // A best fit that leaves far more than the noise is not a diagnosis.
  if (!out.explained) out.confidence = std::min(out.confidence, 0.1);
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  progress(1.0, "done");
  return out;
}

}  // namespace cablefit
