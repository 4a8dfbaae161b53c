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
#include <cstdlib>
#include <string>

#include "cablefit/formats/helper_process.h"
#include "tube_in_child.h"

namespace {

int Sweep(int argc, char** argv) {
  if (argc != 5) return cablefit::kHelperUsage;
  const std::string mode = argv[2];
  if (mode == "sweeps-when-told") {
    if (!cablefit::WaitUntilTold()) return 0;
  } else if (mode != "sweeps") {
    return cablefit::kHelperUsage;
  }
  return cablefit::SweepTubesInHelper(std::atoi(argv[3]), std::atoi(argv[4]));
}

}  // namespace

int main(int argc, char** argv) { cablefit::RunAsHelper(argc, argv, Sweep, /*tune_allocator=*/true); }
