// Sleeves (RodSpec::sleeves): stiffness and weight added over part of a cable, against closed
// forms with a piecewise bending stiffness, torsional stiffness and mass per length.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/core/solver/rod_solution.h"

namespace cablefit {
namespace {

// Tip (x, z) of a cantilever of length 1 with EI = ei_near on [0, a) and ei_far on [a, 1] under
// a dead tip load p along -z (large deflection): RK4 shooting on M(0) of
//   phi' = M / EI(x), M' = -p cos(phi), x' = cos(phi), z' = -sin(phi), M(1) = 0.
Eigen::Vector2d ShootSleevedCantilever(double p, double a, double ei_near, double ei_far) {
  auto integrate = [&](double m0, double* m_end) {
    const int n = 40000;  // a step boundary falls on x = a for the a used below
    const double h = 1.0 / n;
    Eigen::Vector4d y(0, m0, 0, 0);  // phi, M, x, z
    double x = 0.0;
    for (int i = 0; i < n; ++i, x += h) {
      // The piece of this step (its midpoint's), so that no stage straddles x = a.
      const double ei = x + 0.5 * h < a ? ei_near : ei_far;
      auto f = [&](const Eigen::Vector4d& v) {
        return Eigen::Vector4d(v[1] / ei, -p * std::cos(v[0]), std::cos(v[0]), -std::sin(v[0]));
      };
      const Eigen::Vector4d k1 = f(y), k2 = f(y + 0.5 * h * k1), k3 = f(y + 0.5 * h * k2),
                            k4 = f(y + h * k3);
      y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    *m_end = y[1];
    return Eigen::Vector2d(y[2], y[3]);
  };
  double m = p;  // the linear moment at the clamp
  for (int it = 0; it < 50; ++it) {
    double f0, f1;
    integrate(m, &f0);
    integrate(m + 1e-7, &f1);
    const double dm = -f0 / ((f1 - f0) / 1e-7);
    m += dm;
    if (std::abs(dm) < 1e-14) break;
  }
  double unused;
  return integrate(m, &unused);
}

RodSpec Cantilever() {
  RodSpec spec;
  spec.length = 1.0;
  spec.material.bending_stiffness = 1.0;
  spec.material.torsional_stiffness = 0.8;
  spec.gravity = Vec3::Zero();
  SupportSpec clamp;
  clamp.tangent = Vec3::UnitX();
  clamp.normal = Vec3::UnitZ();
  spec.supports = {clamp};
  return spec;
}

TEST(SleeveTest, ASleeveStiffensTheCantileverAsThePiecewiseElastica) {
  // A sleeve of 3x the cable's EI over the clamped 40 %, and a tip load bending the cable far
  // out of the linear range.
  const double a = 0.4, p = 2.0;
  RodSpec spec = Cantilever();
  spec.point_loads.push_back({1.0, Vec3(0, 0, -p)});
  spec.sleeves.push_back({0.0, a, 3.0, 0.0, 0.0});
  const Eigen::Vector2d ref = ShootSleevedCantilever(p, a, 4.0, 1.0);
  const Eigen::Vector2d bare = ShootSleevedCantilever(p, a, 1.0, 1.0);
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(spec);
  ASSERT_TRUE(r.converged);
  const Polyline& c = r.solution.centerline;
  const double tip = c.points(2, c.size() - 1);
  std::printf("tip deflection %.10f m (piecewise elastica %.10f, without the sleeve %.10f)\n", -tip,
              -ref[1], -bare[1]);
  EXPECT_NEAR(tip, ref[1], 1e-5 * std::abs(ref[1]));
  EXPECT_NEAR(c.points(0, c.size() - 1), ref[0], 1e-5);
  // The sleeve matters: without it the tip goes far lower.
  EXPECT_GT(std::abs(bare[1] - ref[1]), 0.05);
}

TEST(SleeveTest, ASleeveTwistsInSeriesWithTheCable) {
  // Both ends clamped on a straight cable, the far clamp turned by phi about the axis: the
  // torque is phi / sum(length_i / GJ_i) (a sleeve doubling GJ over [0.2, 0.7]).
  const double phi = 0.3;
  RodSpec spec = Cantilever();
  SupportSpec far;
  far.s = 1.0;
  far.position = Vec3(1, 0, 0);
  far.tangent = Vec3::UnitX();
  far.normal = Vec3(0, -std::sin(phi), std::cos(phi));
  spec.supports.push_back(far);
  spec.sleeves.push_back({0.2, 0.7, 0.0, 0.8, 0.0});
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(spec);
  ASSERT_TRUE(r.converged);
  const double torque = phi / (0.5 / 0.8 + 0.5 / 1.6);
  EXPECT_NEAR(std::abs(r.solution.reactions[0].moment.x()), torque, 1e-6 * torque);
  EXPECT_NEAR(std::abs(r.solution.reactions[1].moment.x()), torque, 1e-6 * torque);
  // Straight: the sleeve adds no bending stiffness here and nothing bends the cable.
  EXPECT_LT(r.solution.centerline.points.bottomRows(2).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(SleeveTest, ASleeveWeighsOnlyWhereItIs) {
  // Weight of a clamped-clamped cable: the two clamps carry all of it, cable and sleeve.
  RodSpec spec = Cantilever();
  spec.gravity = Vec3(0, 0, -9.81);
  spec.material.linear_density = 0.1;
  SupportSpec far;
  far.s = 1.0;
  far.position = Vec3(0.95, 0, 0);
  far.tangent = Vec3::UnitX();
  far.normal = Vec3::UnitZ();
  spec.supports.push_back(far);
  spec.sleeves.push_back({0.1, 0.35, 0.0, 0.0, 0.4});
  RodSimulator sim;
  const SimulationResult r = sim.Simulate(spec);
  ASSERT_TRUE(r.converged);
  const double weight = (0.1 * 1.0 + 0.4 * 0.25) * 9.81;
  const double lift = r.solution.reactions[0].force.z() + r.solution.reactions[1].force.z();
  EXPECT_NEAR(lift, weight, 1e-9 * weight);
  // The sleeve hangs on the near clamp: it carries more than the far one.
  EXPECT_GT(r.solution.reactions[0].force.z(), r.solution.reactions[1].force.z() + 0.1);
}

TEST(SleeveTest, ABadSleeveIsRefusedWithItsInterval) {
  for (const SleeveSpec bad : {SleeveSpec{0.5, 0.4, 1, 1, 0}, SleeveSpec{-0.5, 0.4, 1, 1, 0},
                               SleeveSpec{0.1, 1.5, 1, 1, 0}, SleeveSpec{0.1, 0.4, -1, 1, 0},
                               SleeveSpec{0.1, 0.4, 1, NAN, 0}}) {
    RodSpec spec = Cantilever();
    spec.sleeves.push_back(bad);
    try {
      (void)CompileRodModel(spec, {});
      ADD_FAILURE() << "accepted the sleeve [" << bad.s_begin << ", " << bad.s_end << "]";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("sleeve"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace cablefit
