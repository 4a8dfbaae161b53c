#include "cablefit/core/diagnosis/harness_diagnosis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <string>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"
#include "cablefit/core/base/solver_failure.h"
#include "harness_effects.h"
#include "harness_fit.h"
#include "model_selection.h"

namespace cablefit {
namespace {

using internal::BranchPoints;
using internal::HarnessEffectModel;
using internal::HarnessFit;

constexpr const char* kNames[] = {"none",           "junction_position", "junction_compliance",
                                  "clip_position",  "clip_orientation",  "branch_stiffness",
                                  "branch_density", "branch_curvature",  "support_contact"};

// Every n-th point so that at most `max` remain, the ends kept.
BranchPoints Thinned(const ShapeObservation& o, int max) {
  BranchPoints p;
  const int n = static_cast<int>(o.points.cols());
  const int m = std::min(n, std::max(max, 2));
  p.points.resize(3, m);
  p.s.resize(m);
  for (int k = 0; k < m; ++k) {
    const int i = m == 1 ? 0 : static_cast<int>(std::lround(static_cast<double>(k) * (n - 1) / (m - 1)));
    p.points.col(k) = o.points.col(i);
    p.s[k] = o.s.size() == n ? o.s[i] : 0.0;
  }
  return p;
}

// Per branch, the offsets' lengths [m] from a weighted residual.
std::vector<Eigen::VectorXd> OffsetLengths(const Eigen::VectorXd& r, const std::vector<BranchPoints>& pts) {
  std::vector<Eigen::VectorXd> out;
  int at = 0;
  for (const BranchPoints& p : pts) {
    const int n = static_cast<int>(p.points.cols());
    Eigen::VectorXd d(n);
    for (int i = 0; i < n; ++i) d[i] = r.segment<3>(at + 3 * i).norm() / p.weight[i];
    at += 3 * n;
    out.push_back(d);
  }
  return out;
}

// Where a branch's offsets stand out: the stretch around the largest one where they stay above
// half of it and three noise sigmas.
std::optional<std::pair<double, double>> MismatchSpan(const Eigen::VectorXd& d, const Eigen::VectorXd& s,
                                                      double sigma) {
  if (d.size() == 0) return std::nullopt;
  Eigen::Index top = 0;
  const double largest = d.maxCoeff(&top);
  const double floor = std::max(0.5 * largest, 3.0 * sigma);
  if (largest <= floor && largest <= 3.0 * sigma) return std::nullopt;
  Eigen::Index a = top, b = top;
  while (a > 0 && d[a - 1] >= floor) --a;
  while (b + 1 < d.size() && d[b + 1] >= floor) ++b;
  return std::make_pair(std::min(s[a], s[b]), std::max(s[a], s[b]));
}

// How many times a chi-square gain must be discounted because the residual left by the best
// fit is smooth along the branches: neighbouring points then repeat one error, not two
// independent ones (an AR(1) process with the lag-one correlation rho has a variance of its
// mean (1 + rho) / (1 - rho) times that of white noise). A recording that the fit leaves at its
// noise gives rho near 0 and changes nothing.
double CorrelationInflation(const Eigen::VectorXd& r, const std::vector<BranchPoints>& pts) {
  double lagged = 0.0, total = 0.0;
  int at = 0;
  for (const BranchPoints& p : pts) {
    const int n = static_cast<int>(p.points.cols());
    for (int i = 0; i < n; ++i) {
      total += r.segment<3>(at + 3 * i).squaredNorm();
      if (i + 1 < n) lagged += r.segment<3>(at + 3 * i).dot(r.segment<3>(at + 3 * i + 3));
    }
    at += 3 * n;
  }
  const double rho = total > 0 ? std::clamp(lagged / total, 0.0, 0.95) : 0.0;
  return (1.0 + rho) / (1.0 - rho);
}

// The forward model's own error may be at most this part of the mismatch it is asked to
// explain [-]: below a half, the effect's signature still dominates what the fits see.
constexpr double kResolvedFraction = 0.5;
// How many times the elements may be halved to resolve the nominal (each doubles every solve).
constexpr int kMaxRefinements = 1;

std::string Format3(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// The rms per component of a weighted residual, in millimetres, as text.
std::string Millimetres(const Eigen::VectorXd& r, const std::vector<BranchPoints>& pts) {
  double sum = 0.0;
  int components = 0;
  for (const Eigen::VectorXd& d : OffsetLengths(r, pts)) {
    sum += d.squaredNorm();
    components += 2 * static_cast<int>(d.size());
  }
  return Format3(1e3 * std::sqrt(sum / std::max(1, components)));
}

struct Fitted {
  HarnessEffectModel model;
  HarnessFit fit;
  int parameters = 0;
  double bic = 0.0;
};

// `cost` is in units of each point's own sigma; `scale` the best fit's residual variance in
// those units, floored at 1 (a fit cannot be better than the recording), times its correlation
// inflation: an error common to every model (a biased centre line, a scan split, a truth solved
// otherwise) then does not make small gains significant.
double Bic(double cost, int parameters, int components, double scale) {
  return 2.0 * cost / scale + parameters * std::log(std::max(components, 1));
}

}  // namespace

const char* ToString(HarnessEffect effect) { return kNames[static_cast<int>(effect)]; }

std::optional<HarnessEffect> HarnessEffectFromString(std::string_view name) {
  for (int i = 0; i < static_cast<int>(std::size(kNames)); ++i)
    if (name == kNames[i]) return static_cast<HarnessEffect>(i);
  return std::nullopt;
}

// Long because it is one recipe over shared state (points, noise, the nominal residual):
// nominal, deviations, screening, single fits, pairs, selection, shares and the fitted shapes.
HarnessDiagnosis DiagnoseHarness(const NetworkSpec& nominal, const HarnessObservation& observation,
                                 const HarnessDiagnosisOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const size_t nb = nominal.branches.size();
  if (observation.branches.size() != nb)
    throw InvalidInput("the recording has " + std::to_string(observation.branches.size()) +
                       " branches, the harness " + std::to_string(nb));
  std::vector<BranchPoints> pts;
  std::vector<double> sigmas;
  int observed = 0;
  double total_length = 0.0;
  for (size_t b = 0; b < nb; ++b) {
    const ShapeObservation& o = observation.branches[b];
    total_length += nominal.branches[b].length;
    if (o.points.cols() == 0) {
      pts.push_back({});
      continue;
    }
    pts.push_back(Thinned(o, options.max_points_per_branch));
    observed += static_cast<int>(pts.back().points.cols());
    sigmas.push_back(o.noise_sigma);
  }
  if (observed == 0) throw InvalidInput("nothing of the harness was recorded");
  std::nth_element(sigmas.begin(), sigmas.begin() + static_cast<long>(sigmas.size() / 2), sigmas.end());
  const double sigma = std::max(1e-6, sigmas[sigmas.size() / 2]);
  double h = options.element_length > 0 ? options.element_length : total_length / 600.0;

  HarnessDiagnosis out;
  out.noise_sigma = sigma;
  int solves = 0;
  // Each point's weight: the recording's noise and the forward model's own error there, from
  // the nominal on elements half as long (second order: the error is 4/3 of the change). Where
  // that error is not small against the mismatch (a contact that settles elsewhere on a finer
  // mesh), the elements are halved, up to kMaxRefinements times, unless the caller fixed them.
  std::unique_ptr<internal::HarnessResidual> nominal_residual;
  Eigen::VectorXd r0;
  for (int level = 0;; ++level) {
    for (BranchPoints& p : pts) p.weight = Eigen::VectorXd::Constant(p.points.cols(), 1.0 / sigma);
    nominal_residual = std::make_unique<internal::HarnessResidual>(nominal, pts, h);
    internal::HarnessResidual finer(nominal, pts, 0.5 * h);
    Eigen::VectorXd r_fine;
    std::vector<Polyline> fine_shapes;
    if (!nominal_residual->Evaluate(nullptr, Eigen::VectorXd(), &r0, &out.nominal) ||
        !finer.Evaluate(nullptr, Eigen::VectorXd(), &r_fine, &fine_shapes))
      throw SolverFailure("the nominal harness could not be solved");
    solves += nominal_residual->solves() + finer.solves();
    const std::vector<Eigen::Matrix3Xd> coarse = internal::PointOffsets(pts, out.nominal);
    const std::vector<Eigen::Matrix3Xd> fine = internal::PointOffsets(pts, fine_shapes);
    out.model_error = 0.0;
    double mismatch = 0.0;
    for (size_t b = 0; b < pts.size(); ++b)
      for (Eigen::Index i = 0; i < pts[b].points.cols(); ++i) {
        const double e = 4.0 / 3.0 * (coarse[b].col(i) - fine[b].col(i)).norm();
        out.model_error = std::max(out.model_error, e);
        mismatch = std::max(mismatch, coarse[b].col(i).norm());
        pts[b].weight[i] = 1.0 / std::sqrt(sigma * sigma + e * e);
      }
    r0 = nominal_residual->Offsets(out.nominal);
    if (out.model_error <= kResolvedFraction * mismatch || level == kMaxRefinements ||
        options.element_length > 0)
      break;
    h *= 0.5;
  }
  out.element_length = h;
  const int components = 2 * observed;  // across the cable: two per point
  const double cost0 = 0.5 * r0.squaredNorm();

  // The mismatch, branch by branch, and where it points.
  const std::vector<Eigen::VectorXd> d0 = OffsetLengths(r0, pts);
  internal::MismatchHints hints;
  out.branches.resize(nb);
  for (size_t b = 0; b < nb; ++b) {
    HarnessBranchDeviation& dev = out.branches[b];
    const Eigen::VectorXd& d = d0[b];
    hints.max_s.push_back(0.5 * nominal.branches[b].length);
    hints.rms.push_back(0.0);
    dev.points = static_cast<int>(d.size());
    dev.s = pts[b].s;
    dev.nominal_offset = d;
    if (d.size() == 0) continue;
    Eigen::Index top = 0;
    dev.nominal_max = d.maxCoeff(&top);
    dev.nominal_rms = std::sqrt(d.squaredNorm() / static_cast<double>(d.size()));
    dev.nominal_max_s = pts[b].s[top];
    dev.mismatch = MismatchSpan(d, pts[b].s, sigma);
    hints.max_s.back() = dev.nominal_max_s;
    hints.rms.back() = dev.nominal_rms;
    out.baseline_max = std::max(out.baseline_max, dev.nominal_max);
  }

  // Every model at every place, screened by its linearised fit from where the mismatch points;
  // the best carried to a full fit.
  const std::vector<HarnessEffectModel> models =
      internal::BuildHarnessEffectModels(nominal, nominal_residual->last(), hints);
  std::vector<internal::HarnessScreen> screens(models.size());
  ParallelFor(static_cast<int>(models.size()), options.threads, [&](int i) {
    screens[static_cast<size_t>(i)] = internal::ScreenHarnessModel(models[static_cast<size_t>(i)], r0, nominal,
                                                                   pts, h);
  });
  for (const internal::HarnessScreen& s : screens) solves += s.solves;
  std::vector<int> order(models.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return screens[static_cast<size_t>(a)].predicted_cost < screens[static_cast<size_t>(b)].predicted_cost;
  });
  order.resize(std::min(order.size(), static_cast<size_t>(std::max(options.fitted_singles, 1))));
  std::vector<Fitted> singles(order.size());
  ParallelFor(static_cast<int>(order.size()), options.threads, [&](int k) {
    const size_t i = static_cast<size_t>(order[static_cast<size_t>(k)]);
    Fitted& f = singles[static_cast<size_t>(k)];
    f.model = models[i];
    f.fit = internal::FitHarnessModel(models[i], screens[i].start, nominal, pts, h,
                                      options.max_iterations);
    f.parameters = static_cast<int>(models[i].x0.size());
  });
  for (const Fitted& f : singles) solves += f.fit.solves;
  std::vector<Fitted> fitted;
  for (Fitted& f : singles)
    if (f.fit.ok) fitted.push_back(std::move(f));
  for (Fitted& f : fitted) f.bic = Bic(f.fit.cost, f.parameters, components, 1.0);
  std::stable_sort(fitted.begin(), fitted.end(),
                   [](const Fitted& a, const Fitted& b) { return a.bic < b.bic; });

  // Pairs of the best singles, each started from both single fits, when the best single does
  // not explain the recording already.
  const double best_single_rms =
      fitted.empty() ? std::sqrt(2.0 * cost0 / std::max(1, components))
                     : std::sqrt(2.0 * fitted.front().fit.cost / std::max(1, components));
  const bool search_pairs = best_single_rms > options.pair_search_allowance;
  const size_t paired =
      search_pairs ? std::min(fitted.size(), static_cast<size_t>(std::max(options.paired_singles, 0))) : 0;
  std::vector<std::pair<size_t, size_t>> pair_index;
  for (size_t a = 0; a < paired; ++a)
    for (size_t b = a + 1; b < paired; ++b)
      if (fitted[a].model.label != fitted[b].model.label) pair_index.emplace_back(a, b);
  std::vector<Fitted> pairs(pair_index.size());
  ParallelFor(static_cast<int>(pair_index.size()), options.threads, [&](int k) {
    const auto [a, b] = pair_index[static_cast<size_t>(k)];
    Fitted& f = pairs[static_cast<size_t>(k)];
    f.model = internal::CombineHarnessModels(fitted[a].model, fitted[b].model);
    Eigen::VectorXd start(f.model.x0.size());
    start << fitted[a].fit.x, fitted[b].fit.x;
    f.fit = internal::FitHarnessModel(f.model, start, nominal, pts, h, options.max_iterations);
    f.parameters = static_cast<int>(start.size());
  });
  for (Fitted& f : pairs) {
    solves += f.fit.solves;
    if (f.fit.ok) fitted.push_back(std::move(f));
  }

  // Selection: a model with more effects must beat the best with fewer by the margin.
  const Fitted* best_fit = nullptr;
  for (const Fitted& f : fitted)
    if (!best_fit || f.fit.cost < best_fit->fit.cost) best_fit = &f;
  const Eigen::VectorXd& best_r = best_fit && best_fit->fit.cost < cost0 ? best_fit->fit.residual : r0;
  const double scale = std::max(1.0, best_r.squaredNorm() / std::max(1, components)) *
                       CorrelationInflation(best_r, pts);
  for (Fitted& f : fitted) f.bic = Bic(f.fit.cost, f.parameters, components, scale);
  const double bic_none = Bic(cost0, 0, components, scale);
  const Fitted* best_single = nullptr;
  const Fitted* best_pair = nullptr;
  for (const Fitted& f : fitted) {
    const bool pair = !f.model.parts.empty();
    const Fitted*& best = pair ? best_pair : best_single;
    if (!best || f.bic < best->bic) best = &f;
  }
  const Fitted* chosen = nullptr;
  double chosen_bic = bic_none;
  if (best_single && best_single->bic < bic_none - options.min_bic_gain) {
    chosen = best_single;
    chosen_bic = best_single->bic;
  }
  if (best_pair && best_pair->bic < chosen_bic - options.min_bic_gain) {
    chosen = best_pair;
    chosen_bic = best_pair->bic;
  }
  const double chosen_cost = chosen ? chosen->fit.cost : cost0;
  const int k = chosen ? chosen->parameters : 0;
  const double allowance = options.noise_allowance;
  out.chi_square = 2.0 * chosen_cost / (allowance * allowance);
  out.limit = internal::ChiSquareQuantile999(std::max(1, components - k));
  out.explained = out.chi_square <= out.limit;
  if (!out.explained) {
    out.reason = "the best model leaves " + Millimetres(chosen ? chosen->fit.residual : r0, pts) +
                 " mm rms, more than the recording's noise allows";
  }
  // A mismatch the forward model cannot resolve names nothing: which effect fits best then says
  // more about the discretisation than about the harness.
  if (chosen && out.model_error > kResolvedFraction * out.baseline_max) {
    out.explained = false;
    out.reason = "the nominal harness is resolved to " + Format3(1e3 * out.model_error) +
                 " mm only (its shape on elements half as long), against a largest mismatch of " +
                 Format3(1e3 * out.baseline_max) + " mm";
  }

  // Candidates (none included), best BIC first, and the chosen model's confidence among them.
  HarnessCandidate none;
  none.bic = bic_none;
  auto rms_of = [&](const Eigen::VectorXd& r) {
    double sum = 0.0;
    for (const Eigen::VectorXd& v : OffsetLengths(r, pts)) sum += v.squaredNorm();
    return std::sqrt(sum / std::max(1, components));
  };
  none.rms = rms_of(r0);
  none.max_deviation = out.baseline_max;
  out.candidates.push_back(none);
  for (const Fitted& f : fitted) {
    HarnessCandidate c;
    c.effects = internal::DescribeEffects(f.model, f.fit.x);
    c.bic = f.bic;
    c.rms = rms_of(f.fit.residual);
    const std::vector<Eigen::VectorXd> d = OffsetLengths(f.fit.residual, pts);
    for (const Eigen::VectorXd& v : d)
      if (v.size()) c.max_deviation = std::max(c.max_deviation, v.maxCoeff());
    out.candidates.push_back(c);
  }
  std::stable_sort(out.candidates.begin(), out.candidates.end(),
                   [](const HarnessCandidate& a, const HarnessCandidate& b) { return a.bic < b.bic; });
  double weight_sum = 0.0;
  const double bic_min = out.candidates.front().bic;
  for (const HarnessCandidate& c : out.candidates) weight_sum += std::exp(-0.5 * (c.bic - bic_min));
  out.confidence = std::exp(-0.5 * (chosen_bic - bic_min)) / weight_sum;

  // The chosen model's effects, their shares of what the fit removes, and the fitted shapes.
  out.fitted = out.nominal;
  if (chosen) {
    internal::HarnessResidual final_residual(nominal, pts, h);
    Eigen::VectorXd r;
    if (final_residual.Evaluate(&chosen->model, chosen->fit.x, &r, &out.fitted)) {
      out.effects = internal::DescribeEffects(chosen->model, chosen->fit.x);
      const double removed = std::max(cost0 - chosen->fit.cost, 0.0);
      if (chosen->model.parts.empty()) {
        out.effects.front().share = cost0 > 0 ? removed / cost0 : 0.0;
      } else {
        // Each part's share: the mismatch that comes back when it is left out of the joint fit.
        std::vector<double> back(chosen->model.parts.size(), 0.0);
        for (size_t p = 0; p < chosen->model.parts.size(); ++p) {
          const HarnessEffectModel& other = chosen->model.parts[1 - p];
          Eigen::VectorXd without;
          const Eigen::VectorXd x = chosen->fit.x.segment(chosen->model.offsets[1 - p], other.x0.size());
          if (final_residual.Evaluate(&other, x, &without))
            back[p] = std::max(0.5 * without.squaredNorm() - chosen->fit.cost, 0.0);
        }
        const double sum = back[0] + back[1];
        for (size_t p = 0; p < back.size(); ++p)
          out.effects[p].share = cost0 > 0 ? (sum > 0 ? back[p] / sum : 0.5) * removed / cost0 : 0.0;
        if (out.effects[1].share > out.effects[0].share) std::swap(out.effects[0], out.effects[1]);
      }
      solves += final_residual.solves();
    } else {
      chosen = nullptr;  // cannot happen for a fit that was evaluated; stated as none
      out.explained = false;
    }
  }
  const Eigen::VectorXd final_r = chosen ? chosen->fit.residual : r0;
  const std::vector<Eigen::VectorXd> d1 = OffsetLengths(final_r, pts);
  for (size_t b = 0; b < nb; ++b) {
    HarnessBranchDeviation& dev = out.branches[b];
    const Eigen::VectorXd& d = d1[b];
    dev.fitted_offset = d;
    if (d.size() == 0) continue;
    dev.fitted_max = d.maxCoeff();
    dev.fitted_rms = std::sqrt(d.squaredNorm() / static_cast<double>(d.size()));
    out.fitted_max = std::max(out.fitted_max, dev.fitted_max);
  }
  if (!out.explained) out.effects.clear();
  out.forward_solves = solves;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace cablefit
