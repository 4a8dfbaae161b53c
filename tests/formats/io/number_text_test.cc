#include "cablefit/formats/number_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cablefit {
namespace {

TEST(NumberText, FormatRoundTripsExactly) {
  for (double v : {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23, 0.0, -0.0,
                   std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max()}) {
    double back = 1.0;
    ASSERT_EQ(ParseDouble(FormatDouble(v), &back), ParsedNumber::kFinite) << FormatDouble(v);
    EXPECT_EQ(back, v);
  }
  EXPECT_EQ(FormatDouble(0.5), "0.5");
  EXPECT_EQ(FormatDouble(std::nan("")), "nan");
  EXPECT_EQ(FormatDouble(-HUGE_VAL), "-inf");
}

TEST(NumberText, ParseClassifiesCells) {
  double v = 0.0;
  EXPECT_EQ(ParseDouble(" +1.5e3 ", &v), ParsedNumber::kFinite);
  EXPECT_EQ(v, 1500.0);
  EXPECT_EQ(ParseDouble("NaN", &v), ParsedNumber::kNaN);
  EXPECT_EQ(ParseDouble("-inf", &v), ParsedNumber::kInfinite);
  EXPECT_EQ(ParseDouble("1e400", &v), ParsedNumber::kInfinite);
  EXPECT_EQ(ParseDouble("1e-400", &v), ParsedNumber::kFinite);
  EXPECT_EQ(v, 0.0);
  v = 7.0;
  EXPECT_EQ(ParseDouble("", &v), ParsedNumber::kNotANumber);
  EXPECT_EQ(ParseDouble("1.5x", &v), ParsedNumber::kNotANumber);
  EXPECT_EQ(ParseDouble("1,5", &v), ParsedNumber::kNotANumber);
  EXPECT_EQ(ParseDouble("0x10", &v), ParsedNumber::kNotANumber);
  EXPECT_EQ(v, 7.0);
}

TEST(NumberText, ParseInteger) {
  long v = 0;
  EXPECT_TRUE(ParseInteger(" 12 ", &v));
  EXPECT_EQ(v, 12);
  EXPECT_TRUE(ParseInteger("-3", &v));
  EXPECT_EQ(v, -3);
  EXPECT_FALSE(ParseInteger("1.0", &v));
  EXPECT_FALSE(ParseInteger("", &v));
  EXPECT_FALSE(ParseInteger("99999999999999999999999", &v));
}

}  // namespace
}  // namespace cablefit
