// libFuzzer target: PLY point clouds (ASCII and binary) through ReadPly.
#include "cablefit/formats/ply_reader.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = cablefit::fuzz::WriteScratch("input.ply", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadPly", [&] {
    const cablefit::PointCloud cloud = cablefit::ReadPly(path);
    // The documented promise: what comes back is finite.
    if (!cloud.points.allFinite()) std::abort();
  });
  return 0;
}
