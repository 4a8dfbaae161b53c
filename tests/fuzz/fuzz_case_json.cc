// libFuzzer target: case.json through ReadRecordingCase and FindCaseFiles. The scratch folder
// holds one valid recording of each kind, so inputs that name them get past the file checks
// into the clamp and force-test validation.
#include "cablefit/formats/case_reader.h"
#include "fuzz_support.h"

namespace {

void WriteRecordings() {
  using cablefit::fuzz::WriteScratch;
  WriteScratch("scan.ply",
               "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n0 0 0\n0.1 0 0\n");
  WriteScratch("centerline.csv", "s,x,y,z\n0,0,0,0\n0.1,0.1,0,0\n");
  WriteScratch("bending.csv", "step,displacement,force\n0,0,0\n1,0.001,0.1\n");
  WriteScratch("torsion.csv", "step,angle,moment\n0,0,0\n1,0.1,0.01\n");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool once = (WriteRecordings(), true);
  (void)once;
  const std::string path = cablefit::fuzz::WriteScratch("case.json", data, size);
  cablefit::fuzz::ExpectOnlyInputErrors("ReadRecordingCase", [&] {
    const cablefit::RecordingCase c = cablefit::ReadRecordingCase(path);
    if (c.recordings.empty()) std::abort();
  });
  cablefit::fuzz::ExpectOnlyInputErrors("FindCaseFiles", [&] {
    (void)cablefit::FindCaseFiles({cablefit::fuzz::ScratchDir().string()});
  });
  return 0;
}
