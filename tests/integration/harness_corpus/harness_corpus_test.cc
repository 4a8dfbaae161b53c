// The harness corpus: every effect of the harness catalogue hidden in each bench layout (a Y
// breakout, a trunk with three breakouts and clips, a Y on a support plate), a synthetic scan of
// the whole harness, and the diagnosis, told nothing, run as `cablefit diagnose` runs a harness
// case (the scan split onto the branches, DiagnoseHarness, the split refined). It must name the
// effect at its place, or say not explained; a clean harness must come out as none. Prints the
// confusion matrix. Nothing in the diagnosis is tuned to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "cablefit/app/diagnose/harness_case.h"
#include "harness_cases.h"
#include "test_support.h"

namespace cablefit {
namespace {

// Whether a found effect sits where the hidden one is: the same junction, the same clip, the
// same branch with an interval overlapping the hidden one (within 5 % of the branch).
bool Localised(const HarnessFoundEffect& f, const testing::HiddenHarnessEffect& h, const NetworkSpec& spec) {
  if (h.junction >= 0) return f.junction == h.junction;
  if (f.branch != h.branch) return false;
  if (h.support >= 0) return f.support == h.support;
  if (!h.interval || !f.interval) return true;
  const double tol = 0.05 * spec.branches[static_cast<size_t>(h.branch)].length;
  return f.interval->first <= h.interval->second + tol && f.interval->second >= h.interval->first - tol;
}

TEST(HarnessCorpus, ConfusionMatrix) {
  std::mt19937 rng(2411);
  const std::vector<testing::HarnessLayout> layouts = testing::HarnessLayouts(rng);
  const std::filesystem::path root = testing::FreshTempDir("harness_corpus");
  std::map<std::string, std::map<std::string, int>> confusion;
  int cases = 0, right = 0, localised = 0, controls = 0, controls_right = 0, wrong = 0;
  std::vector<double> improvements, seconds;
  const char* only = std::getenv("CABLEFIT_CORPUS_ONLY");
  for (const testing::HarnessLayout& layout : layouts) {
    std::vector<std::string> effects = testing::HarnessCorpusEffects();
    effects.push_back("none");
    for (size_t e = 0; e < effects.size(); ++e) {
      const std::string& effect = effects[e];
      const std::string label = layout.name + "-" + effect;
      NetworkSpec truth = layout.spec;
      std::vector<testing::HiddenHarnessEffect> hidden;
      if (effect != "none") {
        hidden.push_back(testing::HideHarnessEffect(effect, layout, rng, &truth));
        if (hidden.back().effect.empty()) continue;  // no such place on this layout
      }
      testing::HarnessScanOptions scan;
      scan.points = 30000 + static_cast<int>(rng() % 30000);
      scan.gap_fraction = rng() % 2 ? 0.1 : 0.0;
      std::string why;
      const std::filesystem::path dir = root / label;
      if (!testing::WriteHarnessCaseFolder(dir, layout, truth, hidden, scan, rng, &why)) {
        std::printf("%-28s truth not solved: %s\n", label.c_str(), why.c_str());
        continue;
      }
      // Under sanitizers (minutes per case) one effect and the control of each layout.
      if (testing::SanitizerBuild() && e != 4 && effect != "none") continue;
      if (only && label.find(only) == std::string::npos) continue;
      addin::DiagnosedHarness d;
      try {
        d = addin::DiagnoseHarnessCase((dir / "case.json").string(), 2);
      } catch (const std::exception& ex) {
        std::printf("%-28s -> error: %s\n", label.c_str(), ex.what());
        ++confusion[effect]["error"];
        continue;
      }
      const HarnessDiagnosis& g = d.diagnosis;
      const std::string got = !g.explained ? "not explained" : g.effects.empty() ? "none"
                                                             : ToString(g.effects.front().effect);
      const bool is_right = got == effect && (effect == "none" || g.effects.size() == 1);
      bool at_place = false;
      if (is_right && effect != "none") at_place = Localised(g.effects.front(), hidden.front(), layout.spec);
      std::printf("%-28s -> %-42s conf %.2f base %.2f mm fit %.3f mm %s%.1f s (%d solves)\n",
                  label.c_str(), addin::HarnessEffectsName(d).c_str(), g.confidence, 1e3 * g.baseline_max,
                  1e3 * g.fitted_max, is_right && effect != "none" && !at_place ? "NOT LOCALISED " : "",
                  d.seconds, g.forward_solves);
      seconds.push_back(d.seconds);
      const std::string verdict = is_right ? "right" : got == "not explained" ? got : "wrong";
      ++confusion[effect][verdict];
      if (effect == "none") {
        ++controls;
        controls_right += is_right;
      } else {
        ++cases;
        right += is_right;
        localised += at_place;
        wrong += verdict == "wrong";
        if (is_right && g.fitted_max > 0) improvements.push_back(g.baseline_max / g.fitted_max);
      }
    }
  }
  std::printf("\nconfusion (rows: hidden, columns: verdict)\n%-22s %6s %6s %14s %6s\n", "", "right",
              "wrong", "not explained", "error");
  for (const auto& [effect, row] : confusion) {
    auto at = [&](const char* k) { const auto it = row.find(k); return it == row.end() ? 0 : it->second; };
    std::printf("%-22s %6d %6d %14d %6d\n", effect.c_str(), at("right"), at("wrong"), at("not explained"),
                at("error"));
  }
  std::sort(improvements.begin(), improvements.end());
  std::sort(seconds.begin(), seconds.end());
  std::printf("identified %d of %d (localised %d), wrong %d, controls %d of %d, median improvement %.1fx, "
              "time median %.1f s worst %.1f s\n",
              right, cases, localised, wrong, controls_right, controls,
              improvements.empty() ? 0.0 : improvements[improvements.size() / 2],
              seconds.empty() ? 0.0 : seconds[seconds.size() / 2], seconds.empty() ? 0.0 : seconds.back());
  if (only) return;
  EXPECT_EQ(controls_right, controls);  // a clean harness is none
  EXPECT_EQ(localised, right);          // every effect named is named where it is
}

}  // namespace
}  // namespace cablefit
