#include "cablefit/core/rod/initial_shape.h"

#include <gtest/gtest.h>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/core/base/errors.h"
#include "test_support.h"

namespace cablefit {
namespace {

RodSpec LevelSag(double span) {
  RodSpec s;
  s.length = 0.6;
  s.material.bending_stiffness = 0.01;
  s.material.torsional_stiffness = 0.008;
  s.material.linear_density = 0.07;
  SupportSpec a, b;
  a.position = Vec3(0, 0, 0.5);
  a.tangent = b.tangent = Vec3(1, 0, 0);
  a.normal = b.normal = Vec3(0, 0, 1);
  b.s = 0.6;
  b.position = a.position + Vec3(span, 0, 0);
  s.supports = {a, b};
  return s;
}

// Clamp tangents along the chord used to fold the default curve back onto a line (a singular
// start): the default shape must bulge instead, with the right length and end tangents.
TEST(InitialShapeTest, DefaultCurveOfALevelSpanHasTheLengthAndSagsDown) {
  for (double span : {0.2, 0.45, 0.59}) {
    const RodSpec spec = LevelSag(span);
    const Polyline c = DefaultInitialCurve(spec);
    EXPECT_NEAR(c.ChordLength(), spec.length, 2e-3 * spec.length);
    EXPECT_LT(c.points.row(2).minCoeff(), 0.5 - 1e-3);
    RodSimulator sim;
    const SimulationResult r = sim.Simulate(spec);
    ASSERT_TRUE(r.converged) << r.solution.summary.BriefReport();
    EXPECT_TRUE(r.solution.summary.stable) << "span " << span;
    EXPECT_LT(r.solution.centerline.points.row(2).minCoeff(), 0.5 - 1e-3);
  }
}

TEST(InitialShapeTest, ReparameteriseRejectsBadShapes) {
  Polyline p;
  p.points.resize(3, 1);
  p.points.setZero();
  EXPECT_THROW_WITH(ReparameteriseToLength(p, 1.0), InvalidInput, "at least 2");
  p.points.resize(3, 2);
  p.points << 0, 1, 0, NAN, 0, 0;
  EXPECT_THROW_WITH(ReparameteriseToLength(p, 1.0), InvalidInput, "non-finite");
}

}  // namespace
}  // namespace cablefit
