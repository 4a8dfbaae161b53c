// Force-curve diagnosis: candidate fits (force_fit.h) compared by penalised BIC (Schwarz 1978;
// Kass & Raftery 1995), see force_diagnosis.h.
#include "cablefit/core/force/force_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/force/force_fit.h"
#include "cablefit/core/force/force_rig.h"

namespace cablefit {
namespace {

constexpr ForceEffect kAllEffects[] = {ForceEffect::kNone, ForceEffect::kStiffness,
                                       ForceEffect::kHysteresis};

CurveDeviation Deviation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  CurveDeviation d;
  if (a.size() == 0) return d;
  const Eigen::ArrayXd diff = (a - b).array().abs();
  d.max_deviation = diff.maxCoeff();
  d.rms_deviation = std::sqrt(diff.square().mean());
  return d;
}

// Posterior model probabilities exp(-criterion/2), normalised.
std::vector<double> Scores(const std::vector<double>& criteria) {
  const double best = *std::min_element(criteria.begin(), criteria.end());
  std::vector<double> w;
  double sum = 0.0;
  for (double c : criteria) {
    w.push_back(std::exp(-0.5 * (c - best)));
    sum += w.back();
  }
  for (double& v : w) v /= sum;
  return w;
}

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}

std::string Fixed(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
  return buf;
}

std::string Explain(const ForceDiagnosis& d, const ForceCandidate& c) {
  std::ostringstream s;
  const std::string what = d.quantity == "torsional_stiffness" ? "torsional" : "bending";
  const std::string measure = d.y_unit == "N" ? "force" : "moment";
  const std::string reduces = "fitting it reduces the max " + measure + " deviation from " +
                              Num(d.baseline.max_deviation) + " " + d.y_unit + " to " +
                              Num(d.fitted.max_deviation) + " " + d.y_unit;
  const auto param = [&](const char* name) {
    const auto it = c.parameters.find(name);
    return it == c.parameters.end() ? 0.0 : it->second;
  };
  const double ratio = c.effect == ForceEffect::kNone ? 1.0 : param("ratio");
  if (!d.adequacy.passed) {
    s << "no catalogue effect explains the recorded curve: the best fit (" << ToString(c.effect)
      << ") leaves a systematic residual of " << Fixed(100.0 * d.adequacy.rms_fraction, 1)
      << " % of the peak response (" << d.adequacy.runs << " runs of one sign where noise gives about "
      << Fixed(d.adequacy.expected_runs, 0) << "); check the set-up: the rig type and its geometry, "
      << "the units, the sensor's zero, and whether the cable was pre-bent or twisted";
    return s.str();
  }
  if (c.effect == ForceEffect::kNone) {
    s << "the recorded curve matches the nominal model within its noise (max deviation "
      << Num(d.baseline.max_deviation) << " " << d.y_unit << ", noise about " << Num(d.noise_sigma)
      << " " << d.y_unit << "); no effect is needed";
  } else if (c.effect == ForceEffect::kStiffness) {
    const double pct = std::round(std::abs(ratio - 1.0) * 100.0);
    s << "the " << what << " stiffness is " << Fixed(pct, 0) << " % "
      << (ratio < 1.0 ? "lower" : "higher") << " than nominal (ratio " << Fixed(ratio, 2) << "); "
      << reduces;
  } else {
    s << "loading and unloading paths differ: a friction (Iwan) model with " << c.elements.size()
      << " slip element(s), total slip " << measure << " " << Num(param("slip_force_total")) << " "
      << d.y_unit << ", encloses a first-cycle loop of " << Num(param("loop_area")) << " "
      << d.y_unit << "*" << d.x_unit << " (recorded " << Num(param("recorded_loop_area")) << ")";
    if (std::abs(ratio - 1.0) >= 0.05) {
      s << " on top of a " << what << " stiffness ratio of " << Fixed(ratio, 2);
    }
    s << "; " << reduces;
  }
  if (std::abs(param("sensor_offset")) > 0.0 && c.effect != ForceEffect::kHysteresis &&
      std::abs(param("sensor_offset")) > 3.0 * d.noise_sigma) {
    s << " (a sensor offset of " << Num(param("sensor_offset")) << " " << d.y_unit
      << " is taken out)";
  }
  return s.str();
}

const ForceCandidate& CandidateFor(const ForceDiagnosis& d, ForceEffect effect) {
  for (const ForceCandidate& c : d.candidates) {
    if (c.effect == effect) return c;
  }
  throw InvalidInput(std::string("force diagnosis has no candidate ") + ToString(effect));
}

// One-sided 99.9 % point of the standard normal distribution.
constexpr double kRunsZLimit = -3.09;
constexpr double kMinSystematicFraction = 0.005;

ForceDiagnosis::Adequacy TestAdequacy(const Eigen::VectorXd& y, const Eigen::VectorXd& fitted) {
  ForceDiagnosis::Adequacy a;
  const Eigen::VectorXd r = y - fitted;
  const double peak = y.cwiseAbs().maxCoeff();
  a.rms_fraction = peak > 0 && r.size() > 0 ? std::sqrt(r.squaredNorm() / r.size()) / peak : 0.0;
  double positive = 0, negative = 0;
  int previous = 0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const int sign = r(i) > 0 ? 1 : r(i) < 0 ? -1 : 0;
    if (sign == 0) continue;  // an exact zero belongs to neither run
    (sign > 0 ? positive : negative) += 1;
    if (sign != previous) ++a.runs;
    previous = sign;
  }
  const double n = positive + negative;
  if (positive < 1 || negative < 1) {
    // All of one sign: one run, the most systematic residual there is.
    a.expected_runs = n / 2 + 1;
    a.z = n >= 10 ? -std::sqrt(n) : 0.0;
  } else {
    a.expected_runs = 2 * positive * negative / n + 1;
    const double variance = (a.expected_runs - 1) * (a.expected_runs - 2) / (n - 1);
    a.z = variance > 0 ? (a.runs - a.expected_runs) / std::sqrt(variance) : 0.0;
  }
  a.passed = !(a.z < kRunsZLimit && a.rms_fraction > kMinSystematicFraction);
  return a;
}

// Fills the chosen-model fields of *d from candidate `c`.
void Choose(const ForceDiagnosis& base, const ForceCandidate& c, const Eigen::VectorXd& y,
            ForceDiagnosis* d) {
  *d = base;
  d->effect = c.effect;
  d->confidence = c.score;
  d->parameters = c.parameters;
  d->elements = c.elements;
  d->fitted_curve = c.fitted;
  d->fitted = Deviation(y, c.fitted);
  const double n = static_cast<double>(y.size());
  d->noise_sigma = std::sqrt(c.rss / std::max(1.0, n - c.parameter_count));
  d->adequacy = TestAdequacy(y, c.fitted);
  d->explanation = Explain(*d, c);
}

}  // namespace

const char* ToString(ForceEffect effect) {
  switch (effect) {
    case ForceEffect::kNone:
      return "none";
    case ForceEffect::kStiffness:
      return "stiffness";
    case ForceEffect::kHysteresis:
      return "hysteresis";
  }
  return "none";
}

bool ForceDiagnosisOptions::IsValid(std::string* why) const {
  const auto fail = [&](const std::string& reason) {
    if (why != nullptr) *why = reason;
    return false;
  };
  if (min_rows < 3) return fail("min_rows must be at least 3");
  if (!(offset_prior_fraction > 0.0)) return fail("offset_prior_fraction must be positive");
  if (!(complexity_margin >= 0.0)) return fail("complexity_margin must be non-negative");
  if (hysteresis_grid_size < 1) return fail("hysteresis_grid_size must be at least 1");
  if (!(min_slip_fraction > 0.0) || !(max_slip_fraction >= min_slip_fraction)) {
    return fail("need 0 < min_slip_fraction <= max_slip_fraction");
  }
  if (!(noise_floor_fraction > 0.0)) return fail("noise_floor_fraction must be positive");
  return true;
}

ForceDiagnosis DiagnoseForceCurve(const RodSpec& nominal, const ForceTestSpec& test,
                                  const ForceCurve& curve, const ForceDiagnosisOptions& options,
                                  const std::string& file) {
  std::string why;
  if (!options.IsValid(&why)) throw UsageError("force diagnosis options: " + why);
  // Bad data is a FileError naming the recording when the caller gave its name.
  const auto fail = [&](const std::string& problem) {
    if (file.empty()) throw InvalidInput("force curve: " + problem);
    throw FileError(file, problem);
  };
  if (curve.x.size() != curve.y.size()) {
    fail("displacement and force columns differ in length");
  }
  const int n = curve.size();
  if (n < options.min_rows) {
    fail(std::to_string(n) + " rows, need at least " + std::to_string(options.min_rows));
  }
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(curve.x[i]) || !std::isfinite(curve.y[i])) {
      fail("row " + std::to_string(i + 1) + " is not a finite number");
    }
  }
  if (curve.x.maxCoeff() - curve.x.minCoeff() <= 0.0) {
    fail("the displacement/angle never changes");
  }
  ForceFitProblem problem;
  problem.x = curve.x;
  problem.y = curve.y;
  try {
    problem.nominal = NominalForceCurve(nominal, test, curve.x);
  } catch (const InvalidInput& e) {
    fail(e.what());
  }
  problem.peak = problem.nominal.cwiseAbs().maxCoeff();
  {
    // A stiffness off by two orders of magnitude is not a cable that differs from its data
    // sheet but a set-up that does not belong to the recording (units, length, stiffness).
    const double recorded_peak = curve.y.cwiseAbs().maxCoeff();
    if (recorded_peak > 0.0 &&
        !(problem.peak > 0.01 * recorded_peak && problem.peak < 100.0 * recorded_peak)) {
      fail("the recorded " + std::string(curve.y_name.empty() ? "response" : curve.y_name) +
           " peaks at " + Num(recorded_peak) + ", the nominal model's at " + Num(problem.peak) +
           ": orders of magnitude apart, check the units and the case's length and stiffness");
    }
  }
  if (!(problem.peak > 0.0)) problem.peak = curve.y.cwiseAbs().maxCoeff();
  if (!(problem.peak > 0.0)) fail("nominal and recorded curves are zero");

  ForceDiagnosis base;
  base.file = file;
  const bool torsion = test.type == ForceTestType::kClampedTorsion;
  base.quantity = torsion ? "torsional_stiffness" : "bending_stiffness";
  base.x_unit = torsion ? "rad" : "m";
  base.y_unit = torsion ? "N m" : "N";
  base.recorded_curve = curve.y;
  base.nominal_curve = problem.nominal;
  base.baseline = Deviation(curve.y, problem.nominal);

  std::vector<double> criteria;
  for (ForceEffect e : kAllEffects) {
    base.candidates.push_back(FitForceCandidate(e, problem, options));
    criteria.push_back(base.candidates.back().criterion);
  }
  const std::vector<double> scores = Scores(criteria);
  for (size_t i = 0; i < scores.size(); ++i) base.candidates[i].score = scores[i];
  std::stable_sort(
      base.candidates.begin(), base.candidates.end(),
      [](const ForceCandidate& a, const ForceCandidate& b) { return a.criterion < b.criterion; });
  ForceDiagnosis out;
  Choose(base, base.candidates.front(), curve.y, &out);
  return out;
}

ForceCaseDiagnosis CombineForceDiagnoses(const std::vector<ForceDiagnosis>& curves,
                                         const ForceDiagnosisOptions& options) {
  if (curves.empty()) throw InvalidInput("force diagnosis: the case has no force curves");
  ForceCaseDiagnosis out;
  std::vector<double> criteria;
  for (ForceEffect e : kAllEffects) {
    double sum = 0.0;
    for (const ForceDiagnosis& d : curves) sum += CandidateFor(d, e).criterion;
    sum -= static_cast<double>(curves.size() - 1) * options.complexity_margin * ComplexityRank(e);
    criteria.push_back(sum);
  }
  const std::vector<double> scores = Scores(criteria);
  for (size_t i = 0; i < scores.size(); ++i) out.candidates.emplace_back(kAllEffects[i], scores[i]);
  std::stable_sort(out.candidates.begin(), out.candidates.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  out.effect = out.candidates.front().first;
  out.confidence = out.candidates.front().second;

  // Strongest curve: the largest criterion gain of the chosen effect over `none`.
  double best_gain = -std::numeric_limits<double>::infinity();
  double sum_sq_base = 0.0;
  double sum_sq_fit = 0.0;
  double rows = 0.0;
  for (size_t i = 0; i < curves.size(); ++i) {
    const ForceDiagnosis& d = curves[i];
    const ForceCandidate& c = CandidateFor(d, out.effect);
    const double gain = CandidateFor(d, ForceEffect::kNone).criterion - c.criterion;
    if (gain > best_gain) {
      best_gain = gain;
      out.strongest_curve = static_cast<int>(i);
    }
    ForceDiagnosis re;
    Choose(d, c, d.recorded_curve, &re);
    const double n = static_cast<double>(re.recorded_curve.size());
    out.baseline.max_deviation = std::max(out.baseline.max_deviation, re.baseline.max_deviation);
    out.fitted.max_deviation = std::max(out.fitted.max_deviation, re.fitted.max_deviation);
    sum_sq_base += n * re.baseline.rms_deviation * re.baseline.rms_deviation;
    sum_sq_fit += n * re.fitted.rms_deviation * re.fitted.rms_deviation;
    rows += n;
    out.explained = out.explained && re.adequacy.passed;
    out.curves.push_back(std::move(re));
  }
  out.baseline.rms_deviation = std::sqrt(sum_sq_base / rows);
  out.fitted.rms_deviation = std::sqrt(sum_sq_fit / rows);
  // A best fit that leaves a systematic residual is not a diagnosis.
  if (!out.explained) out.confidence = std::min(out.confidence, 0.1);
  const ForceDiagnosis& strongest = out.curves[static_cast<size_t>(out.strongest_curve)];
  out.parameters = strongest.parameters;
  out.explanation =
      (strongest.file.empty() ? std::string() : strongest.file + ": ") + strongest.explanation;
  for (const ForceDiagnosis& d : out.curves) {
    if (d.adequacy.passed) continue;
    out.explanation = (d.file.empty() ? std::string() : d.file + ": ") + d.explanation;
    break;
  }
  if (curves.size() > 1) {
    out.explanation += " (" + std::to_string(curves.size()) + " curves combined)";
  }
  return out;
}

}  // namespace cablefit
