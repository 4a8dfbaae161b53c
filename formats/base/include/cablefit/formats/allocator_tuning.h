// How the C library's allocator is set up in cablefit's processes (the commands and their
// OpenCASCADE helpers): see allocator_tuning.cc for why.
#pragma once

namespace cablefit {

/// Keeps freed large blocks (Newton systems, picture buffers) in the process instead of handing
/// them back to the kernel after every use. Call once, before any thread starts.
void TuneAllocatorForSolves();

}  // namespace cablefit
