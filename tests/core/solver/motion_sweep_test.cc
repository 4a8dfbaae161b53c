// Motion sweeps: a hinge that swings out and back returns the cable to its start shape; every
// pose equals a cold solve of the same pose; a clamped-clamped rod whose clamp is pushed in
// loses the straight branch at the first pose past the Euler load 4 pi^2 EI / L^2 (Timoshenko &
// Gere, "Theory of Elastic Stability" (1961), sec. 2.3), its end force following EA delta / L
// until then.
#include "cablefit/core/solver/motion_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace cablefit {
namespace {

SupportSpec Clamp(double s, const Vec3& position, const Vec3& tangent) {
  SupportSpec sp;
  sp.kind = SupportKind::kClamp;
  sp.s = s;
  sp.position = position;
  sp.tangent = tangent;
  sp.normal = Vec3::UnitZ();
  return sp;
}

// A 0.6 m cable from a fixed clamp to a clamp on a door that swings about the vertical axis
// through (0.5, 0.1, 0), sagging under gravity (slack: the clamps are 0.45 m apart).
RodSpec DoorCable() {
  RodSpec spec;
  spec.name = "door";
  spec.length = 0.6;
  spec.material.bending_stiffness = 0.02;
  spec.material.torsional_stiffness = 0.015;
  spec.material.linear_density = 0.1;
  spec.material.diameter = 0.008;
  spec.gravity = Vec3(0, 0, -9.81);
  spec.supports = {Clamp(0.0, Vec3(0, 0, 0), Vec3::UnitX()),
                   Clamp(0.6, Vec3(0.45, 0, 0), Vec3::UnitX())};
  return spec;
}

Polyline Straight(const Vec3& a, const Vec3& b) {
  Polyline p;
  p.points.resize(3, 2);
  p.points << a, b;
  p.ParameteriseByChords();
  return p;
}

Eigen::Isometry3d Hinge(double angle) {
  const Vec3 point(0.5, 0.1, 0);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix();
  t.translation() = point - t.linear() * point;
  return t;
}

std::vector<double> ThereAndBack(double to, int steps) {
  std::vector<double> q;
  for (int i = 0; i <= steps; ++i) q.push_back(to * i / steps);
  for (int i = steps - 1; i >= 0; --i) q.push_back(to * i / steps);
  return q;
}

double LargestDistance(const Polyline& a, const Polyline& b, double length) {
  const Eigen::VectorXd s = UniformArcLengths(length, 301);
  return (SampleCenterline(a, s).points - SampleCenterline(b, s).points)
      .colwise()
      .norm()
      .maxCoeff();
}

TEST(MotionSweep, AHingeSwungOutAndBackReturnsTheCableToItsStartShape) {
  const RodSpec spec = DoorCable();
  const std::vector<double> q = ThereAndBack(60 * M_PI / 180, 12);
  const SweepSummary sweep = SweepRod(spec, nullptr, {1}, Hinge, q);
  ASSERT_TRUE(sweep.completed) << sweep.message;
  ASSERT_EQ(sweep.poses.size(), q.size());
  EXPECT_EQ(sweep.branch_lost_pose, -1);
  const Polyline& first = sweep.poses.front().result.solution.centerline;
  const Polyline& last = sweep.poses.back().result.solution.centerline;
  const double back = LargestDistance(first, last, spec.length);
  std::printf("hinge 0 -> 60 deg -> 0 in 25 poses: back to the start shape within %.3g m\n", back);
  EXPECT_LT(back, 1e-9);
  // The way out moved it: the comparison is not trivially zero.
  EXPECT_GT(LargestDistance(first, sweep.poses[12].result.solution.centerline, spec.length), 0.05);
  for (const SweepPose& p : sweep.poses) EXPECT_TRUE(p.stable);
}

TEST(MotionSweep, EveryPoseEqualsAColdSolveOfThatPose) {
  const RodSpec spec = DoorCable();
  const std::vector<double> q = {0.0, 0.3, 0.6, 0.9};
  SweepOptions options;
  const SweepSummary sweep = SweepRod(spec, nullptr, {1}, Hinge, q, options);
  ASSERT_TRUE(sweep.completed) << sweep.message;
  for (size_t i = 0; i < q.size(); ++i) {
    RodSimulator cold(options.simulation);
    const RodSpec at = MovedSpec(spec, {1}, Hinge(q[i]));
    const SimulationResult r =
        cold.Simulate(at, nullptr);  // from a smooth curve through the moved supports
    ASSERT_TRUE(r.converged);
    const double tol = 10 * options.simulation.accuracy;
    EXPECT_LT(LargestDistance(r.solution.centerline, sweep.poses[i].result.solution.centerline,
                              spec.length),
              tol)
        << "pose " << i;
    for (size_t k = 0; k < r.solution.reactions.size(); ++k)
      EXPECT_LT((r.solution.reactions[k].force - sweep.poses[i].result.solution.reactions[k].force)
                    .norm(),
                1e-4)
          << "pose " << i;
  }
}

TEST(MotionSweep, PushingAClampedClampedRodLosesTheStraightBranchPastTheEulerLoad) {
  // Weightless, extensible rod 1 m long, clamped straight at both ends; the end clamp is moved
  // towards the start. Straight while the compression EA delta / L is below 4 pi^2 EI / L^2.
  RodSpec spec;
  spec.length = 1.0;
  spec.material.bending_stiffness = 0.01;
  spec.material.torsional_stiffness = 0.008;
  spec.material.linear_density = 0.0;
  spec.material.diameter = 0.005;
  spec.material.axial_stiffness = 1e3;
  spec.gravity = Vec3::Zero();
  spec.supports = {Clamp(0.0, Vec3::Zero(), Vec3::UnitX()),
                   Clamp(1.0, Vec3::UnitX(), Vec3::UnitX())};
  const double euler =
      4 * M_PI * M_PI * spec.material.bending_stiffness / (spec.length * spec.length);
  const double delta_cr = euler * spec.length / spec.material.axial_stiffness;
  std::vector<double> q;  // 0.1, 0.3, ..., 1.9 times delta_cr: the 6th pose (1.1) is the first past
  for (int i = 0; i < 10; ++i) q.push_back((0.1 + 0.2 * i) * delta_cr);
  const auto push = [](double d) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Vec3(-d, 0, 0);
    return t;
  };
  const Polyline straight = Straight(Vec3::Zero(), Vec3::UnitX());
  const SweepSummary sweep = SweepRod(spec, &straight, {1}, push, q);
  ASSERT_TRUE(sweep.completed) << sweep.message;
  EXPECT_EQ(sweep.branch_lost_pose, 5);
  for (int i = 0; i < 5; ++i) {
    const SweepPose& p = sweep.poses[static_cast<size_t>(i)];
    EXPECT_TRUE(p.stable) << i;
    // The end clamp pushes with EA delta / L (compression) while straight.
    EXPECT_NEAR(p.result.solution.reactions[1].force.x(),
                -spec.material.axial_stiffness * q[static_cast<size_t>(i)] / spec.length,
                1e-6 * euler)
        << i;
  }
  EXPECT_TRUE(sweep.poses[5].escaped_unstable);
  // Past it the rod is bent (off the axis) and stable, its end force near the Euler load.
  for (size_t i = 5; i < q.size(); ++i) {
    EXPECT_TRUE(sweep.poses[i].stable) << i;
    const Polyline& c = sweep.poses[i].result.solution.centerline;
    EXPECT_GT(c.points.bottomRows(2).colwise().norm().maxCoeff(), 1e-3) << i;
  }
  EXPECT_NEAR(-sweep.poses.back().result.solution.reactions[1].force.x(), euler, 0.05 * euler);
}

}  // namespace
}  // namespace cablefit
