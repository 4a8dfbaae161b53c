// libFuzzer target: truth.json through ReadTruth and ReadTruthCenterline.
#include "cablefit/formats/truth_reader.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = cablefit::fuzz::WriteScratch("truth.json", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadTruth", [&] { (void)cablefit::ReadTruth(path); });
  for (const char* key : {"nominal_centerline", "truth_centerline"}) {
    cablefit::fuzz::ExpectOnlyInputErrors("ReadTruthCenterline", [&] {
      const cablefit::Polyline line = cablefit::ReadTruthCenterline(path, key);
      if (!line.points.allFinite()) std::abort();
    });
  }
  return 0;
}
