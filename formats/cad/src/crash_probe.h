// Runs a third-party reader once in a forked child before trusting it in this process: OCCT 7.6
// dereferences null handles on some corrupt STEP files (SIGSEGV in StepToGeom, seen with
// byte-mutated copies of the sample harness), which no exception handler can catch. A crash or
// hang in the child becomes one failed input (FileError) instead of the end of a whole batch.
#pragma once

#include <functional>
#include <string>

namespace cablefit {

/// Calls `read` in a forked child (its output discarded, its exceptions ignored: the real read
/// in this process reports those). Throws FileError(path, ...) when the child dies by a signal
/// or a non-zero exit (a sanitizer report), or is still running after `max_seconds` (then it
/// is killed). Does nothing when fork() fails.
void ProbeInChildProcess(const std::string& path, const std::string& what,
                         const std::function<void()>& read, double max_seconds = 600.0);

}  // namespace cablefit
