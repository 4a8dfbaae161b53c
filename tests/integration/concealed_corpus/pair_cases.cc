#include "pair_cases.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace cablefit::testing {
namespace {

double IoU(std::pair<double, double> a, std::pair<double, double> b) {
  const double inter = std::min(a.second, b.second) - std::max(a.first, b.first);
  const double uni = std::max(a.second, b.second) - std::min(a.first, b.first);
  return inter > 0 && uni > 0 ? inter / uni : 0.0;
}

// Whether a found effect sits where its hidden counterpart is: the same clamp (or the named
// equivalent alternative of a twist preload), a span where the true one is.
bool Localised(const FoundEffect& f, const Truth& t, double L, SpanCheck check) {
  if (t.clamp) {
    if (f.clamp == t.clamp) return true;
    const auto alt = f.parameters.find("alternative_clamp");
    return alt != f.parameters.end() && alt->second == *t.clamp;
  }
  if (!t.span) return true;
  if (!f.interval) return false;
  if (check == SpanCheck::kNear)
    return f.interval->first <= t.span->second + 0.05 * L &&
           f.interval->second >= t.span->first - 0.05 * L;
  std::pair<double, double> truth = *t.span;
  if (truth.second - truth.first < 1e-9) {  // a contact's point, as wide as the found span
    const double half = 0.5 * (f.interval->second - f.interval->first);
    truth = {truth.first - half, truth.first + half};
  }
  return IoU(*f.interval, truth) >= 0.4;
}

// Every hidden part matched to a found effect of its name that sits where it is.
bool AllLocalised(const std::vector<FoundEffect>& found, const std::vector<Truth>& truths, double L,
                  SpanCheck check) {
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
            Localised(found[j], truths[i], L, check))
          used[j] = matched = true;
      ok = ok && matched;
    }
    if (ok) return true;
  } while (std::next_permutation(order.begin(), order.end()));
  return false;
}

}  // namespace

std::string Multiset(std::vector<std::string> names) {
  if (names.empty()) return "none";
  std::sort(names.begin(), names.end());
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : "+") + n;
  return s;
}

std::vector<Truth> HideParts(const std::vector<HiddenPart>& parts, const RodSpec& nominal,
                             std::mt19937& rng, RodSpec* truth, bool whole_cable_spans) {
  std::vector<Truth> truths;
  std::vector<std::mt19937> drawn;  // the draws each part was hidden with
  for (const HiddenPart& part : parts) {
    drawn.push_back(rng);
    Truth t{part.effect, {}, {}};
    t.clamp = HideEffect(part.effect, nominal, false, rng, truth, part.place);
    t.span = HiddenSpan(part.effect, *truth);
    truths.push_back(t);
  }
  if (!whole_cable_spans) return truths;
  // An effect of the whole cable shows where the truth hangs apart from the truth without it
  // (the other parts hidden again with their own draws).
  for (size_t p = 0; p < parts.size(); ++p) {
    if (truths[p].clamp || truths[p].span) continue;
    RodSpec without = nominal;
    for (size_t q = 0; q < parts.size(); ++q) {
      if (q == p) continue;
      std::mt19937 r = drawn[q];
      HideEffect(parts[q].effect, nominal, false, r, &without, parts[q].place);
    }
    truths[p].span = ContributionSpan(*truth, without);
  }
  return truths;
}

Outcome RunPairCase(const char* layout, const std::string& label, const RodSpec& nominal,
                    const RodSpec& truth, const std::vector<Truth>& truths, std::mt19937& rng,
                    bool run, SpanCheck span_check, const ScanQuality& quality) {
  Outcome out;
  // A developer's filter (a substring of "layout label"): the others are drawn but not run.
  const char* only = std::getenv("CABLEFIT_CORPUS_ONLY");
  if (only && (std::string(layout) + " " + label).find(only) == std::string::npos) run = false;
  const std::optional<ScannedTruth> scanned =
      ScanOrReport(layout, label, truth, nominal, rng, run, quality);
  if (!scanned) return out;
  if (!run) {
    out.got = "skipped";
    return out;
  }
  try {
    const ShapeDiagnosis dg = DiagnoseAsCommand(nominal, *scanned, &out.seconds);
    std::vector<std::string> names;
    for (const FoundEffect& f : dg.effects) names.push_back(ToString(f.effect));
    out.got = dg.explained ? Multiset(names) : "unexplained";
    out.improvement = dg.baseline_max / std::max(dg.fitted_max, 1e-12);
    if (out.got == label)
      out.localised = AllLocalised(dg.effects, truths, nominal.length, span_check);
    std::string shares;
    for (const FoundEffect& f : dg.effects) {
      char buf[160];
      if (f.interval)
        std::snprintf(buf, sizeof buf, " %s%s %.2f [%.0f-%.0f mm]", ToString(f.effect),
                      f.clamp ? ("@" + std::to_string(*f.clamp)).c_str() : "", f.share,
                      1e3 * f.interval->first, 1e3 * f.interval->second);
      else
        std::snprintf(buf, sizeof buf, " %s%s %.2f", ToString(f.effect),
                      f.clamp ? ("@" + std::to_string(*f.clamp)).c_str() : "", f.share);
      shares += buf;
    }
    std::string hidden;
    for (const Truth& t : truths) {
      char buf[160];
      std::snprintf(buf, sizeof buf, " %s%s", t.effect.c_str(),
                    t.clamp ? ("@" + std::to_string(*t.clamp)).c_str() : "");
      hidden += buf;
      if (t.span) {
        std::snprintf(buf, sizeof buf, " [%.0f-%.0f mm]", 1e3 * t.span->first,
                      1e3 * t.span->second);
        hidden += buf;
      }
    }
    std::printf(
        "%-9s %-45s -> %-45s conf %.2f base %.2f mm fit %.3f mm (x%.1f) chi2/limit "
        "%.2f%s  %.1f s (fits %.1f, pairs %.1f, %d solves) single %.2f  shares:%s  "
        "hidden:%s\n",
        layout, label.c_str(), out.got.c_str(), dg.confidence, dg.baseline_max * 1e3,
        dg.fitted_max * 1e3, out.improvement, dg.adequacy.chi_square / dg.adequacy.limit,
        out.localised ? "" : " NOT LOCALISED", out.seconds, dg.cost.fits_seconds,
        dg.cost.pairs_seconds, dg.cost.forward_solves, dg.adequacy.single_residual, shares.c_str(),
        hidden.c_str());
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
        for (size_t i = 0; i < c.effects.size(); ++i)
          n += std::string(n.empty() ? "" : "+") + ToString(c.effects[i]) +
               (c.clamps[i] ? "@" + std::to_string(*c.clamps[i]) : "");
        std::printf("          pair %-45s bic %.1f score %.2f max %.3f mm\n", n.c_str(), c.bic,
                    c.score, c.max_deviation * 1e3);
      }
  } catch (const std::exception& e) {
    out.got = "error";
    std::printf("%-9s %-45s -> error: %s\n", layout, label.c_str(), e.what());
  }
  std::fflush(stdout);
  return out;
}

void PairTally::Add(const std::string& kind, const std::string& label, const Outcome& o) {
  if (o.got.empty()) return void(++failed);
  if (o.got == "skipped") return;
  if (o.seconds >= 0) seconds.push_back(o.seconds);
  const bool right = o.got == label;
  const std::string verdict = right                                        ? "right"
                              : o.got == "unexplained" || o.got == "error" ? o.got
                                                                           : "wrong";
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
}

double PairTally::MedianImprovement() const {
  std::vector<double> v = improvements;
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

void PairTally::Print(const char* title) const {
  std::printf("\n%s: confusion (rows: hidden, columns: verdict)\n%-8s %6s %6s %11s %6s\n", title,
              "", "right", "wrong", "unexplained", "error");
  for (const char* kind : {"pair", "single", "none"}) {
    auto row = confusion.find(kind);
    auto count = [&](const char* v) {
      if (row == confusion.end()) return 0;
      auto it = row->second.find(v);
      return it == row->second.end() ? 0 : it->second;
    };
    std::printf("%-8s %6d %6d %11d %6d\n", kind, count("right"), count("wrong"),
                count("unexplained"), count("error"));
  }
  std::vector<double> t = seconds;
  std::sort(t.begin(), t.end());
  std::printf(
      "%s: pairs identified %d of %d, controls %d of %d, not localised %d, median "
      "improvement %.1fx, truth solves failed %d, diagnosis time median %.2f s worst "
      "%.2f s (%u threads)\n",
      title, pair_right, pair_cases, controls_right, controls, not_localised, MedianImprovement(),
      failed, t.empty() ? 0.0 : t[t.size() / 2], t.empty() ? 0.0 : t.back(),
      std::thread::hardware_concurrency());
}

}  // namespace cablefit::testing
