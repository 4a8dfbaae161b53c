#include "cablefit/app/base/batch_pool.h"

#include <gtest/gtest.h>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/solver_failure.h"

#ifdef __linux__
#include <sched.h>
#endif

#include <atomic>
#include <new>
#include <stdexcept>
#include <thread>
#include <vector>

namespace cablefit::addin {
namespace {

TEST(ResolveJobs, ClampsToItemsAndAtLeastOne) {
  EXPECT_EQ(ResolveJobs(4, 2), 2);
  EXPECT_EQ(ResolveJobs(1, 10), 1);
  EXPECT_EQ(ResolveJobs(3, 0), 1);
  EXPECT_GE(ResolveJobs(0, 100), 1);  // hardware concurrency
}

#ifdef __linux__
// `taskset -c 0 cablefit ...` (or a container's cpuset) leaves one core whatever the machine
// has: more threads than that would only take turns.
TEST(UsableCores, FollowsTheCpuAffinity) {
  cpu_set_t before;
  ASSERT_EQ(sched_getaffinity(0, sizeof(before), &before), 0);
  EXPECT_EQ(UsableCores(), CPU_COUNT(&before));
  int first = 0;
  while (!CPU_ISSET(first, &before)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
  const int cores = UsableCores();
  const int jobs = ResolveJobs(0, 100);
  ASSERT_EQ(sched_setaffinity(0, sizeof(before), &before), 0);
  EXPECT_EQ(cores, 1);
  EXPECT_EQ(jobs, 1);
}
#endif

TEST(RunBatch, RunsEveryItemOnceAndKeepsFailuresPerItem) {
  for (int jobs : {1, 3}) {
    std::vector<std::atomic<int>> calls(20);
    const auto errors = RunBatch(20, jobs, [&](int i) {
      ++calls[static_cast<std::size_t>(i)];
      if (i % 7 == 3) throw std::runtime_error("item " + std::to_string(i));
    });
    ASSERT_EQ(errors.size(), 20u);
    for (int i = 0; i < 20; ++i) {
      EXPECT_EQ(calls[static_cast<std::size_t>(i)], 1) << i;
      EXPECT_EQ(errors[static_cast<std::size_t>(i)] != nullptr, i % 7 == 3) << i;
    }
    try {
      std::rethrow_exception(errors[10]);
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "item 10");
    }
  }
}

TEST(RunBatch, RunsInParallel) {
  // Two items that each wait for the other to start can only finish on two threads.
  std::atomic<int> started{0};
  const auto errors = RunBatch(2, 2, [&](int) {
    ++started;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (started < 2 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    if (started < 2) throw std::runtime_error("ran alone");
  });
  EXPECT_EQ(errors[0], nullptr);
  EXPECT_EQ(errors[1], nullptr);
}

// Every tier of error in one item becomes that item's one-line problem; the other items run.
TEST(RunBatch, EachErrorTierOfOneItemIsItsOneLineProblem) {
  const auto errors = RunBatch(7, 2, [](int i) {
    if (i == 0) throw InvalidInput("bad value");
    if (i == 1) throw FileError("a.csv", "row 3: not a number");
    if (i == 2) throw UsageError("sizes differ");
    if (i == 3) throw DeadlineExceeded("timed out after 2 s");
    if (i == 4) throw std::bad_alloc();
    if (i == 5) throw SolverFailure("the nominal set-up could not be solved");
  });
  ASSERT_EQ(errors.size(), 7u);
  EXPECT_EQ(ErrorText(errors[0]), "bad value");
  EXPECT_EQ(ErrorText(errors[1]), "row 3: not a number");  // the caller names the file
  EXPECT_EQ(ErrorText(errors[2]), "internal error: sizes differ");
  EXPECT_EQ(ErrorText(errors[3]), "timed out after 2 s");
  EXPECT_EQ(ErrorText(errors[4]), "out of memory");
  EXPECT_EQ(ErrorText(errors[5]), "the nominal set-up could not be solved");
  EXPECT_EQ(errors[6], nullptr);
}

TEST(RunBatch, NoItemsIsNothing) { EXPECT_TRUE(RunBatch(0, 4, [](int) { FAIL(); }).empty()); }

}  // namespace
}  // namespace cablefit::addin
