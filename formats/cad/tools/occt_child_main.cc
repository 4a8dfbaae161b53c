// cablefit-occt-child: the helper process of cablefit/formats/helper_process.h that reads CAD.
// OCCT's readers can crash on real data; a segfault then ends this process and not cablefit.
// (The sweeps, which need none of the data exchange libraries, run in cablefit-sweep-child.)
//   cablefit-occt-child PARENT_PID read PATH SPACING DEFLECTION AREA_FRACTION ASPECT JUNCTION_TOL
//       reads the STEP/IGES file as ReadCadFile does; exit 0 whether or not it is valid (the
//       read in cablefit reports the problem), non-zero or a signal only when OCCT crashed
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include "cablefit/formats/allocator_tuning.h"
#include "cablefit/formats/helper_process.h"
#include "cad_read_in_process.h"

namespace {

constexpr int kUsage = 64;

double Number(const char* text) { return std::strtod(text, nullptr); }

int Run(int argc, char** argv) {
  const std::string mode = argv[2];
  if (mode == "read" && argc == 9) {
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
  return kUsage;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return kUsage;
  // Killed with cablefit (kill -9 included) instead of reading on for minutes as an orphan.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (std::to_string(::getppid()) != argv[1]) return kUsage;  // the parent is already gone
  cablefit::TuneAllocatorForSolves();
  const int code = Run(argc, argv);
  // No exit handlers: OCCT's per-process reader state is not torn down (and LeakSanitizer,
  // in sanitizer builds, does not report it), as in a process that is simply ended.
  std::_Exit(code);
}
