// The concealed-effect corpus: the project's own core solves set-ups with
// a hidden effect, a synthetic hand-held scan is taken of the result (partial
// circumference, gaps, clamp margins, noise, clustered outliers), and the
// diagnosis — told nothing — must name the effect. Layouts: sagging, 3-D bend,
// drop, loop; gravity numbers 2-35; moderate and subtle strengths; far clamps set near the
// cable's torque-free twist, as a bench does. Beyond one case per layout and effect: twist
// preloads at the start clamp, strong anisotropy (ratio 1.9-2.4), a small clamp rotation at the
// start of a stiff cable (gravity number 2-3), a subtle contact near the start, and recordings
// that nothing in the catalogue explains (a two-clamp cable diagnosed with a case that lists
// only its first clamp), which must come out as not explained. Prints the confusion matrix.
// This is a test of the method: nothing in the diagnosis is tuned to it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>
#include <random>
#include <thread>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "concealed_cases.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::HideEffect;
using testing::MakeNominal;
using testing::NormalPush;

struct Hidden {
  std::string effect;
  RodSpec truth;
};

// `clamp` >= 0 puts a clamp effect at that clamp (else either, at random).
Hidden Hide(const std::string& effect, const RodSpec& nominal, bool subtle, std::mt19937& rng,
            int clamp = -1) {
  Hidden h{effect, nominal};
  HideEffect(effect, nominal, subtle, rng, &h.truth, {clamp, -1.0});
  return h;
}

struct CaseOutcome {
  std::string got;        // diagnosed effect, "unexplained", "error", or "" (truth not solved)
  double improvement = 0;  // baseline max / fitted max
  bool clamp_right = true;
  // The diagnosis named the true clamp only as the equivalent alternative (a twist preload on an
  // isotropic cable: the shape fixes only the twist between the clamps).
  bool clamp_ambiguous = false;
  double seconds = -1.0;  // scan -> centre line and diagnosis (a figure printed, not a test)
};

// Solves the hidden truth, scans it, and diagnoses the scan against `told` (the nominal set-up
// the diagnosis is given).
CaseOutcome RunCase(const char* layout, const std::string& label, bool subtle, const Hidden& h,
                    const RodSpec& told, std::optional<int> truth_clamp, std::mt19937& rng,
                    bool run) {
  CaseOutcome out;
  const std::optional<testing::ScannedTruth> scanned =
      testing::ScanOrReport(layout, label, h.truth, told, rng, run);
  if (!scanned) return out;
  if (!run) {
    out.got = "skipped";
    return out;
  }
  try {
    const ShapeDiagnosis dg = testing::DiagnoseAsCommand(told, *scanned, &out.seconds);
    out.got = dg.explained ? ToString(dg.effect) : "unexplained";
    out.improvement = dg.baseline_max / std::max(dg.fitted_max, 1e-12);
    if (truth_clamp && out.got == label) {
      out.clamp_right = dg.clamp == truth_clamp;
      const auto alt = dg.parameters.find("alternative_clamp");
      if (!out.clamp_right && alt != dg.parameters.end() && alt->second == *truth_clamp)
        out.clamp_right = out.clamp_ambiguous = true;
    }
    std::printf("%-7s %-24s %-7s -> %-24s conf %.2f  base %.2f mm fit %.3f mm (x%.1f) "
                "chi2/limit %.2f%s  %.1f s single %.2f%s\n",
                layout, label.c_str(), subtle ? "subtle" : "", out.got.c_str(), dg.confidence,
                dg.baseline_max * 1e3, dg.fitted_max * 1e3, out.improvement,
                dg.adequacy.chi_square / dg.adequacy.limit,
                out.clamp_ambiguous ? " clamp: the alternative" : out.clamp_right ? "" : " WRONG CLAMP",
                out.seconds, dg.adequacy.single_residual, dg.effects.size() > 1 ? " PAIR" : "");
    for (const DiagnosisNote& note : dg.notes) {
      const char* what = note.kind == DiagnosisNote::Kind::kRecordingReversed ? "reversed"
                         : note.kind == DiagnosisNote::Kind::kFitDidNotHold
                             ? "did not hold"
                             : "started from another equilibrium";
      std::printf("          note: %s %s\n", ToString(note.effect), what);
    }
    if (out.got != label) {  // how close the hidden effect came
      for (const EffectCandidate& c : dg.candidates)
        std::printf("          candidate %-24s bic %.1f\n", ToString(c.effect), c.bic);
    }
  } catch (const std::exception& e) {
    out.got = "error";
    std::printf("%-7s %-24s -> error: %s\n", layout, label.c_str(), e.what());
  }
  return out;
}

TEST(ConcealedCorpusTest, ConfusionMatrix) {
  const std::vector<testing::Layout> layouts = testing::CorpusLayouts();
  const std::vector<std::string> effects = {"none",
                                            "intrinsic_curvature",
                                            "clamp_orientation",
                                            "weight_stiffness_ratio",
                                            "anisotropic_bending",
                                            "support_contact",
                                            "clamp_compliance",
                                            "twist_preload",
                                            "unexplained"};
  std::mt19937 rng(2026);
  std::map<std::string, std::map<std::string, int>> confusion;
  int total = 0, correct = 0, none_false_positive = 0, failed = 0, wrong_clamp = 0,
      ambiguous_clamp = 0;
  std::vector<double> improvements, seconds;
  auto tally = [&](const std::string& label, const CaseOutcome& o) {
    if (o.seconds >= 0) seconds.push_back(o.seconds);
    if (o.got.empty()) {
      ++failed;
      return;
    }
    if (o.got == "skipped") return;
    ++confusion[label][o.got];
    ++total;
    if (o.got == label) ++correct;
    if (label == "none" && o.got != "none") ++none_false_positive;
    if (!o.clamp_right) ++wrong_clamp;
    if (o.clamp_ambiguous) ++ambiguous_clamp;
    if (o.got == label && label != "none" && label != "unexplained")
      improvements.push_back(o.improvement);
  };
  for (size_t li = 0; li < layouts.size(); ++li) {
    // One case per catalogue effect, subtle on a diagonal.
    for (size_t ei = 0; ei + 1 < effects.size(); ++ei) {
      const bool subtle = (li + ei) % 3 == 0;
      const RodSpec nominal = MakeNominal(layouts[li], rng);
      const Hidden h = Hide(effects[ei], nominal, subtle, rng);
      std::optional<int> clamp;
      for (size_t k = 0; k < nominal.supports.size(); ++k)
        if (!(h.truth.supports[k].normal - nominal.supports[k].normal).isZero(0) ||
            !(h.truth.supports[k].tangent - nominal.supports[k].tangent).isZero(0) ||
            h.truth.supports[k].compliance != nominal.supports[k].compliance)
          clamp = static_cast<int>(k);
      // Under sanitizers one case per effect (a diagonal through the layouts), drawn as above so
      // that it is the same case as in the full corpus.
      const bool run = !testing::SanitizerBuild() || (li + ei) % 4 == 0;
      tally(effects[ei], RunCase(layouts[li].name, effects[ei], subtle, h, nominal, clamp, rng, run));
    }
    // A twist preload at the start clamp, where a fitted far twist used to absorb it.
    {
      const bool subtle = li % 2 == 1;
      const RodSpec nominal = MakeNominal(layouts[li], rng);
      const Hidden h = Hide("twist_preload", nominal, subtle, rng, 0);
      const bool run = !testing::SanitizerBuild() || li == 0;
      tally("twist_preload",
            RunCase(layouts[li].name, "twist_preload", subtle, h, nominal, 0, rng, run));
    }
    // The classes hidden cases found hard: a strong anisotropy (ratio 1.9-2.4, any principal
    // angle), a small clamp rotation at the start of a stiff cable (gravity number 2-3), and a
    // subtle contact near the start.
    {
      std::uniform_real_distribution<double> u(0.0, 1.0);
      const RodSpec nominal = MakeNominal(layouts[li], rng);
      Hidden h = Hide("anisotropic_bending", nominal, false, rng);
      h.truth.material.bending_ratio = 1.9 + 0.5 * u(rng);
      h.truth.material.principal_angle = M_PI * u(rng);
      const bool run = !testing::SanitizerBuild() || li == 0;
      tally("anisotropic_bending", RunCase(layouts[li].name, "anisotropic_bending", false, h,
                                           nominal, {}, rng, run));
    }
    {
      std::uniform_real_distribution<double> u(0.0, 1.0);
      const RodSpec nominal = MakeNominal(layouts[li], rng, 2.0 + u(rng));
      Hidden h{"clamp_orientation", nominal};
      SupportSpec& sp = h.truth.supports[0];
      const Frame fr = Frame::FromTangentNormal(sp.tangent, sp.normal);
      const double a = 2 * M_PI * u(rng);
      const Eigen::AngleAxisd rot(0.1 + 0.08 * u(rng), std::cos(a) * fr.d1 + std::sin(a) * fr.d2);
      sp.tangent = rot * fr.d3;
      sp.normal = rot * fr.d1;
      const bool run = !testing::SanitizerBuild() || li == 0;
      tally("clamp_orientation", RunCase(layouts[li].name, "clamp_orientation", true, h, nominal,
                                         0, rng, run));
    }
    {
      std::uniform_real_distribution<double> u(0.0, 1.0);
      const RodSpec nominal = MakeNominal(layouts[li], rng);
      Hidden h{"support_contact", nominal};
      const double w = nominal.material.linear_density * 9.81 * nominal.length;
      const double a = 2 * M_PI * u(rng), sc = (0.15 + 0.1 * u(rng)) * nominal.length;
      h.truth.point_loads.push_back(
          {sc, NormalPush(nominal, sc, (0.017 + 0.011 * u(rng)) * w, a)});
      const bool run = !testing::SanitizerBuild() || li == 0;
      tally("support_contact", RunCase(layouts[li].name, "support_contact", true, h, nominal, {},
                                       rng, run));
    }
    // A cable held by two clamps, diagnosed with a case that lists only the first (a
    // cantilever): nothing in the catalogue explains that.
    {
      const RodSpec nominal = MakeNominal(layouts[li], rng);
      RodSpec cantilever = nominal;
      cantilever.supports.resize(1);
      const Hidden h{"unexplained", nominal};
      const bool run = !testing::SanitizerBuild() || li == 0;
      tally("unexplained",
            RunCase(layouts[li].name, "unexplained", false, h, cantilever, {}, rng, run));
    }
  }
  std::printf("\nconfusion matrix (rows: hidden effect, columns: diagnosed)\n");
  std::vector<std::string> cols = effects;
  cols.push_back("error");
  std::printf("%-24s", "");
  for (const auto& c : cols) std::printf(" %5.5s", c.c_str());
  std::printf("\n");
  for (const auto& r : effects) {
    std::printf("%-24s", r.c_str());
    for (const auto& c : cols) std::printf(" %5d", confusion[r][c]);
    std::printf("\n");
  }
  std::sort(improvements.begin(), improvements.end());
  const double median = improvements.empty() ? 0.0 : improvements[improvements.size() / 2];
  std::printf(
      "identified %d of %d (%.0f %%), none false positives %d, wrong clamp %d (true clamp "
      "named as the equivalent alternative %d), median improvement %.1fx, truth solves failed "
      "%d\n",
      correct, total, 100.0 * correct / std::max(1, total), none_false_positive, wrong_clamp,
      ambiguous_clamp, median, failed);
  std::sort(seconds.begin(), seconds.end());
  if (!seconds.empty())
    std::printf("diagnosis time (scan -> centre line and diagnosis, %u threads): median %.2f s, "
                "worst %.2f s\n",
                std::thread::hardware_concurrency(), seconds[seconds.size() / 2], seconds.back());
  EXPECT_EQ(none_false_positive, 0);
  EXPECT_EQ(wrong_clamp, 0);
  EXPECT_LE(failed, 2);
  EXPECT_GE(correct, 0.85 * total);
  // Every cantilever-told recording is flagged as not explained.
  int unexplained_cases = 0;
  for (const auto& [got, count] : confusion["unexplained"]) unexplained_cases += count;
  EXPECT_EQ(confusion["unexplained"]["unexplained"], unexplained_cases);
}

}  // namespace
}  // namespace cablefit
