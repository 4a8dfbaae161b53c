// cablefit-sweep-child: the helper process that sweeps tubes and flat strips
// (cablefit/formats/helper_process.h, tube_in_child.h). A segfault in OCCT's sweeps ends this
// process, not cablefit. It links only OCCT's modelling libraries: started ahead of every
// relax that writes STEP, it loads in ~0.03 s where cablefit-occt-child, with the STEP and
// IGES readers and what they bring (XCAF, visualisation, image codecs), takes ~0.1 s of a core
// the relax is using.
//   cablefit-sweep-child PARENT_PID sweeps SPINES_FD TUBES_FD
//       sweeps every tube and flat strip of a batch (SweepTubesInHelper)
//   cablefit-sweep-child PARENT_PID sweeps-when-told SPINES_FD TUBES_FD
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
#include "tube_in_child.h"

namespace {

constexpr int kUsage = 64;

int Run(int argc, char** argv) {
  if (argc != 5) return kUsage;
  const std::string mode = argv[2];
  if (mode == "sweeps") return cablefit::SweepTubesInHelper(std::atoi(argv[3]), std::atoi(argv[4]));
  if (mode != "sweeps-when-told") return kUsage;
  char go = 0;
  ssize_t got = 0;
  while ((got = ::read(cablefit::kGoFd, &go, 1)) < 0 && errno == EINTR) {
  }
  if (got != 1) return 0;
  return cablefit::SweepTubesInHelper(std::atoi(argv[3]), std::atoi(argv[4]));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return kUsage;
  // Killed with cablefit (kill -9 included) instead of sweeping on as an orphan.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (std::to_string(::getppid()) != argv[1]) return kUsage;  // the parent is already gone
  cablefit::TuneAllocatorForSolves();
  const int code = Run(argc, argv);
  // No exit handlers, as in a process that is simply ended (see cablefit-occt-child).
  std::_Exit(code);
}
