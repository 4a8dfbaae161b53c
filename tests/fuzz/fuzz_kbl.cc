// libFuzzer target: KBL (VDA 4964) harness files through ReadKblFile (libxml2 underneath, our
// id resolution, units and B-spline centre curves on top).
#include "cablefit/formats/kbl_file.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = cablefit::fuzz::WriteScratch("input.kbl", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadKblFile", [&] {
    const cablefit::KblHarness h = cablefit::ReadKblFile(path);
    // The documented promise: every segment that comes back has a finite route.
    for (const cablefit::DrawnCable& c : h.drawing.cables)
      if (!c.centreline.points.allFinite()) std::abort();
  });
  return 0;
}
