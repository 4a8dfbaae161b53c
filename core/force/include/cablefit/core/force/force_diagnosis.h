// Diagnosis of a recorded force curve (recording-v1 "force_curve", effects `none`, `stiffness`,
// `hysteresis`): fit each candidate model to the recorded rows, compare them with the Bayesian
// information criterion (Schwarz, "Estimating the dimension of a model", Ann. Stat. 6 (1978)
// 461-464) plus a prior that favours simpler models by a fixed evidence margin (Kass & Raftery,
// "Bayes factors", JASA 90 (1995) 773-795: a BIC difference above 6 is strong evidence).
//
// Candidate models, all with a small constant sensor offset c as a nuisance unknown (Gaussian
// prior of width offset_prior_fraction * peak, because for the nearly flat buckling curve an
// offset and a stiffness change are otherwise indistinguishable):
//   none        y = N(x) + c
//   stiffness   y = r N(x) + c                      (N scales exactly with EI or GJ)
//   hysteresis  y = r N(x) + c + sum_j f_j z_j(x)   (Iwan model, force_hysteresis.h; slip
//               displacements on a log grid, slip forces f_j >= 0 by NNLS)
// Noise is unknown: each model's likelihood is profiled over sigma (n ln(RSS/n)), so no sensor
// noise has to be supplied; the chosen model's residual gives the reported noise estimate.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "cablefit/core/force/force_hysteresis.h"
#include "cablefit/core/rod/recording_case.h"
#include "cablefit/core/rod/rod_spec.h"

namespace cablefit {

/// The force-data effects of the recording-v1 catalogue.
enum class ForceEffect { kNone, kStiffness, kHysteresis };
/// "none", "stiffness", "hysteresis".
const char* ToString(ForceEffect effect);

struct ForceDiagnosisOptions {
  /// Fewer recorded rows than this are rejected (InvalidInput): a loop and a level need both
  /// branches with a few rows each.
  int min_rows = 5;
  /// Width of the Gaussian prior on the sensor offset, as a fraction of the peak nominal
  /// response. An offset this size biases a bending stiffness ratio by about this fraction.
  double offset_prior_fraction = 0.02;
  /// Extra BIC a model must win by for each step of complexity (none -> stiffness ->
  /// hysteresis); 6 = "strong evidence" (Kass & Raftery 1995). Keeps `none` when the nominal
  /// model explains the data within noise.
  double complexity_margin = 6.0;
  /// Number of Iwan elements on the slip-displacement grid.
  int hysteresis_grid_size = 12;
  /// Slip-displacement grid, log-spaced between these fractions of the recorded x range.
  double min_slip_fraction = 0.005;
  double max_slip_fraction = 0.5;
  /// The residual sum of squares is floored at n (this * peak)^2 so noise-free data does not
  /// make the log-likelihood diverge.
  double noise_floor_fraction = 1e-6;

  /// True when every field is usable; otherwise false with the reason in *why (if given).
  bool IsValid(std::string* why) const;
};

/// Max and root-mean-square absolute difference between two curves, in the curve's unit.
struct CurveDeviation {
  double max_deviation = 0.0;
  double rms_deviation = 0.0;
};

/// One fitted candidate model.
struct ForceCandidate {
  ForceEffect effect = ForceEffect::kNone;
  /// Posterior model probability from the penalised BIC (higher is better, sums to 1).
  double score = 0.0;
  /// BIC + complexity prior (lower is better); additive over independent curves.
  double criterion = 0.0;
  int parameter_count = 0;
  double rss = 0.0;                          // residual sum of squares [unit^2]
  std::map<std::string, double> parameters;  // ratio, sensor_offset, loop_area, ...
  std::vector<JenkinsElement> elements;      // hysteresis only
  Eigen::VectorXd fitted;                    // n [N] or [N m], offset included
};

struct ForceDiagnosis {
  std::string file;  ///< the recording's file name (set by the caller, used in text)
  ForceEffect effect = ForceEffect::kNone;
  /// "bending_stiffness" or "torsional_stiffness": what a `stiffness` ratio refers to.
  std::string quantity;
  std::string x_unit;                        ///< "m" or "rad"
  std::string y_unit;                        ///< "N" or "N m"
  double confidence = 0.0;                   ///< score of the chosen candidate, in [0, 1]
  std::vector<ForceCandidate> candidates;    ///< every model considered, best first
  std::map<std::string, double> parameters;  ///< of the chosen model (spec names + nuisances)
  std::vector<JenkinsElement> elements;      ///< hysteresis: the fitted Iwan elements
  double noise_sigma = 0.0;        ///< residual standard deviation of the chosen model [unit]
  /// Whether the chosen model explains the curve: its residual, in recording order, must look
  /// like noise. Wald-Wolfowitz runs test of the residual signs (a force curve has no noise
  /// estimate of its own to compare with): a model that misses the physics leaves long runs of
  /// one sign. z = (runs - expected) / standard deviation; not explained when z is below the
  /// one-sided 99.9 % point (-3.09) and the residual is larger than 0.5 % of the peak response
  /// (a systematic residual smaller than that is within what a bench can tell).
  struct Adequacy {
    int runs = 0;
    double expected_runs = 0.0;
    double z = 0.0;
    double rms_fraction = 0.0;  ///< fitted RMS deviation / peak recorded response
    bool passed = true;
  } adequacy;
  CurveDeviation baseline;         ///< recorded vs nominal
  CurveDeviation fitted;           ///< recorded vs fitted
  Eigen::VectorXd recorded_curve;  ///< n, the recorded force/moment
  Eigen::VectorXd nominal_curve;   ///< n, nominal model per recorded row
  Eigen::VectorXd fitted_curve;    ///< n, chosen model per recorded row
  std::string explanation;         ///< one or two sentences for an engineer
};

/// Diagnoses one recorded curve against the nominal rod and rig. Throws InvalidInput for too
/// few rows, mismatched or non-finite columns, displacements outside the rig's geometry, a
/// recorded response orders of magnitude from the nominal one (units, length, stiffness: not a
/// catalogue effect); UsageError for invalid options. `file` only labels the result.
ForceDiagnosis DiagnoseForceCurve(const RodSpec& nominal, const ForceTestSpec& test,
                                  const ForceCurve& curve,
                                  const ForceDiagnosisOptions& options = {},
                                  const std::string& file = "");

/// A case with several curves: the effect whose criterion summed over the curves is lowest
/// (each curve keeps its own parameters). `curves` holds the per-curve diagnoses re-expressed
/// with the case-level effect (its fit of each curve; nothing is refitted).
struct ForceCaseDiagnosis {
  ForceEffect effect = ForceEffect::kNone;
  double confidence = 0.0;
  std::vector<std::pair<ForceEffect, double>> candidates;  ///< (effect, score), best first
  /// Parameters of the curve with the strongest evidence for `effect` (index strongest_curve).
  std::map<std::string, double> parameters;
  int strongest_curve = 0;
  CurveDeviation baseline;  ///< max over curves; rms pooled over all rows
  CurveDeviation fitted;
  bool explained = true;  ///< every curve's chosen fit passed its adequacy test
  std::string explanation;
  std::vector<ForceDiagnosis> curves;  ///< each re-expressed with the case-level effect
};

/// Combines the diagnoses of all force curves of one case: the curves' likelihoods are joint
/// (criteria summed), and the prior against complexity (options.complexity_margin) is counted
/// once, because the effect is one hypothesis about the cable, however many curves test it.
/// Throws InvalidInput if empty.
ForceCaseDiagnosis CombineForceDiagnoses(const std::vector<ForceDiagnosis>& curves,
                                         const ForceDiagnosisOptions& options = {});

}  // namespace cablefit
