// The helper-process runner behind the CAD reader's probe, the isolated tube sweep and the mesh
// skeleton: a crash, a hang or a failure in the child is reported to the parent, which goes on.
#include "cablefit/formats/helper_process.h"

#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <csignal>
#include <chrono>
#include <thread>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cablefit/core/base/cancellation.h"

namespace cablefit {
namespace {

std::optional<ChildOutcome> Shell(const std::string& script, double max_seconds) {
  return RunChildProcess("/bin/sh", {"-c", script}, max_seconds);
}

TEST(HelperProcess, ChildExitStatusComesBack) {
  const auto outcome = Shell("exit 7", 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 7);
  EXPECT_EQ(outcome->signal, 0);
  EXPECT_FALSE(outcome->timed_out);
}

TEST(HelperProcess, CrashInTheChildIsASignalNotADeadParent) {
  const auto outcome = Shell("kill -SEGV $$", 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->signal, SIGSEGV);
}

TEST(HelperProcess, HangingChildIsKilledAfterTheLimit) {
  const auto start = std::chrono::steady_clock::now();
  const auto outcome = Shell("sleep 60", 0.2);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_TRUE(outcome->timed_out);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30);
}

TEST(HelperProcess, TheThreadsDeadlineEndsTheWaitAndTheChild) {
  const CancellationScope deadline(0.2);
  EXPECT_THROW(Shell("sleep 60", 600.0), DeadlineExceeded);
}

TEST(HelperProcess, AProgramThatCannotBeStartedIsNoOutcome) {
  EXPECT_FALSE(RunChildProcess("/nonexistent/cablefit-no-such-program", {}, 10.0).has_value());
}

TEST(HelperProcess, DescriptorsAreHandedOverOnlyWhenAsked) {
  int pipe_fds[2];
  ASSERT_EQ(::pipe2(pipe_fds, O_CLOEXEC), 0);
  // Asked: the child writes into descriptor 3, which is our pipe.
  auto outcome = RunChildProcess("/bin/sh", {"-c", "echo handed >&3"}, 60.0, {{pipe_fds[1], 3}});
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 0);
  char buffer[16] = {};
  ASSERT_GT(::read(pipe_fds[0], buffer, sizeof buffer - 1), 0);
  EXPECT_EQ(std::string(buffer), "handed\n");
  // Not asked: a close-on-exec descriptor is not open in the child.
  outcome = RunChildProcess(
      "/bin/sh", {"-c", "test -e /proc/self/fd/" + std::to_string(pipe_fds[1]) + " && exit 9"},
      60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 1);  // the test failed, so `&&` gave the shell's status 1
  ::close(pipe_fds[0]);
  ::close(pipe_fds[1]);
}

// A stand-in helper: reports on descriptor 3 whether it was told to work (a byte on kGoFd) or
// let go (end of file there), and with which arguments.
struct WaitingScriptFile {
  std::string path = "/tmp/cablefit-test-waiting-child-" + std::to_string(::getpid()) + ".sh";
  WaitingScriptFile() {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs("#!/bin/sh\n[ \"$2\" = die ] && exit 3\n"
               "if [ \"$(head -c 1 <&5)\" = g ]; then echo \"told $*\" >&3; "
               "else echo unused >&3; fi\n",
               f);
    std::fclose(f);
    ::chmod(path.c_str(), 0755);
    ::setenv("CABLEFIT_TEST_WAITING_CHILD", path.c_str(), 1);
  }
  ~WaitingScriptFile() { std::remove(path.c_str()); }
};

void WaitingScript() { static const WaitingScriptFile file; }

std::string ReadAll(int fd) {
  std::string text;
  char buffer[256];
  ssize_t got = 0;
  while ((got = ::read(fd, buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<size_t>(got));
  return text;
}

TEST(WaitingHelper, RunsItsWorkWhenToldAndReportsLikeAChild) {
  WaitingScript();
  int out[2];
  ASSERT_EQ(::pipe2(out, O_CLOEXEC), 0);
  auto helper = WaitingHelper::Start("cablefit-test-waiting-child", {"sweeps-when-told", "3"},
                                     {{out[1], 3}});
  ASSERT_NE(helper, nullptr);
  ::close(out[1]);
  const auto outcome = helper->Run(60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 0);
  EXPECT_EQ(ReadAll(out[0]), "told " + std::to_string(::getpid()) + " sweeps-when-told 3\n");
  ::close(out[0]);
}

TEST(WaitingHelper, AnUnusedOneIsLetGoAndReaped) {
  WaitingScript();
  int out[2];
  ASSERT_EQ(::pipe2(out, O_CLOEXEC), 0);
  auto helper = WaitingHelper::Start("cablefit-test-waiting-child", {}, {{out[1], 3}});
  ASSERT_NE(helper, nullptr);
  ::close(out[1]);
  helper.reset();  // closes the go pipe and waits for the helper
  EXPECT_EQ(ReadAll(out[0]), "unused\n");
  ::close(out[0]);
  // Reaped: no child of ours is left, not even a zombie.
  EXPECT_EQ(::waitpid(-1, nullptr, WNOHANG), -1);
}

// A helper that ended before it was told (it could not load, or was killed): telling it must not
// end this process with SIGPIPE.
TEST(WaitingHelper, OneThatDiedBeforeItWasToldIsNoOutcomeNotADeadParent) {
  WaitingScript();
  auto helper = WaitingHelper::Start("cablefit-test-waiting-child", {"die"}, {});
  ASSERT_NE(helper, nullptr);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // it exits at once
  const auto outcome = helper->Run(60.0);
  if (outcome) {
    EXPECT_EQ(outcome->exit_code, 3);  // told in the instant before it ended
  }
  // Still here, and SIGPIPE is not left pending or blocked for this thread.
  sigset_t pending;
  sigpending(&pending);
  EXPECT_EQ(sigismember(&pending, SIGPIPE), 0);
  sigset_t mask;
  pthread_sigmask(SIG_BLOCK, nullptr, &mask);
  EXPECT_EQ(sigismember(&mask, SIGPIPE), 0);
}

TEST(WaitingHelper, AHelperThatDoesNotExistIsNoHelper) {
  ::setenv("CABLEFIT_TEST_ABSENT_CHILD", "/nonexistent/cablefit-no-such-helper", 1);
  EXPECT_EQ(WaitingHelper::Start("cablefit-test-absent-child", {}, {}), nullptr);
}

}  // namespace
}  // namespace cablefit
