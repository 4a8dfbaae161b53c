// The error tiers of errors.h: which type each tier throws, so that callers (the CLI, the FreeCAD
// module) can tell a bug in cablefit from bad data and from a stopped run.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <type_traits>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/solver_failure.h"

namespace cablefit {
namespace {

int Positive(int value) {
  CABLEFIT_REQUIRE(value > 0, "value must be positive");
  return value;
}

TEST(ErrorTiers, TheTiersAreDistinctTypes) {
  // Caller misuse is a logic error; bad data and a stopped run are runtime errors, and a stopped
  // run is not bad data (a handler for InvalidInput must not swallow a cancel).
  static_assert(std::is_base_of_v<std::logic_error, UsageError>);
  static_assert(std::is_base_of_v<std::runtime_error, InvalidInput>);
  static_assert(std::is_base_of_v<InvalidInput, FileError>);
  static_assert(std::is_base_of_v<std::runtime_error, Cancelled>);
  static_assert(!std::is_base_of_v<InvalidInput, Cancelled>);
  static_assert(std::is_base_of_v<Cancelled, DeadlineExceeded>);
  static_assert(std::is_base_of_v<std::runtime_error, SolverFailure>);
  static_assert(!std::is_base_of_v<InvalidInput, SolverFailure>);
}

TEST(ErrorTiers, RequireThrowsUsageErrorOnCallerMisuse) {
  EXPECT_EQ(Positive(3), 3);
  try {
    Positive(0);
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "value must be positive");
  }
}

TEST(ErrorTiers, MessagesAreOneLine) {
  EXPECT_STREQ(UsageError("a\nb").what(), "a\\nb");
  EXPECT_STREQ(InvalidInput("a\nb").what(), "a\\nb");
  EXPECT_STREQ(FileError("f.csv", "bad").what(), "f.csv: bad");
}

TEST(ErrorTiersDeathTest, CheckAbortsOnABrokenInvariant) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(CABLEFIT_CHECK(1 + 1 == 3, "arithmetic broke"), "internal error: arithmetic broke");
}

}  // namespace
}  // namespace cablefit
