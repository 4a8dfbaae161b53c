#include "cablefit/core/base/distinct_numbers.h"

#include <gtest/gtest.h>

namespace cablefit {
namespace {

TEST(DistinctNumbers, FourDigitsWhenTheyAlreadyDiffer) {
  EXPECT_EQ(DistinctNumbers(0.71, 0.6), std::make_pair(std::string("0.71"), std::string("0.6")));
}

TEST(DistinctNumbers, MoreDigitsUntilCloseValuesReadDifferent) {
  const auto [a, b] = DistinctNumbers(0.020102, 0.0201);
  EXPECT_NE(a, b);
  EXPECT_EQ(a, "0.020102");
  EXPECT_EQ(b, "0.0201");
}

TEST(DistinctNumbers, EqualValuesStayShort) {
  EXPECT_EQ(DistinctNumbers(1.5, 1.5), std::make_pair(std::string("1.5"), std::string("1.5")));
}

}  // namespace
}  // namespace cablefit
