// libFuzzer target: harness.json (relax sidecar) through ReadHarnessConfig. The sample section
// (on a coarse grid) and its library sit next to it, so material.section references are read.
#include "fuzz_support.h"
#include "cablefit/app/config/harness_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool once = [] {
    cablefit::fuzz::CopySample("samples/materials/automotive.json", "automotive.json");
    // The sample wire on a coarse torsion grid: the default grid takes seconds under the
    // sanitizers, and the section reader has its own target.
    cablefit::fuzz::WriteScratch("examples/single-wire.json",
                                 R"({"format": "cablefit-section/1", "library": "../automotive.json",
                                     "components": [{"name": "w1", "wire": "FLRY-B 0.5",
                                                     "position": [0, 0]}],
                                     "torsion": {"finest_cells": 32, "levels": 2}})");
    return true;
  }();
  (void)once;
  const std::string path = cablefit::fuzz::WriteScratch("harness.json", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadHarnessConfig", [&] {
    (void)cablefit::addin::ReadHarnessConfig(path);
  });
  return 0;
}
