// cablefit-occt-child: the helper process of cablefit/formats/helper_process.h. It runs one piece
// of OCCT work that can crash on real data, so that a segfault ends this process and not cablefit.
//   cablefit-occt-child PARENT_PID read PATH SPACING DEFLECTION AREA_FRACTION ASPECT JUNCTION_TOL
//       reads the STEP/IGES file as ReadCadFile does; exit 0 whether or not it is valid (the
//       read in cablefit reports the problem), non-zero or a signal only when OCCT crashed
//   cablefit-occt-child PARENT_PID sweeps SPINES_FD TUBES_FD
//       sweeps every tube and flat strip of a batch (SweepTubesInHelper)
//   cablefit-occt-child PARENT_PID sweeps-when-told SPINES_FD TUBES_FD
//       the same once a byte arrives on descriptor 5 (a WaitingHelper, started before the
//       batch was written); end of file there instead: exit 0, unused
#include <sys/prctl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <string>

#include "cablefit/formats/allocator_tuning.h"
#include "cablefit/formats/helper_process.h"
#include "cad_read_in_process.h"
#include "tube_in_child.h"

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
  if (mode == "sweeps" && argc == 5) {
    return cablefit::SweepTubesInHelper(std::atoi(argv[3]), std::atoi(argv[4]));
  }
  if (mode == "sweeps-when-told" && argc == 5) {
    char go = 0;
    ssize_t got = 0;
    while ((got = ::read(cablefit::kGoFd, &go, 1)) < 0 && errno == EINTR) {
    }
    if (got != 1) return 0;
    return cablefit::SweepTubesInHelper(std::atoi(argv[3]), std::atoi(argv[4]));
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
