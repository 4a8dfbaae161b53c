// cablefit-occt-child: the helper process of cablefit/formats/helper_process.h that reads CAD.
// OCCT's readers can crash on real data; a segfault then ends this process and not cablefit.
// (The sweeps, which need none of the data exchange libraries, run in cablefit-sweep-child.)
//   cablefit-occt-child PARENT_PID read PATH SPACING DEFLECTION AREA_FRACTION ASPECT JUNCTION_TOL
//       reads the STEP/IGES file as ReadCadFile does; exit 0 whether or not it is valid (the
//       read in cablefit reports the problem), non-zero or a signal only when OCCT crashed
#include <cstdlib>
#include <string>

#include "cablefit/formats/helper_process.h"
#include "cad_read_in_process.h"

namespace {

double Number(const char* text) { return std::strtod(text, nullptr); }

int Read(int argc, char** argv) {
  if (argc != 9 || std::string(argv[2]) != "read") return cablefit::kHelperUsage;
  cablefit::CadReadOptions options;
  options.sample_spacing = Number(argv[4]);
  options.mesh_relative_deflection = Number(argv[5]);
  options.min_tube_area_fraction = Number(argv[6]);
  options.min_tube_aspect = Number(argv[7]);
  options.junction_tolerance = Number(argv[8]);
  options.probe_seconds = 0;
  try {
    cablefit::internal::ReadCadFileInThisProcess(argv[3], options);
  } catch (...) {
    // An exception is a clean failure that cablefit's own read will report with its message.
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) { cablefit::RunAsHelper(argc, argv, Read, /*tune_allocator=*/true); }
