// The helper-process runner behind the CAD reader's probe, the isolated tube sweep and the mesh
// skeleton: a crash, a hang or a failure in the child is reported to the parent, which goes on.
#include "cablefit/formats/helper_process.h"

#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <csignal>

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

}  // namespace
}  // namespace cablefit
