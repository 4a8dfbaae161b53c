// libFuzzer target: harness.json (relax sidecar) through ReadHarnessConfig. The sample section
// file and its library sit next to it so that material.section references get read too.
#include "fuzz_support.h"
#include "harness_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool once = [] {
    cablefit::fuzz::CopySample("samples/materials/automotive.json", "automotive.json");
    cablefit::fuzz::CopySample("samples/materials/examples/single-wire.json",
                               "examples/single-wire.json");
    return true;
  }();
  (void)once;
  const std::string path = cablefit::fuzz::WriteScratch("harness.json", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadHarnessConfig", [&] {
    (void)cablefit::addin::ReadHarnessConfig(path);
  });
  return 0;
}
