// K(k), E(k) against tabulated values (Abramowitz & Stegun table 17.1, m = k^2) and Legendre's
// relation E K' + E' K - K K' = pi/2 (A&S 17.3.13).
#include "cablefit/core/force/force_elliptic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

TEST(ForceElliptic, ZeroModulusIsQuarterCircle) {
  const CompleteElliptic ke = CompleteEllipticIntegrals(0.0);
  EXPECT_NEAR(ke.K, std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(ke.E, std::numbers::pi / 2, 1e-15);
}

TEST(ForceElliptic, KnownValues) {
  // m = 1/2 (k = 1/sqrt 2): K = 1.854074677301372, E = 1.350643881047675 (A&S 17.1).
  const CompleteElliptic half = CompleteEllipticIntegrals(std::sqrt(0.5));
  EXPECT_NEAR(half.K, 1.8540746773013719, 1e-15);
  EXPECT_NEAR(half.E, 1.3506438810476755, 1e-15);
  // m = 0.25 (k = 0.5): K = 1.685750354812596, E = 1.467462209339427.
  const CompleteElliptic quarter = CompleteEllipticIntegrals(0.5);
  EXPECT_NEAR(quarter.K, 1.685750354812596, 1e-15);
  EXPECT_NEAR(quarter.E, 1.467462209339427, 1e-15);
  // m = 0.9 : K = 2.578092113348173, E = 1.104774732704073.
  const CompleteElliptic m09 = CompleteEllipticIntegrals(std::sqrt(0.9));
  EXPECT_NEAR(m09.K, 2.578092113348173, 2e-15);
  EXPECT_NEAR(m09.E, 1.104774732704073, 2e-15);
}

TEST(ForceElliptic, LegendreRelationHolds) {
  for (double k : {0.05, 0.3, 0.6, 0.8, 0.95, 0.999}) {
    const CompleteElliptic a = CompleteEllipticIntegrals(k);
    const CompleteElliptic b = CompleteEllipticIntegrals(std::sqrt((1 - k) * (1 + k)));
    EXPECT_NEAR(a.E * b.K + b.E * a.K - a.K * b.K, std::numbers::pi / 2, 1e-13) << "k=" << k;
  }
}

TEST(ForceElliptic, RejectsModulusOutsideRange) {
  EXPECT_THROW(CompleteEllipticIntegrals(1.0), InvalidInput);
  EXPECT_THROW(CompleteEllipticIntegrals(-0.1), InvalidInput);
  EXPECT_THROW(CompleteEllipticIntegrals(std::nan("")), InvalidInput);
}

}  // namespace
}  // namespace cablefit
