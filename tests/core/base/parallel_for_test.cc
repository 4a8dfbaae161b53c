#include "cablefit/core/base/parallel_for.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace cablefit
