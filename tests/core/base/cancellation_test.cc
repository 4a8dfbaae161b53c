// One cancellation mechanism: a scope per thread that a time limit or a progress callback
// returning false trips, checked by CheckCancelled().
#include "cablefit/core/base/cancellation.h"

#include <gtest/gtest.h>

#include <string>
#include <thread>

namespace cablefit {
namespace {

TEST(Cancellation, NothingIsCancelledOutsideAScope) {
  EXPECT_FALSE(CancellationRequested());
  EXPECT_NO_THROW(CheckCancelled());
  RequestCancellation();  // no scope: nothing to stop, and nothing left behind
  EXPECT_FALSE(CancellationRequested());
  EXPECT_NO_THROW(CheckCancelled());
}

TEST(Cancellation, ATimeLimitThrowsDeadlineExceeded) {
  const CancellationScope scope(1e-9);
  EXPECT_TRUE(CancellationRequested());
  try {
    CheckCancelled();
    FAIL() << "no exception";
  } catch (const DeadlineExceeded& e) {
    EXPECT_STREQ(e.what(), "timed out after 1e-09 s");
  }
}

TEST(Cancellation, AProgressCallbackReturningFalseCancelsTheScope) {
  const ProgressCallback keep_going = [](double, const std::string&) { return true; };
  const ProgressCallback stop = [](double, const std::string&) { return false; };
  {
    const CancellationScope scope;
    EXPECT_NO_THROW(ReportProgress(keep_going, 0.5, "half"));
    EXPECT_NO_THROW(ReportProgress(ProgressCallback{}, 0.5, "no callback"));
    EXPECT_NO_THROW(CheckCancelled());
    EXPECT_THROW(ReportProgress(stop, 0.6, "stop"), Cancelled);
    EXPECT_TRUE(CancellationRequested());
    EXPECT_THROW(CheckCancelled(), Cancelled);  // every later check point stops too
  }
  EXPECT_FALSE(CancellationRequested());  // the next run on this thread starts afresh
}

TEST(Cancellation, ACancelInsideAnItemStopsTheRunButAnItemsTimeoutDoesNot) {
  const CancellationScope run;
  {
    const CancellationScope item(1e-9);
    EXPECT_THROW(CheckCancelled(), DeadlineExceeded);
  }
  EXPECT_NO_THROW(CheckCancelled());  // the next item still runs
  {
    const CancellationScope item(60.0);
    RequestCancellation();
  }
  EXPECT_THROW(CheckCancelled(), Cancelled);  // the user stopped the whole run
}

TEST(Cancellation, AWorkerThreadContinuesItsParentsScope) {
  auto in_worker = [](const CancellationState& parent) {
    bool timed_out = false, cancelled = false;
    std::thread([&] {
      const CancellationScope scope(parent);
      try {
        CheckCancelled();
      } catch (const DeadlineExceeded&) {
        timed_out = true;
      } catch (const Cancelled&) {
        cancelled = true;
      }
    }).join();
    return std::make_pair(timed_out, cancelled);
  };
  {
    const CancellationScope item(1e-9);
    EXPECT_EQ(in_worker(CurrentCancellation()), std::make_pair(true, false));
  }
  {
    const CancellationScope item(60.0);
    EXPECT_EQ(in_worker(CurrentCancellation()), std::make_pair(false, false));
    RequestCancellation();
    EXPECT_EQ(in_worker(CurrentCancellation()), std::make_pair(false, true));
  }
}

}  // namespace
}  // namespace cablefit
