// OCCT work that can crash the process runs first in a separate helper process, the executable
// cablefit-occt-child: OCCT 7.6 dereferences null handles on some corrupt STEP files (SIGSEGV in
// StepToGeom) and its sweeps have read null faces, which no exception handler can catch. A crash
// or hang in the helper becomes one failed input instead of the end of a whole batch.
//
// The helper is started by posix_spawn, i.e. a fresh process image, never by a bare fork():
// relax reads and writes files in worker threads, and a fork() taken while another thread holds
// a lock (the allocator's, OCCT's statics', a sanitizer runtime's) leaves the child waiting on
// that lock forever.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace cablefit {

/// How a helper process ended.
struct ChildOutcome {
  int signal = 0;          // the signal that ended it, 0 when it exited
  int exit_code = 0;       // its exit status when it exited
  bool timed_out = false;  // still running after the limit (then killed)
};

/// The helper executable: $CABLEFIT_OCCT_CHILD when set, else cablefit-occt-child beside the
/// running executable, else the one of the build tree this library was built in. Empty when
/// none of them is an executable file.
std::string OcctChildPath();

/// Runs `program` with `args` (argv[1..]) in a new process: same environment and working folder,
/// standard input and output from/to /dev/null, standard error to /dev/null unless
/// `keep_stderr`. Each `inherit_fds` entry {from, to} makes this process's descriptor `from`
/// the child's descriptor `to`. Waits at most `max_seconds` (and no longer than the calling
/// thread's deadline, see cablefit/core/base/cancellation.h: then the child is killed and
/// DeadlineExceeded thrown). std::nullopt when the process cannot be started or is lost.
std::optional<ChildOutcome> RunChildProcess(const std::string& program,
                                            const std::vector<std::string>& args,
                                            double max_seconds,
                                            const std::vector<std::pair<int, int>>& inherit_fds = {},
                                            bool keep_stderr = false);

/// Runs the helper with `args`. std::nullopt when there is no helper or it cannot be started:
/// the caller then does the work in this process.
std::optional<ChildOutcome> RunOcctChild(const std::vector<std::string>& args, double max_seconds,
                                         const std::vector<std::pair<int, int>>& inherit_fds = {});

/// Runs the helper with `args` as a probe of the file `path`: throws FileError(path, ...) when it
/// dies by a signal or exits non-zero (a sanitizer report), or is still running after
/// `max_seconds` (then it is killed). Does nothing when the helper cannot be started.
void ProbeFileInChild(const std::string& path, const std::string& what,
                      const std::vector<std::string>& args, double max_seconds);

}  // namespace cablefit
