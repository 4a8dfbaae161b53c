#include "crash_probe.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "cablefit/core/base/errors.h"

namespace cablefit {

std::optional<ChildOutcome> RunInChildProcess(const std::function<int()>& body,
                                              double max_seconds) {
  const pid_t pid = ::fork();
  if (pid < 0) return std::nullopt;
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    int code = 1;
    try {
      code = body();
    } catch (...) {
    }
    ::_exit(code);  // no atexit handlers, no flushing of the parent's buffered output
  }
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return std::nullopt;  // lost the child
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        max_seconds) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      ChildOutcome outcome;
      outcome.timed_out = true;
      return outcome;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ChildOutcome outcome;
  if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  return outcome;
}

void ProbeInChildProcess(const std::string& path, const std::string& what,
                         const std::function<void()>& read, double max_seconds) {
  const std::optional<ChildOutcome> outcome = RunInChildProcess(
      [&] {
        try {
          read();
        } catch (...) {
        }
        return 0;
      },
      max_seconds);
  if (!outcome) return;  // the real read decides
  if (outcome->timed_out)
    throw FileError(path, what + " did not finish within " +
                              std::to_string(static_cast<int>(max_seconds)) + " s");
  if (outcome->signal != 0)
    throw FileError(path, what + " crashed on this file (signal " +
                              std::to_string(outcome->signal) + ": " +
                              ::strsignal(outcome->signal) + "); the file is corrupt");
  if (outcome->exit_code != 0)
    throw FileError(path, what + " failed on this file (exit status " +
                              std::to_string(outcome->exit_code) + "); the file is corrupt");
}

}  // namespace cablefit
