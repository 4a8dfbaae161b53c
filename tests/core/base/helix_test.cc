#include "cablefit/core/base/helix.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cablefit {
namespace {

// The chord polyline keeps the helix's length, ends and radius: a coil drawn from it is the
// coil that was meant.
TEST(SampleHelix, LengthEndsAndRadiusAreTheHelixs) {
  const double r = 0.02, p = 0.015, turns = 3.5;
  const Polyline h = SampleHelix(r, p, turns);
  ASSERT_EQ(h.size(), static_cast<int>(96 * turns) + 1);
  const double exact = turns * std::hypot(2 * M_PI * r, p);
  EXPECT_NEAR(h.s[h.size() - 1], exact, 1e-3 * exact);  // chords: shorter by ~ (2 pi / 96)^2 / 24
  EXPECT_LT(h.s[h.size() - 1], exact);
  EXPECT_LT((h.points.col(0) - Vec3(r, 0, 0)).norm(), 1e-15);
  EXPECT_LT((h.points.col(h.size() - 1) - Vec3(-r, 0, p * turns)).norm(), 1e-12);
  for (int k = 0; k < h.size(); ++k)
    EXPECT_NEAR(h.points.col(k).head<2>().norm(), r, 1e-15);
}

}  // namespace
}  // namespace cablefit
