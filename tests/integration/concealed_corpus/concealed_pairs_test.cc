// The two-effect concealed corpus: set-ups with two pieces of physics left out at once (two
// different ones, or one at two places: curvature sets near both ends, both clamps mis-set), a
// synthetic hand-held scan of the result, and the diagnosis, told nothing, must name both (the
// multiset of effects), put clamp effects at their clamps and spans where they are. Single-effect
// and clean controls run through the same path and must come out as one effect and none. Prints
// the confusion matrix. Nothing in the diagnosis is tuned to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <random>
#include <thread>

#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "concealed_cases.h"
#include "test_support.h"

namespace cablefit {
namespace {

// One hidden effect and where it goes.
struct HiddenPart {
  HiddenPart(const char* e, testing::Placement p = {}) : effect(e), place(p) {}
  std::string effect;
  testing::Placement place;
};

// The pairs of the corpus: every shape effect appears, and the same effect twice where it can
// act at two places.
const std::vector<std::pair<HiddenPart, HiddenPart>>& Pairs() {
  static const std::vector<std::pair<HiddenPart, HiddenPart>> pairs = {
      {{"intrinsic_curvature"}, {"clamp_orientation"}},
      {{"weight_stiffness_ratio"}, {"intrinsic_curvature"}},
      {{"support_contact"}, {"clamp_orientation"}},
      {{"intrinsic_curvature", {-1, 0.2}}, {"intrinsic_curvature", {-1, 0.8}}},
      {{"clamp_orientation", {0, -1}}, {"clamp_orientation", {1, -1}}},
      {{"anisotropic_bending"}, {"support_contact"}},
      {{"weight_stiffness_ratio"}, {"clamp_compliance"}},
      {{"twist_preload"}, {"intrinsic_curvature"}},
      {{"clamp_compliance"}, {"support_contact"}},
      {{"anisotropic_bending"}, {"clamp_orientation"}},
      {{"weight_stiffness_ratio"}, {"support_contact"}},
      {{"twist_preload", {0, -1}}, {"clamp_orientation", {1, -1}}},
  };
  return pairs;
}

std::string Multiset(std::vector<std::string> names) {
  if (names.empty()) return "none";
  std::sort(names.begin(), names.end());
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : "+") + n;
  return s;
}

// A hidden part as the check sees it: its clamp and its true span (curvature, contact).
struct Truth {
  std::string effect;
  std::optional<int> clamp;
  std::optional<std::pair<double, double>> span;
};

// Whether a found effect sits where its hidden counterpart is: the same clamp (or the named
// equivalent alternative of a twist preload), a span within 5 % of the cable of the true one.
bool Localised(const FoundEffect& f, const Truth& t, double L) {
  if (t.clamp) {
    if (f.clamp == t.clamp) return true;
    const auto alt = f.parameters.find("alternative_clamp");
    return alt != f.parameters.end() && alt->second == *t.clamp;
  }
  if (t.span && f.interval)
    return f.interval->first <= t.span->second + 0.05 * L &&
           f.interval->second >= t.span->first - 0.05 * L;
  return true;
}

// Every hidden part matched to a found effect of its name that sits where it is.
bool AllLocalised(const std::vector<FoundEffect>& found, const std::vector<Truth>& truths,
                  double L) {
  std::vector<bool> used(found.size(), false);
  // Two of one name: either assignment may be the right one.
  std::vector<size_t> order(truths.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  do {
    std::fill(used.begin(), used.end(), false);
    bool ok = true;
    for (size_t i : order) {
      bool matched = false;
      for (size_t j = 0; j < found.size() && !matched; ++j)
        if (!used[j] && ToString(found[j].effect) == truths[i].effect &&
            Localised(found[j], truths[i], L))
          used[j] = matched = true;
      ok = ok && matched;
    }
    if (ok) return true;
  } while (std::next_permutation(order.begin(), order.end()));
  return false;
}

struct Outcome {
  std::string got;  // the multiset found, "unexplained", "error"; "" = truth not solved
  bool localised = true;
  double improvement = 0.0;
  double seconds = -1.0;
};

Outcome RunPairCase(const char* layout, const std::string& label, const RodSpec& nominal,
            const RodSpec& truth, const std::vector<Truth>& truths, std::mt19937& rng,
                    bool run) {
  Outcome out;
  // A developer's filter (a substring of "layout label"): the others are drawn but not run.
  const char* only = std::getenv("CABLEFIT_CORPUS_ONLY");
  if (only && (std::string(layout) + " " + label).find(only) == std::string::npos) run = false;
  const std::optional<testing::ScannedTruth> scanned =
      testing::ScanOrReport(layout, label, truth, nominal, rng, run);
  if (!scanned) return out;
  if (!run) {
    out.got = "skipped";
    return out;
  }
  try {
    const ShapeDiagnosis dg = testing::DiagnoseAsCommand(nominal, *scanned, &out.seconds);
    std::vector<std::string> names;
    for (const FoundEffect& f : dg.effects) names.push_back(ToString(f.effect));
    out.got = dg.explained ? Multiset(names) : "unexplained";
    out.improvement = dg.baseline_max / std::max(dg.fitted_max, 1e-12);
    if (out.got == label) out.localised = AllLocalised(dg.effects, truths, nominal.length);
    std::string shares;
    for (const FoundEffect& f : dg.effects) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " %s%s %.2f", ToString(f.effect),
                    f.clamp ? ("@" + std::to_string(*f.clamp)).c_str() : "", f.share);
      shares += buf;
    }
    std::printf("%-7s %-45s -> %-45s conf %.2f base %.2f mm fit %.3f mm (x%.1f) chi2/limit "
                "%.2f%s  %.1f s (fits %.1f, pairs %.1f, %d solves) single %.2f  shares:%s\n",
                layout, label.c_str(), out.got.c_str(), dg.confidence, dg.baseline_max * 1e3,
                dg.fitted_max * 1e3, out.improvement, dg.adequacy.chi_square / dg.adequacy.limit,
                out.localised ? "" : " NOT LOCALISED", out.seconds, dg.cost.fits_seconds,
                dg.cost.pairs_seconds, dg.cost.forward_solves, dg.adequacy.single_residual,
                shares.c_str());
    for (const DiagnosisNote& note : dg.notes)
      std::printf("          note: %s %s\n", ToString(note.effect),
                  note.kind == DiagnosisNote::Kind::kRecordingReversed ? "reversed"
                  : note.kind == DiagnosisNote::Kind::kFitDidNotHold
                      ? (note.solved ? "did not hold" : "did not hold (not solved)")
                      : "started from another equilibrium");
    if (out.got != label)
      for (const EffectCandidate& c : dg.candidates)
        std::printf("          single %-24s%s bic %.1f max %.3f mm\n", ToString(c.effect),
                    c.clamp ? ("@" + std::to_string(*c.clamp)).c_str() : "", c.bic,
                    c.max_deviation * 1e3);
    if (out.got != label)
      for (const CombinationCandidate& c : dg.combinations) {
        std::string n;
        for (ShapeEffect e : c.effects) n += std::string(n.empty() ? "" : "+") + ToString(e);
        std::printf("          pair %-45s bic %.1f score %.2f max %.3f mm\n", n.c_str(), c.bic,
                    c.score, c.max_deviation * 1e3);
      }
  } catch (const std::exception& e) {
    out.got = "error";
    std::printf("%-7s %-45s -> error: %s\n", layout, label.c_str(), e.what());
  }
  return out;
}

TEST(ConcealedPairsTest, ConfusionMatrix) {
  const std::vector<testing::Layout> layouts = testing::CorpusLayouts();
  const std::vector<std::string> singles = {"intrinsic_curvature", "support_contact",
                                            "clamp_orientation", "weight_stiffness_ratio"};
  std::mt19937 rng(4937);
  std::map<std::string, std::map<std::string, int>> confusion;  // kind of case -> verdict
  int pair_cases = 0, pair_right = 0, controls = 0, controls_right = 0, not_localised = 0,
      failed = 0, false_pairs = 0, none_false_positives = 0;
  std::vector<double> improvements, seconds;
  auto tally = [&](const std::string& kind, const std::string& label, const Outcome& o) {
    if (o.got.empty()) return void(++failed);
    if (o.got == "skipped") return;
    if (o.seconds >= 0) seconds.push_back(o.seconds);
    const bool right = o.got == label;
    const std::string verdict =
        right ? "right" : o.got == "unexplained" || o.got == "error" ? o.got : "wrong";
    ++confusion[kind][verdict];
    if (kind == "pair") {
      ++pair_cases;
      pair_right += right;
      if (right) improvements.push_back(o.improvement);
    } else {
      ++controls;
      controls_right += right;
      false_pairs += o.got.find('+') != std::string::npos;
      none_false_positives += kind == "none" && !right;
    }
    not_localised += right && !o.localised;
  };
  // Under sanitizers (each case takes minutes there) the controls of the first layout only.
  auto controls_run = [](size_t li) { return li == 0 || !testing::SanitizerBuild(); };
  for (size_t li = 0; li < layouts.size(); ++li) {
    const testing::Layout& lay = layouts[li];
    for (size_t pi = 0; pi < Pairs().size(); ++pi) {
      const auto& [a, b] = Pairs()[pi];
      const RodSpec nominal = MakeNominal(lay, rng);
      RodSpec truth = nominal;
      std::vector<Truth> truths;
      for (const HiddenPart& part : {a, b}) {
        Truth t{part.effect, {}, {}};
        t.clamp = testing::HideEffect(part.effect, nominal, false, rng, &truth, part.place);
        t.span = testing::HiddenSpan(part.effect, truth);
        truths.push_back(t);
      }
      const std::string label = Multiset({a.effect, b.effect});
      // Under sanitizers four pairs, one per layout.
      const bool run = !testing::SanitizerBuild() || pi == 3 * li;
      tally("pair", label, RunPairCase(lay.name, label, nominal, truth, truths, rng, run));
    }
    // Controls: one single effect and one clean recording per layout.
    {
      const RodSpec nominal = MakeNominal(lay, rng);
      RodSpec truth = nominal;
      const std::string& effect = singles[li % singles.size()];
      Truth t{effect, {}, {}};
      t.clamp = testing::HideEffect(effect, nominal, false, rng, &truth);
      t.span = testing::HiddenSpan(effect, truth);
      tally("single", effect,
            RunPairCase(lay.name, effect, nominal, truth, {t}, rng, controls_run(li)));
    }
    {
      const RodSpec nominal = MakeNominal(lay, rng);
      tally("none", "none",
            RunPairCase(lay.name, "none", nominal, nominal, {}, rng, controls_run(li)));
    }
  }
  std::printf("\nconfusion (rows: hidden, columns: verdict)\n%-8s %6s %6s %11s %6s\n", "",
              "right", "wrong", "unexplained", "error");
  for (const char* kind : {"pair", "single", "none"})
    std::printf("%-8s %6d %6d %11d %6d\n", kind, confusion[kind]["right"],
                confusion[kind]["wrong"], confusion[kind]["unexplained"],
                confusion[kind]["error"]);
  std::sort(improvements.begin(), improvements.end());
  std::sort(seconds.begin(), seconds.end());
  const double median = improvements.empty() ? 0.0 : improvements[improvements.size() / 2];
  std::printf("pairs identified %d of %d, controls %d of %d, not localised %d, median improvement "
              "%.1fx, truth solves failed %d, diagnosis time median %.2f s worst %.2f s (%u "
              "threads)\n",
              pair_right, pair_cases, controls_right, controls, not_localised, median, failed,
              seconds.empty() ? 0.0 : seconds[seconds.size() / 2],
              seconds.empty() ? 0.0 : seconds.back(), std::thread::hardware_concurrency());
  // One cause stays one effect, a clean recording none (a single fit stuck in a wrong basin is
  // replaced by its part of the pair that found the better one: the backward check).
  EXPECT_EQ(false_pairs, 0);
  EXPECT_EQ(none_false_positives, 0);
  // Measured: none or one contact of 48 pairs placed more than 5 % of the cable from the true
  // one, depending on the basin its search ends in.
  EXPECT_LE(not_localised, 2);
  EXPECT_LE(failed, 2);
  // The identification rate is measured on the whole corpus, not on the sanitizers' sample.
  if (!testing::SanitizerBuild()) {
    EXPECT_GE(pair_right, 0.75 * pair_cases);
    EXPECT_GE(median, 30.0);
  }
}

}  // namespace
}  // namespace cablefit
