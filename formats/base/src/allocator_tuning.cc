#include "cablefit/formats/allocator_tuning.h"

#include <cstdlib>  // defines __GLIBC__ on glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cablefit {

// A network's Newton iteration allocates and frees blocks of megabytes (the KKT factor, the
// assembled Hessian), and so do OpenCASCADE's sweeps. glibc maps blocks above its threshold
// fresh and trims its heaps when their free top passes another: each use then pays the kernel
// for zeroed pages again, and threads faulting pages at the same time queue on the process's
// memory-map lock. Measured on the 30-segment KBL sample (`perf stat`, relax writing the STEP
// file): the command 20 000 -> 14 100 page faults, with its helpers 28 000 -> 21 500 and 1.35 ->
// 1.26 s of CPU; peak memory 205 -> 230 MB. Blocks above 32 MB that the heap has no room for
// are still mapped on their own, a heap still shrinks past 128 MB of free top, and it grows by
// 64 MB of address space at a time (pages are only paid for when touched).
constexpr int kMmapThreshold = 32 << 20;
constexpr int kTrimThreshold = 128 << 20;
constexpr int kTopPad = 64 << 20;

void TuneAllocatorForSolves() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
  mallopt(M_TOP_PAD, kTopPad);
#endif
}

}  // namespace cablefit
