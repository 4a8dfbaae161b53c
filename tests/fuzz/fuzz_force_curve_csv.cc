// libFuzzer target: force-curve CSV through ReadForceCurveCsv.
#include "cablefit/formats/force_curve_csv.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = cablefit::fuzz::WriteScratch("curve.csv", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadForceCurveCsv", [&] {
    const cablefit::ForceCurve curve = cablefit::ReadForceCurveCsv(path);
    if (curve.x.size() < 2 || curve.x.size() != curve.y.size()) std::abort();
    if (!curve.x.allFinite() || !curve.y.allFinite()) std::abort();
  });
  return 0;
}
