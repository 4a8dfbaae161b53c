// libFuzzer target: centreline CSV through ReadCenterlineCsv.
#include <cmath>

#include "cablefit/formats/centerline_csv.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = cablefit::fuzz::WriteScratch("centerline.csv", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadCenterlineCsv", [&] {
    const cablefit::Polyline line = cablefit::ReadCenterlineCsv(path);
    // The documented promise: at least 2 finite points, s as long as the points, never falling.
    if (line.points.cols() < 2 || !line.points.allFinite()) std::abort();
    if (line.s.size() != line.points.cols()) std::abort();
    for (Eigen::Index i = 1; i < line.s.size(); ++i)
      if (!(line.s[i] >= line.s[i - 1])) std::abort();
  });
  return 0;
}
