// A two-effect concealed case run through the diagnosis and checked: whether it named the
// hidden multiset of effects and put each at its clamp or span, with a tally of a corpus's
// verdicts. Shared by the corpus the diagnosis was developed on and the one of new layouts.
#pragma once

#include <map>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "concealed_cases.h"

namespace cablefit::testing {

/// One hidden effect and where it goes.
struct HiddenPart {
  HiddenPart(const char* e, Placement p = {}) : effect(e), place(p) {}
  std::string effect;
  Placement place;
};

/// The catalogue names sorted and joined with '+' ("none" when empty): a verdict's label.
std::string Multiset(std::vector<std::string> names);

/// A hidden part as the check sees it: its clamp and its true span (curvature, contact; where
/// an effect of the whole cable shows, when asked for).
struct Truth {
  std::string effect;
  std::optional<int> clamp;
  std::optional<std::pair<double, double>> span;
};

/// How close a found span must be to the hidden one.
enum class SpanCheck {
  kNear,  // overlaps the true span widened by 5 % of the cable on either side
  kIoU,   // intersection over union >= 0.4 (a contact's point widened to the found span's width)
};

/// Hides `parts` in `nominal` one after the other: the truth and what the check needs of it.
/// With `whole_cable_spans`, an effect that acts everywhere (weight, anisotropy) is given the
/// span where it shows (ContributionSpan of the truth and the truth without it), as the
/// catalogue states its interval.
std::vector<Truth> HideParts(const std::vector<HiddenPart>& parts, const RodSpec& nominal,
                             std::mt19937& rng, RodSpec* truth, bool whole_cable_spans = false);

struct Outcome {
  std::string got;  // the multiset found, "unexplained", "error", "skipped"; "" = truth not solved
  bool localised = true;
  double improvement = 0.0;
  double seconds = -1.0;
};

/// Scans `truth`, diagnoses the scan against `nominal` and checks the verdict against `label`
/// and `truths`, printing one line (and, when wrong, the candidates). Not run (drawn only) when
/// `run` is false or CABLEFIT_CORPUS_ONLY names other cases ("layout label" substring).
Outcome RunPairCase(const char* layout, const std::string& label, const RodSpec& nominal,
                    const RodSpec& truth, const std::vector<Truth>& truths, std::mt19937& rng,
                    bool run, SpanCheck span_check, const ScanQuality& quality = {});

/// A corpus's verdicts: pairs, single-effect and clean controls.
struct PairTally {
  void Add(const std::string& kind, const std::string& label, const Outcome& o);
  /// The confusion matrix and the summary line, headed by `title`.
  void Print(const char* title) const;
  double MedianImprovement() const;

  std::map<std::string, std::map<std::string, int>> confusion;  // kind of case -> verdict
  int pair_cases = 0, pair_right = 0, controls = 0, controls_right = 0, not_localised = 0,
      failed = 0, false_pairs = 0, none_false_positives = 0;
  std::vector<double> improvements, seconds;
};

}  // namespace cablefit::testing
