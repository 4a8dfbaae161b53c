#include "crash_probe.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "cablefit/core/errors.h"

namespace cablefit {

void ProbeInChildProcess(const std::string& path, const std::string& what,
                         const std::function<void()>& read, double max_seconds) {
  const pid_t pid = ::fork();
  if (pid < 0) return;
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    try {
      read();
    } catch (...) {
    }
    ::_exit(0);  // no atexit handlers, no flushing of the parent's buffered output
  }
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return;  // lost the child: the real read decides
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        max_seconds) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      throw FileError(path, what + " did not finish within " +
                                std::to_string(static_cast<int>(max_seconds)) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFSIGNALED(status))
    throw FileError(path, what + " crashed on this file (signal " +
                              std::to_string(WTERMSIG(status)) + ": " +
                              ::strsignal(WTERMSIG(status)) + "); the file is corrupt");
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    throw FileError(path, what + " failed on this file (exit status " +
                              std::to_string(WEXITSTATUS(status)) + "); the file is corrupt");
}

}  // namespace cablefit
