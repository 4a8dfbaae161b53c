// Work that can crash or that must not depend on this process's history runs in a separate
// helper process, the executables cablefit-occt-child (CAD reads), cablefit-sweep-child (tube
// and flat-strip sweeps; OCCT's modelling libraries only, so it starts in a third of the time)
// and cablefit-mesh-child (mesh skeletons; a small program, quick to start):
// - OCCT 7.6 dereferences null handles on some corrupt STEP files (SIGSEGV in StepToGeom) and
//   its sweeps have read null faces, which no exception handler can catch: a crash or hang in
//   the helper becomes one failed input instead of the end of a whole batch;
// - CGAL's curve skeleton orders some of its work by heap addresses, so the same mesh gave other
//   routes after other work in the same process (and with --jobs 2): a fresh process gives the
//   same heap history, hence the same result, every time.
//
// The helper is started by posix_spawn, i.e. a fresh process image, never by a bare fork():
// relax reads and writes files in worker threads, and a fork() taken while another thread holds
// a lock (the allocator's, OCCT's statics', a sanitizer runtime's) leaves the child waiting on
// that lock forever.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cablefit {

/// How a helper process ended.
struct ChildOutcome {
  int signal = 0;          // the signal that ended it, 0 when it exited
  int exit_code = 0;       // its exit status when it exited
  bool timed_out = false;  // still running after the limit (then killed)
};

inline constexpr const char* kOcctHelper = "cablefit-occt-child";
inline constexpr const char* kSweepHelper = "cablefit-sweep-child";
inline constexpr const char* kMeshHelper = "cablefit-mesh-child";

/// The helper executable named `helper`: $CABLEFIT_OCCT_CHILD / $CABLEFIT_MESH_CHILD (the name in
/// capitals, '-' as '_') when set, else the file of that name beside the running executable, else
/// the one of the build tree this library was built in. Empty when none of them is an
/// executable file.
std::string HelperPath(const std::string& helper);
std::string OcctChildPath();  ///< HelperPath(kOcctHelper)

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

/// Runs the helper `helper` with `args` (after this process's id, so that it can tell when its
/// parent is gone). std::nullopt when there is no helper or it cannot be started: the caller
/// then does the work in this process.
std::optional<ChildOutcome> RunHelper(const std::string& helper,
                                      const std::vector<std::string>& args, double max_seconds,
                                      const std::vector<std::pair<int, int>>& inherit_fds = {});
std::optional<ChildOutcome> RunOcctChild(const std::vector<std::string>& args, double max_seconds,
                                         const std::vector<std::pair<int, int>>& inherit_fds = {});

/// The descriptor on which a WaitingHelper reads the byte that lets it start its work.
inline constexpr int kGoFd = 5;

/// A helper's exit status for a call it does not know (or a parent already gone).
inline constexpr int kHelperUsage = 64;

/// The main function of every helper executable, around its own `work(argc, argv)`: it dies
/// with its parent (kill -9 included) instead of working on as an orphan, returns kHelperUsage
/// at once when its parent (argv[1], as RunHelper passes it) is already gone, optionally tunes
/// the allocator as cablefit does (TuneAllocatorForSolves), and ends without exit handlers, as
/// a process that is simply ended (OCCT's per-process state is not torn down, and
/// LeakSanitizer in sanitizer builds does not report it).
[[noreturn]] void RunAsHelper(int argc, char** argv, int (*work)(int argc, char** argv),
                              bool tune_allocator);

/// The helper's side of a WaitingHelper: blocks until Run() lets it work (true) or the
/// WaitingHelper went unused (false: end of file on kGoFd).
bool WaitUntilTold();

/// A helper started before its work is ready: the executable loads (~0.03 s for OCCT's modelling
/// libraries, ~0.1 s with its 70 data exchange ones) while this process does other things, at
/// nice 10, then blocks reading one byte from descriptor kGoFd. Its arguments and descriptors are fixed at Start, so the work goes
/// through files it was handed (MemoryFile). Run() sends the byte and waits as RunChildProcess
/// does; an unused helper reads end-of-file when this object goes and exits (it is reaped).
/// The parent-death signal of the helpers follows the thread that starts them: start them on
/// a thread that outlives their use (the main thread).
class WaitingHelper {
 public:
  /// nullptr when the helper does not exist or cannot be started (do the work another way).
  static std::unique_ptr<WaitingHelper> Start(const std::string& helper,
                                              const std::vector<std::string>& args,
                                              const std::vector<std::pair<int, int>>& inherit_fds);
  /// Once: lets it work and waits at most `max_seconds` (and the calling thread's deadline).
  /// std::nullopt when it was lost before it could be told.
  std::optional<ChildOutcome> Run(double max_seconds);
  ~WaitingHelper();
  WaitingHelper(const WaitingHelper&) = delete;
  WaitingHelper& operator=(const WaitingHelper&) = delete;

 private:
  static constexpr int kWaitingNice = 10;
  WaitingHelper(int pid, int go_fd) : pid_(pid), go_fd_(go_fd) {}
  int pid_;
  int go_fd_;
};

/// An anonymous in-memory file (memfd) to hand data to and from the helper: nothing is left in
/// a temporary folder when this process or the helper is killed. Close-on-exec, so children
/// that other threads start at the same time do not inherit it; RunChildProcess hands it to the
/// helper explicitly (as descriptor 3 or 4, 5 being a WaitingHelper's go pipe: ours is kept above
/// those, so that dup2 never maps a
/// descriptor onto itself, which would leave close-on-exec set).
class MemoryFile {
 public:
  explicit MemoryFile(const char* name);
  ~MemoryFile();
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  bool ok() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  /// A path that opens the file anew from the start, for path-based readers and writers.
  std::string path() const { return "/proc/self/fd/" + std::to_string(fd_); }

 private:
  static constexpr int kHelperFdLast = kGoFd;
  int fd_;
};

}  // namespace cablefit
