// Diagnosis of a whole harness from one recording of it: the nominal set-up of a rod network
// (core/network) against the centre points observed on each of its branches (a scan of the whole
// harness split onto the branches by the caller, or measured centrelines), the mismatch located
// by branch and arc length, and the physics that was left out named from a harness catalogue
// (a junction elsewhere along the trunk or compliant, a clip elsewhere along the bundle or
// turned, one branch stiffer, heavier or set in a curve, a support nobody modelled under a
// branch), each fitted by Levenberg-Marquardt and the model chosen by BIC against the
// recording's noise: none, one effect, two, or not explained.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "cablefit/core/network/network_spec.h"

namespace cablefit {

enum class HarnessEffect {
  kNone,
  kJunctionPosition,    // a junction sits elsewhere along the trunk (the trunk's length kept)
  kJunctionCompliance,  // the branches are held at a junction through a rotational spring
  kClipPosition,        // a clip holds the bundle at another place along it
  kClipOrientation,     // a clip (or clamp) holds the bundle turned
  kBranchStiffness,     // one branch stiffer or softer (EI and GJ together)
  kBranchDensity,       // one branch heavier or lighter
  kBranchCurvature,     // one branch set in a curve over a span (taped bent, stored coiled)
  kSupportContact,      // a branch rests on a support the set-up does not have
};

/// The catalogue name ("junction_position", "branch_stiffness", ...).
const char* ToString(HarnessEffect effect);
std::optional<HarnessEffect> HarnessEffectFromString(std::string_view name);

/// What was recorded, per branch of the NetworkSpec (same order): its observed centre points
/// with their approximate arc length along the branch; a branch with no points was not seen.
struct HarnessObservation {
  std::vector<ShapeObservation> branches;
};

struct HarnessDiagnosisOptions {
  /// Element length of the fits' forward solves [m]; 0 = the harness's length / 600.
  double element_length = 0.0;
  int max_iterations = 20;  // Levenberg-Marquardt iterations per fit
  /// Observed points per branch the fits use at most (evenly thinned).
  int max_points_per_branch = 120;
  /// BIC margin a model must win by over the simpler ones [-].
  double min_bic_gain = 10.0;
  /// The best model may scatter up to this many times the recording's noise estimate [-] (as
  /// ShapeDiagnosisOptions::noise_allowance).
  double noise_allowance = 3.0;
  /// Single models carried from the linearised screening to a full fit, and how many of the
  /// best fitted singles are combined in pairs.
  int fitted_singles = 6;
  int paired_singles = 4;
  /// Pairs are searched only when the best single model leaves more than this many times the
  /// recording's noise (rms per component) [-]: a single effect that explains the recording
  /// needs no second one, and a pair search is most of the work.
  double pair_search_allowance = 2.0;
  int threads = 1;  // fits in parallel; the result does not depend on it
};

/// One effect as the chosen model states it.
struct HarnessFoundEffect {
  HarnessEffect effect = HarnessEffect::kNone;
  int branch = -1;    // the branch it acts on (-1 for a junction effect)
  int junction = -1;  // the junction (junction effects)
  int support = -1;   // index into the branch's supports (clip effects)
  /// [m] along `branch` where it acts (curvature span, contact, clip; the whole branch for a
  /// stiffness or density).
  std::optional<std::pair<double, double>> interval;
  std::map<std::string, double> parameters;
  std::map<std::string, std::string> units;
  /// The part of the nominal mismatch (sum of squared offsets) this effect removes in the joint
  /// fit [-] (as FoundEffect::share).
  double share = 0.0;
};

/// How one branch's recording compares with the nominal and the fitted harness.
struct HarnessBranchDeviation {
  int points = 0;                // observed points used
  double nominal_max = 0.0;      // [m] largest distance of an observed point to the nominal
  double nominal_rms = 0.0;      // [m]
  double nominal_max_s = 0.0;    // [m] where along the branch
  double fitted_max = 0.0;       // [m] the same against the fitted harness
  double fitted_rms = 0.0;       // [m]
  /// [m] the stretch where the nominal mismatch stands out (above half its largest value and
  /// three noise sigmas); empty when the branch matches.
  std::optional<std::pair<double, double>> mismatch;
  /// Per point used: its arc length along the branch [m] and its distance to the nominal and to
  /// the fitted centreline [m] (pictures, plots).
  Eigen::VectorXd s, nominal_offset, fitted_offset;
};

/// A model that was fitted: its effects, its BIC and its largest remaining deviation.
struct HarnessCandidate {
  std::vector<HarnessFoundEffect> effects;
  double bic = 0.0;
  double rms = 0.0;            // [m] rms offset per component
  double max_deviation = 0.0;  // [m]
};

struct HarnessDiagnosis {
  /// False: no model of the catalogue (one or two effects) brings the recording within its
  /// noise, or the nominal harness is not resolved well enough to tell the effects apart.
  bool explained = true;
  std::string reason;  // why not explained (empty when explained)
  double confidence = 0.0;  // [0, 1] of the chosen model among the fitted ones
  std::vector<HarnessFoundEffect> effects;  // the chosen model's, dominant first; empty = none
  std::vector<HarnessBranchDeviation> branches;
  std::vector<Polyline> nominal;  // per branch: the nominal centreline, s [m], points [m]
  std::vector<Polyline> fitted;   // per branch: the chosen model's
  double baseline_max = 0.0;      // [m] largest nominal deviation over all branches
  double fitted_max = 0.0;        // [m]
  double noise_sigma = 0.0;       // [m] the recording's centre-point noise
  /// [m] the forward model's largest own error at a recorded point (its discretisation: the
  /// nominal against the nominal on elements half as long); each point counts with the noise
  /// and this error together, so the fits do not explain the model's error by an effect.
  double model_error = 0.0;
  double element_length = 0.0;  // [m] of the fits' forward solves (halved when unresolved)
  double chi_square = 0.0;        // of the chosen (or best) model, offsets / (allowance sigma)
  double limit = 0.0;             // 99.9 % chi-square quantile at its degrees of freedom
  std::vector<HarnessCandidate> candidates;  // every fitted model, best BIC first (none included)
  int forward_solves = 0;
  double seconds = 0.0;
};

/// Diagnoses `nominal` (a valid NetworkSpec) against `observation`. Throws InvalidInput for an
/// invalid spec, a branch count that differs, or nothing observed; SolverFailure when the
/// nominal harness cannot be solved.
HarnessDiagnosis DiagnoseHarness(const NetworkSpec& nominal, const HarnessObservation& observation,
                                 const HarnessDiagnosisOptions& options = {});

}  // namespace cablefit
