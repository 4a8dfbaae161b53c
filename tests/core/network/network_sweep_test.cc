// Network motion sweeps, checked as the single-rod sweep is (tests/core/solver/motion_sweep_test):
// a Y harness whose branch clamp swings out on a hinge and back returns to its start shape;
// every pose equals a cold solve of that pose; a clamped-clamped branch pushed in loses the
// straight branch at the first pose past the Euler load 4 pi^2 EI / L^2 (Timoshenko & Gere,
// "Theory of Elastic Stability" (1961), sec. 2.3), its end force EA delta / L until then.
#include "cablefit/core/network/network_sweep.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/core/base/errors.h"
#include "network_test_util.h"

namespace cablefit {
namespace {

using testing::Clamp;
using testing::StraightRoute;
using testing::TestMaterial;

// Three 0.3 m branches from a breakout at (0.25, 0, 0.05) to clamps; the clamp of branch 2
// sits on a door that swings about the vertical axis through (0.6, 0.1, 0).
NetworkSpec YHarness() {
  NetworkSpec spec;
  spec.gravity = Vec3(0, 0, -9.81);
  const Vec3 hub(0.25, 0.0, 0.05);
  const Vec3 ends[3] = {Vec3(0.0, 0.0, 0.0), Vec3(0.25, 0.25, 0.0), Vec3(0.5, 0.0, 0.0)};
  spec.junctions.push_back({"Y", 0.0, 0.0});
  for (int b = 0; b < 3; ++b) {
    BranchSpec br;
    br.name = "branch" + std::to_string(b);
    br.length = 0.3;
    br.material = TestMaterial(0.02, 0.1, 0.008);
    // Branch b runs from its clamp (s = 0) to the hub (s = length).
    br.route = StraightRoute(ends[b], hub);
    br.supports = {Clamp(0.0, ends[b], (hub - ends[b]).normalized())};
    br.end_junction = 0;
    spec.branches.push_back(br);
  }
  return spec;
}

Eigen::Isometry3d Hinge(double angle) {
  const Vec3 point(0.6, 0.1, 0);
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

double LargestDistance(const NetworkSolution& a, const NetworkSolution& b) {
  double d = 0.0;
  for (size_t k = 0; k < a.branches.size(); ++k) {
    EXPECT_EQ(a.branches[k].size(), b.branches[k].size());
    if (a.branches[k].size() != b.branches[k].size()) return INFINITY;
    d = std::max(d, (a.branches[k].points - b.branches[k].points).colwise().norm().maxCoeff());
  }
  return d;
}

NetworkSweepOptions Options() {
  NetworkSweepOptions o;
  o.network.element_length = 0.01;
  return o;
}

TEST(NetworkSweep, AHingeSwungOutAndBackReturnsTheHarnessToItsStartShape) {
  const std::vector<double> q = ThereAndBack(0.6, 6);
  const NetworkSweepSummary sweep = SweepNetwork(YHarness(), {{{2, 0}}, {}}, Hinge, q, Options());
  ASSERT_TRUE(sweep.completed) << sweep.message;
  ASSERT_EQ(sweep.poses.size(), q.size());
  EXPECT_EQ(sweep.branch_lost_pose, -1);
  for (const NetworkSweepPose& p : sweep.poses) EXPECT_TRUE(p.stable) << p.q;
  EXPECT_LT(LargestDistance(sweep.poses.front().solution, sweep.poses.back().solution), 1e-9);
  // The door moved the harness: the middle pose is far from the first.
  EXPECT_GT(LargestDistance(sweep.poses.front().solution, sweep.poses[6].solution), 0.05);
  // The swinging clamp is where the hinge puts it.
  const Vec3 moved = Hinge(0.6) * Vec3(0.5, 0.0, 0.0);
  EXPECT_LT((sweep.poses[6].solution.branches[2].points.col(0) - moved).norm(), 1e-9);
}

TEST(NetworkSweep, EveryPoseEqualsAColdSolveOfThatPose) {
  const NetworkSpec base = YHarness();
  const std::vector<double> q = {0.0, 0.2, 0.4, 0.6};
  const NetworkSweepSummary sweep = SweepNetwork(base, {{{2, 0}}, {}}, Hinge, q, Options());
  ASSERT_TRUE(sweep.completed) << sweep.message;
  for (size_t i = 0; i < q.size(); ++i) {
    const NetworkSolution cold =
        SolveNetwork(MovedNetworkSpec(base, {{{2, 0}}, {}}, Hinge(q[i])), Options().network);
    ASSERT_TRUE(cold.converged()) << q[i];
    EXPECT_LT(LargestDistance(cold, sweep.poses[i].solution), 1e-8) << q[i];
  }
}

TEST(NetworkSweep, PushingAClampedClampedBranchLosesTheStraightBranchPastTheEulerLoad) {
  NetworkSpec spec;
  spec.gravity = Vec3::Zero();
  BranchSpec br;
  br.name = "rod";
  br.length = 1.0;
  br.material = TestMaterial(0.01, 0.0, 0.005);
  br.material.torsional_stiffness = 0.008;
  br.material.axial_stiffness = 1e3;
  br.route = StraightRoute(Vec3::Zero(), Vec3::UnitX());
  br.supports = {Clamp(0.0, Vec3::Zero(), Vec3::UnitX()), Clamp(1.0, Vec3::UnitX(), Vec3::UnitX())};
  spec.branches.push_back(br);
  const double ei = br.material.bending_stiffness, ea = br.material.axial_stiffness;
  const double euler = 4 * M_PI * M_PI * ei;
  const double delta_cr = euler / ea;
  std::vector<double> q;  // 0.1, 0.3, ..., 1.9 times delta_cr: the 6th pose (1.1) is the first past
  for (int i = 0; i < 10; ++i) q.push_back((0.1 + 0.2 * i) * delta_cr);
  const auto push = [](double d) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Vec3(-d, 0, 0);
    return t;
  };
  const NetworkSweepSummary sweep = SweepNetwork(spec, {{{0, 1}}, {}}, push, q, Options());
  ASSERT_TRUE(sweep.completed) << sweep.message;
  EXPECT_EQ(sweep.branch_lost_pose, 5);
  for (int i = 0; i < 5; ++i) {
    const NetworkSweepPose& p = sweep.poses[static_cast<size_t>(i)];
    EXPECT_TRUE(p.stable) << i;
    EXPECT_NEAR(p.solution.reactions[1].force.x(), -ea * q[static_cast<size_t>(i)], 1e-6 * euler)
        << i;
  }
  EXPECT_TRUE(sweep.poses[5].escaped_unstable);
  for (size_t i = 5; i < q.size(); ++i) {
    EXPECT_TRUE(sweep.poses[i].stable) << i;
    EXPECT_GT(sweep.poses[i].solution.branches[0].points.bottomRows(2).colwise().norm().maxCoeff(),
              1e-3)
        << i;
  }
  EXPECT_NEAR(-sweep.poses.back().solution.reactions[1].force.x(), euler, 0.05 * euler);
}

TEST(NetworkSweep, AMovingSupportThatDoesNotExistIsRefused) {
  EXPECT_THROW(SweepNetwork(YHarness(), {{{3, 0}}, {}}, Hinge, {0.0, 0.1}, Options()), InvalidInput);
  EXPECT_THROW(SweepNetwork(YHarness(), {{{0, 1}}, {}}, Hinge, {0.0, 0.1}, Options()), InvalidInput);
}

}  // namespace
}  // namespace cablefit
