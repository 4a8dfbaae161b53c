#include "cablefit/core/base/parallel_for.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "cablefit/core/base/cancellation.h"

namespace cablefit {
namespace {

TEST(ParallelFor, EveryIndexOnceAndEachWritesItsOwnSlot) {
  for (int threads : {1, 2, 5}) {
    std::vector<int> calls(100, 0);
    ParallelFor(100, threads, [&](int i) { calls[static_cast<size_t>(i)] += i; });
    for (int i = 0; i < 100; ++i) EXPECT_EQ(calls[static_cast<size_t>(i)], i) << threads;
  }
  ParallelFor(0, 4, [](int) { FAIL() << "no index"; });
}

TEST(ParallelFor, TheLowestFailedIndexIsRethrownAndNoMoreAreStarted) {
  std::atomic<int> started{0};
  try {
    ParallelFor(1000, 3, [&](int i) {
      ++started;
      if (i == 7 || i == 9) throw std::runtime_error("item " + std::to_string(i));
      // Items that take a while, as real ones do: on a loaded machine the thread holding item 7
      // can be descheduled before it throws, and instant items would all be started by then.
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "item 7");
  }
  EXPECT_LT(started.load(), 1000);
}

TEST(ParallelFor, TheCallersTimeLimitHoldsInTheWorkers) {
  const CancellationScope deadline(1e-9);
  EXPECT_THROW(ParallelFor(8, 4, [](int) { CheckCancelled(); }), DeadlineExceeded);
}

TEST(ParallelForEach, EveryIndexRunsAndFailuresStayWithTheirIndex) {
  for (int threads : {1, 4}) {
    std::vector<int> calls(50, 0);
    const std::vector<std::exception_ptr> errors = ParallelForEach(50, threads, [&](int i) {
      ++calls[static_cast<size_t>(i)];
      if (i % 9 == 2) throw std::runtime_error("item " + std::to_string(i));
    });
    ASSERT_EQ(errors.size(), 50u);
    for (int i = 0; i < 50; ++i) {
      EXPECT_EQ(calls[static_cast<size_t>(i)], 1) << i;
      EXPECT_EQ(errors[static_cast<size_t>(i)] != nullptr, i % 9 == 2) << i;
    }
  }
  EXPECT_TRUE(ParallelForEach(0, 3, [](int) { FAIL(); }).empty());
}

TEST(ParallelForEach, ACancelInsideOneItemDoesNotStopTheItemsAfterIt) {
  for (int threads : {1, 3}) {
    const std::vector<std::exception_ptr> errors = ParallelForEach(12, threads, [](int i) {
      const CancellationScope item(60.0);
      if (i % 4 == 1) RequestCancellation();
      CheckCancelled();
    });
    for (int i = 0; i < 12; ++i)
      EXPECT_EQ(errors[static_cast<size_t>(i)] != nullptr, i % 4 == 1) << threads << " " << i;
  }
}

TEST(ParallelForEach, TheCallersTimeLimitHoldsInEveryItem) {
  const CancellationScope deadline(1e-9);
  const std::vector<std::exception_ptr> errors = ParallelForEach(6, 3, [](int) { CheckCancelled(); });
  for (const std::exception_ptr& e : errors) {
    ASSERT_NE(e, nullptr);
    EXPECT_THROW(std::rethrow_exception(e), DeadlineExceeded);
  }
}

}  // namespace
}  // namespace cablefit
