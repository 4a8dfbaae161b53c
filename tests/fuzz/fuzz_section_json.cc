// libFuzzer target: SECTION.json through ReadSectionFile. The sample material library sits at
// ../automotive.json, where the sample section files look for it.
#include "fuzz_support.h"
#include "cablefit/app/config/section_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool once = [] {
    cablefit::fuzz::CopySample("samples/materials/automotive.json", "automotive.json");
    return true;
  }();
  (void)once;
  const std::string path = cablefit::fuzz::WriteScratch("examples/section.json", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadSectionFile", [&] {
    (void)cablefit::addin::ReadSectionFile(path);
  });
  return 0;
}
