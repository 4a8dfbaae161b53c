#include "cablefit/formats/helper_process.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/allocator_tuning.h"

extern char** environ;

namespace cablefit {
namespace {

bool IsExecutableFile(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

// "cablefit-occt-child" -> "CABLEFIT_OCCT_CHILD".
std::string EnvironmentName(const std::string& helper) {
  std::string name;
  for (const char c : helper) name += c == '-' ? '_' : static_cast<char>(std::toupper(c));
  return name;
}

std::string FindHelper(const std::string& helper) {
  if (const char* env = std::getenv(EnvironmentName(helper).c_str()); env != nullptr && *env != '\0') {
    return IsExecutableFile(env) ? std::string(env) : std::string();
  }
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path beside = self.parent_path() / helper;
    if (IsExecutableFile(beside)) return beside.string();
  }
#ifdef CABLEFIT_HELPER_BUILD_DIR
  // Test executables and the FreeCAD module run from other folders of the build tree.
  const std::filesystem::path built = std::filesystem::path(CABLEFIT_HELPER_BUILD_DIR) / helper;
  if (IsExecutableFile(built)) return built.string();
#endif
  return {};
}

// Kills and reaps the child when the caller leaves RunChildProcess by an exception.
class ChildGuard {
 public:
  explicit ChildGuard(pid_t pid) : pid_(pid) {}
  ~ChildGuard() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  ChildGuard(const ChildGuard&) = delete;
  ChildGuard& operator=(const ChildGuard&) = delete;
  void Release() { pid_ = -1; }

 private:
  pid_t pid_;
};

}  // namespace

std::string HelperPath(const std::string& helper) {
  static std::mutex mutex;
  static std::map<std::string, std::string> found;
  const std::lock_guard lock(mutex);
  const auto it = found.find(helper);
  if (it != found.end()) return it->second;
  return found[helper] = FindHelper(helper);
}

std::string OcctChildPath() { return HelperPath(kOcctHelper); }

namespace {

// Starts `program` as RunChildProcess describes; -1 when it cannot be started.
pid_t SpawnChild(const std::string& program, const std::vector<std::string>& args,
                 const std::vector<std::pair<int, int>>& inherit_fds, bool keep_stderr) {
  std::vector<std::string> argv_storage;
  argv_storage.reserve(args.size() + 1);
  argv_storage.push_back(program);
  argv_storage.insert(argv_storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_storage) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  if (::posix_spawn_file_actions_init(&actions) != 0) return -1;
  ::posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (!keep_stderr) {
    ::posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  // dup2 clears close-on-exec on the target; callers pass descriptors opened with O_CLOEXEC so
  // that children spawned by other threads at the same time do not inherit them.
  for (const auto& [from, to] : inherit_fds) {
    ::posix_spawn_file_actions_adddup2(&actions, from, to);
  }
  // Same process group as cablefit: a Ctrl-C at the terminal ends the child too.
  pid_t pid = -1;
  const int rc = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// Waits for the started child `pid` as RunChildProcess describes.
std::optional<ChildOutcome> WaitForChild(pid_t pid, double max_seconds) {
  ChildGuard guard(pid);
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      guard.Release();
      return std::nullopt;  // lost the child
    }
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        max_seconds) {
      ChildOutcome outcome;
      outcome.timed_out = true;
      return outcome;  // the guard kills and reaps it
    }
    CheckCancelled();  // throws; the guard kills and reaps the child
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  guard.Release();
  ChildOutcome outcome;
  if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  return outcome;
}

// A helper's arguments: this process's id first, so that it can end itself when its parent is
// gone, then `args`.
std::vector<std::string> HelperArguments(const std::vector<std::string>& args) {
  std::vector<std::string> out{std::to_string(::getpid())};
  out.insert(out.end(), args.begin(), args.end());
  return out;
}

// A descriptor moved above the ones helpers receive (dup2 never maps one onto itself, which
// would leave close-on-exec set), close-on-exec.
int AboveHelperFds(int fd, int last) {
  if (fd < 0 || fd > last) return fd;
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, last + 1);
  ::close(fd);
  return moved;
}

}  // namespace

std::optional<ChildOutcome> RunChildProcess(const std::string& program,
                                            const std::vector<std::string>& args,
                                            double max_seconds,
                                            const std::vector<std::pair<int, int>>& inherit_fds,
                                            bool keep_stderr) {
  const pid_t pid = SpawnChild(program, args, inherit_fds, keep_stderr);
  if (pid < 0) return std::nullopt;
  return WaitForChild(pid, max_seconds);
}

std::unique_ptr<WaitingHelper> WaitingHelper::Start(
    const std::string& helper, const std::vector<std::string>& args,
    const std::vector<std::pair<int, int>>& inherit_fds) {
  const std::string program = HelperPath(helper);
  if (program.empty()) return nullptr;
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) return nullptr;
  const int read_end = AboveHelperFds(ends[0], kGoFd);
  const int write_end = AboveHelperFds(ends[1], kGoFd);
  if (read_end < 0 || write_end < 0) {
    if (read_end >= 0) ::close(read_end);
    if (write_end >= 0) ::close(write_end);
    return nullptr;
  }
  std::vector<std::pair<int, int>> fds = inherit_fds;
  fds.emplace_back(read_end, kGoFd);
  const pid_t pid = SpawnChild(program, HelperArguments(args), fds, false);
  ::close(read_end);
  if (pid < 0) {
    ::close(write_end);
    return nullptr;
  }
  // It loads while this process works: behind that work on a busy core.
  ::setpriority(PRIO_PROCESS, static_cast<id_t>(pid), kWaitingNice);
  return std::unique_ptr<WaitingHelper>(new WaitingHelper(pid, write_end));
}

std::optional<ChildOutcome> WaitingHelper::Run(double max_seconds) {
  CABLEFIT_REQUIRE(go_fd_ >= 0, "WaitingHelper::Run called twice");
  // A helper that died meanwhile (it could not load, or was killed) has closed the pipe: the
  // write then fails with EPIPE, and the SIGPIPE it raises must not end this process. Blocked
  // for this thread and taken back if it came.
  sigset_t pipe_signal, previous;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  ::pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
  const char go = 'g';
  ssize_t written = 0;
  while ((written = ::write(go_fd_, &go, 1)) < 0 && errno == EINTR) {
  }
  const bool sent = written == 1;
  if (!sent && errno == EPIPE) {
    const timespec no_wait{0, 0};
    while (::sigtimedwait(&pipe_signal, nullptr, &no_wait) < 0 && errno == EINTR) {
    }
  }
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  ::close(go_fd_);
  go_fd_ = -1;
  const pid_t pid = pid_;
  pid_ = -1;
  if (!sent) {
    ChildGuard reap(pid);  // it ends on the closed pipe, or is killed
    return std::nullopt;
  }
  return WaitForChild(pid, max_seconds);
}

WaitingHelper::~WaitingHelper() {
  if (go_fd_ >= 0) ::close(go_fd_);  // end of file: an unused helper exits
  if (pid_ > 0) {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
}

std::optional<ChildOutcome> RunHelper(const std::string& helper,
                                      const std::vector<std::string>& args, double max_seconds,
                                      const std::vector<std::pair<int, int>>& inherit_fds) {
  const std::string program = HelperPath(helper);
  if (program.empty()) return std::nullopt;
  return RunChildProcess(program, HelperArguments(args), max_seconds, inherit_fds);
}

std::optional<ChildOutcome> RunOcctChild(const std::vector<std::string>& args, double max_seconds,
                                         const std::vector<std::pair<int, int>>& inherit_fds) {
  return RunHelper(kOcctHelper, args, max_seconds, inherit_fds);
}

MemoryFile::MemoryFile(const char* name)
    : fd_(AboveHelperFds(::memfd_create(name, MFD_CLOEXEC), kHelperFdLast)) {}

MemoryFile::~MemoryFile() {
  if (fd_ >= 0) ::close(fd_);
}

void RunAsHelper(int argc, char** argv, int (*work)(int argc, char** argv), bool tune_allocator) {
  if (argc < 3) std::_Exit(kHelperUsage);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (std::to_string(::getppid()) != argv[1]) std::_Exit(kHelperUsage);
  if (tune_allocator) TuneAllocatorForSolves();
  std::_Exit(work(argc, argv));
}

bool WaitUntilTold() {
  char go = 0;
  ssize_t got = 0;
  while ((got = ::read(kGoFd, &go, 1)) < 0 && errno == EINTR) {
  }
  return got == 1;
}

}  // namespace cablefit
