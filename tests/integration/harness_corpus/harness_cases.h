// The harness corpus's cases: an effect of the harness catalogue hidden in a bench layout
// (tests/support/harness_layouts.h), the hidden truth solved and scanned as one hand-held scan of
// the whole harness, and the case folder a bench would hand over (case.json with its routes,
// scan.ply; hidden.json for the reader only).
#pragma once

#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cablefit/core/diagnosis/harness_diagnosis.h"
#include "harness_layouts.h"

namespace cablefit::testing {

/// What was hidden and where.
struct HiddenHarnessEffect {
  std::string effect;  // catalogue name
  int branch = -1, junction = -1, support = -1;
  std::optional<std::pair<double, double>> interval;  // [m] along `branch`
};

/// The harness-level effects the corpus hides (every one of the catalogue).
const std::vector<std::string>& HarnessCorpusEffects();

/// Hides `effect` in `truth` (a copy of `layout.spec` or one with an effect already), at a place
/// drawn from `rng`; its size is drawn from the range a bench would notice.
HiddenHarnessEffect HideHarnessEffect(const std::string& effect, const HarnessLayout& layout,
                                      std::mt19937& rng, NetworkSpec* truth);

struct HarnessScanOptions {
  int points = 60000;          // on the whole harness
  double noise_sigma = 0.1e-3;  // [m]
  double gap_fraction = 0.0;   // a gap of this share of each branch's length, unseen
};

/// A synthetic hand-held scan of the solved `truth`; empty when the truth cannot be solved.
PointCloud ScanHarness(const NetworkSpec& truth, const HarnessScanOptions& options, std::mt19937& rng);

/// Writes the case folder `dir`: case.json (the nominal `layout`, routes/<branch>.csv),
/// scan.ply of `truth`, hidden.json. False (and `why`) when the truth cannot be solved.
bool WriteHarnessCaseFolder(const std::filesystem::path& dir, const HarnessLayout& layout,
                            const NetworkSpec& truth, const std::vector<HiddenHarnessEffect>& hidden,
                            const HarnessScanOptions& scan, std::mt19937& rng, std::string* why);

}  // namespace cablefit::testing
