// Writes one harness recording case as a bench would hand it over: case.json (the nominal
// harness, routes/<branch>.csv), scan.ply (a synthetic scan of the whole harness with the hidden
// effects) and hidden.json (what was hidden, for the reader; the diagnosis never sees it).
//   make_harness_case OUT_DIR LAYOUT SEED [EFFECT...] [--points N] [--gap FRACTION]
// LAYOUT is y, trunk3 or plate; EFFECT an effect of the harness catalogue (none: nothing).
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "harness_cases.h"

namespace {

int Run(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: make_harness_case OUT_DIR LAYOUT SEED [EFFECT...] [--points N] [--gap F]\n");
    return 2;
  }
  const std::filesystem::path out = argv[1];
  const std::string layout_name = argv[2];
  std::mt19937 rng(static_cast<unsigned>(std::stoul(argv[3])));
  const std::vector<cablefit::testing::HarnessLayout> layouts = cablefit::testing::HarnessLayouts(rng);
  const cablefit::testing::HarnessLayout* layout = nullptr;
  for (const auto& l : layouts)
    if (l.name == layout_name) layout = &l;
  if (!layout) {
    std::fprintf(stderr, "make_harness_case: unknown layout %s (y, trunk3, plate)\n", layout_name.c_str());
    return 2;
  }
  cablefit::testing::HarnessScanOptions scan;
  cablefit::NetworkSpec truth = layout->spec;
  std::vector<cablefit::testing::HiddenHarnessEffect> hidden;
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--points" && i + 1 < argc) {
      scan.points = std::stoi(argv[++i]);
    } else if (a == "--gap" && i + 1 < argc) {
      scan.gap_fraction = std::stod(argv[++i]);
    } else if (a != "none") {
      hidden.push_back(cablefit::testing::HideHarnessEffect(a, *layout, rng, &truth));
      if (hidden.back().effect.empty()) {
        std::fprintf(stderr, "make_harness_case: layout %s has no place for %s\n", layout_name.c_str(), a.c_str());
        return 2;
      }
    }
  }
  std::string why;
  if (!cablefit::testing::WriteHarnessCaseFolder(out, *layout, truth, hidden, scan, rng, &why)) {
    std::fprintf(stderr, "make_harness_case: %s\n", why.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_harness_case: %s\n", e.what());
    return 1;
  }
}
