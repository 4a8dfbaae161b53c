// Runs a third-party reader once in a forked child before trusting it in this process: OCCT 7.6
// dereferences null handles on some corrupt STEP files (SIGSEGV in StepToGeom, seen with
// byte-mutated copies of the sample harness), which no exception handler can catch. A crash or
// hang in the child becomes one failed input (FileError) instead of the end of a whole batch.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace cablefit {

/// How a forked child ended.
struct ChildOutcome {
  int signal = 0;          // the signal that ended it, 0 when it exited
  int exit_code = 0;       // its exit status when it exited
  bool timed_out = false;  // still running after the limit (then killed)
};

/// Calls `body` in a forked child (stdout/stderr to /dev/null, exit status = its return value,
/// 1 when it throws) and waits at most `max_seconds` for it. std::nullopt when fork() fails or
/// the child is lost: the caller then does the work in this process.
std::optional<ChildOutcome> RunInChildProcess(const std::function<int()>& body,
                                              double max_seconds);

/// Calls `read` in a forked child (its output discarded, its exceptions ignored: the real read
/// in this process reports those). Throws FileError(path, ...) when the child dies by a signal
/// or a non-zero exit (a sanitizer report), or is still running after `max_seconds` (then it
/// is killed). Does nothing when fork() fails.
void ProbeInChildProcess(const std::string& path, const std::string& what,
                         const std::function<void()>& read, double max_seconds = 600.0);

}  // namespace cablefit
