// The forked-child runner behind the CAD reader's probe and the isolated tube sweep: a crash, a
// hang or a failure in the child is reported to the parent, which goes on.
#include "crash_probe.h"

#include <gtest/gtest.h>

#include <csignal>
#include <thread>

namespace cablefit {
namespace {

TEST(CrashProbe, ChildExitStatusComesBack) {
  const auto outcome = RunInChildProcess([] { return 7; }, 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 7);
  EXPECT_EQ(outcome->signal, 0);
  EXPECT_FALSE(outcome->timed_out);
}

TEST(CrashProbe, CrashInTheChildIsASignalNotADeadParent) {
  // A null read, as OCCT's did (under ASan the child aborts instead: still a signal).
  const auto outcome = RunInChildProcess(
      [] {
        std::raise(SIGSEGV);
        return 0;
      },
      60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_NE(outcome->signal, 0);
}

TEST(CrashProbe, HangingChildIsKilledAfterTheLimit) {
  const auto outcome = RunInChildProcess(
      [] {
        std::this_thread::sleep_for(std::chrono::seconds(60));
        return 0;
      },
      0.2);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_TRUE(outcome->timed_out);
}

TEST(CrashProbe, ExceptionInTheChildIsExitStatusOne) {
  const auto outcome = RunInChildProcess([]() -> int { throw 42; }, 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 1);
}

}  // namespace
}  // namespace cablefit
