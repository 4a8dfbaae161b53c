// How the C library's allocator is set up for a command: see allocator_tuning.cc for why.
#pragma once

namespace cablefit::addin {

/// Keeps freed large blocks (Newton systems, picture buffers) in the process instead of handing
/// them back to the kernel after every use. Call once, before any thread starts.
void TuneAllocatorForSolves();

}  // namespace cablefit::addin
