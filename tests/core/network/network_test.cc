// Rod networks: symmetry and balance of a Y junction, a splice that is exactly the rod it
// joins, and clear errors for broken networks.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/solver/statics_solver.h"
#include "cablefit/core/solver/rod_solution.h"
#include "network_test_util.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::Clamp;
using testing::StraightRoute;
using testing::TestMaterial;

// A breakout hanging from three identical branches clamped 120 degrees apart around the z axis
// (a harness drop): each branch is drawn straight from its clamp, pointing down and inwards, to
// the breakout 2 % closer than its length, and the breakout's weight keeps the branches in
// tension, so the equilibrium is unique. Gravity along -z is symmetric under the 120 degree
// rotation about z.
constexpr double kBreakoutMass = 0.02;  // [kg]

NetworkSpec YJunction(double length) {
  NetworkSpec spec;
  spec.name = "Y";
  spec.junctions.push_back({"breakout", 0.0, kBreakoutMass});
  const double radius = 0.6 * length;
  const Vec3 drop(0, 0, -std::sqrt(std::pow(0.98 * length, 2) - radius * radius));
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * M_PI * k / 3;
    const Vec3 far = radius * Vec3(std::cos(a), std::sin(a), 0.0);
    BranchSpec b;
    b.name = "leg" + std::to_string(k);
    b.length = length;
    b.material = TestMaterial();
    b.route = StraightRoute(far, drop);
    b.supports.push_back(Clamp(0.0, far, (drop - far).normalized()));
    b.end_junction = 0;
    spec.branches.push_back(b);
  }
  return spec;
}

Eigen::Matrix3d RotZ(double a) {
  return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix();
}

// The Y junction with each clamp's normal turned by a different angle about its leg: the legs
// twist and the breakout turns.
NetworkSpec TwistedYJunction(double length) {
  NetworkSpec spec = YJunction(length);
  for (int k = 0; k < 3; ++k) {
    SupportSpec& clamp = spec.branches[k].supports[0];
    clamp.normal = Eigen::AngleAxisd(0.4 * (k + 1), clamp.tangent) * clamp.tangent.unitOrthogonal();
  }
  return spec;
}

// A level started from an equilibrium keeps its twist, not only its shape: the Y junction with
// each clamp's normal turned by a different angle about its leg twists the legs and turns the
// breakout. Started from that equilibrium's centrelines and element normals, the same level is
// already at it (frames and all, up to round-off), and the next finer level started from it
// needs fewer iterations than from the drawing and lands on the same equilibrium.
TEST(Network, AWarmStartWithTheElementNormalsKeepsTheEquilibriumTwist) {
  const double length = 0.3;
  const NetworkSpec spec = TwistedYJunction(length);
  NetworkOptions opt;
  opt.element_length = 0.01;
  const NetworkSolution cold = SolveNetwork(spec, opt);
  ASSERT_TRUE(cold.converged()) << cold.summary.BriefReport();
  ASSERT_EQ(cold.element_normals.size(), 3u);
  NetworkOptions warm = opt;
  warm.initial_routes = cold.branches;
  warm.initial_normals = cold.element_normals;
  const NetworkSolution again = SolveNetwork(spec, warm);
  ASSERT_TRUE(again.converged()) << again.summary.BriefReport();
  // One step finds the multipliers (a start carries none), a second confirms.
  EXPECT_LE(again.summary.iterations, 2);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT((again.branches[k].points - cold.branches[k].points).cwiseAbs().maxCoeff(), 1e-9 * length);
    EXPECT_LT((again.element_normals[k] - cold.element_normals[k]).cwiseAbs().maxCoeff(), 1e-7);
  }
  NetworkOptions fine = warm;
  fine.refinement = 1;
  const NetworkSolution from_coarse = SolveNetwork(spec, fine);
  fine.initial_routes.clear();
  fine.initial_normals.clear();
  const NetworkSolution from_drawing = SolveNetwork(spec, fine);
  ASSERT_TRUE(from_coarse.converged() && from_drawing.converged());
  EXPECT_LT(from_coarse.summary.iterations, from_drawing.summary.iterations);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT((from_coarse.branches[k].points - from_drawing.branches[k].points).cwiseAbs().maxCoeff(),
              1e-9 * length);
}

// Options for a level `refinement` times finer than `opt`'s, started from `coarse`'s equilibrium.
NetworkOptions StartedFrom(NetworkOptions opt, const NetworkSolution& coarse, int refinement) {
  opt.refinement = refinement;
  opt.initial_routes = coarse.branches;
  opt.initial_normals = coarse.element_normals;
  opt.start = coarse.start;
  return opt;
}

TEST(Network, AFinerLevelStartsFromTheCoarserEquilibriumItself) {
  const double length = 0.3;
  const NetworkSpec spec = TwistedYJunction(length);
  NetworkOptions opt;
  opt.element_length = 0.01;
  opt.keep_start = true;
  const NetworkSolution coarse = SolveNetwork(spec, opt);
  ASSERT_TRUE(coarse.converged()) << coarse.summary.BriefReport();
  ASSERT_TRUE(coarse.start);
  // The same elements: the start is the equilibrium, frames, supports and multipliers alike.
  NetworkOptions same = opt;
  same.start = coarse.start;
  EXPECT_EQ(SolveNetwork(spec, same).summary.iterations, 0);
  // Finer elements: at most as many Newton steps as from the start drawn through the coarse
  // nodes, and the same equilibrium.
  NetworkOptions fine = StartedFrom(opt, coarse, 1);
  fine.start.reset();
  const NetworkSolution from_routes = SolveNetwork(spec, fine);
  fine.start = coarse.start;
  const NetworkSolution from_state = SolveNetwork(spec, fine);
  ASSERT_TRUE(from_routes.converged() && from_state.converged());
  EXPECT_LE(from_state.summary.iterations, from_routes.summary.iterations);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT((from_state.branches[k].points - from_routes.branches[k].points).cwiseAbs().maxCoeff(),
              1e-9 * length);
  // Without keep_start no model copy travels with a solution.
  fine.keep_start = false;
  EXPECT_FALSE(SolveNetwork(spec, fine).start);
}

// The finer start bends where the coarse equilibrium bends, up to the clamps and the breakout:
// its energy is the finer equilibrium's up to the discretisation's difference. Holding each
// branch's outermost coarse frame out to its ends put the turn of half a coarse element into one
// finer joint.
TEST(Network, AFinerStartBendsUpToTheClampsAndTheBreakout) {
  const NetworkSpec spec = TwistedYJunction(0.3);
  NetworkOptions opt;
  opt.element_length = 0.02;
  opt.keep_start = true;
  const NetworkSolution coarse = SolveNetwork(spec, opt);
  ASSERT_TRUE(coarse.converged()) << coarse.summary.BriefReport();
  const NetworkSolution from_state = SolveNetwork(spec, StartedFrom(opt, coarse, 2));
  ASSERT_TRUE(from_state.converged()) << from_state.summary.BriefReport();
  const StaticsSummary& s = from_state.summary;
  // Measured: 2.5e-5 of the energy above the equilibrium; holding the ends' frames: 2.8e-3.
  EXPECT_GE(s.initial_energy, s.final_energy);
  EXPECT_LT(s.initial_energy - s.final_energy, 3e-4 * std::abs(s.final_energy));
}

TEST(Network, YJunctionIsSymmetricAndItsJunctionBalances) {
  const double length = 0.3;
  NetworkOptions opt;
  opt.element_length = 0.01;
  const NetworkSolution sol = SolveNetwork(YJunction(length), opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_TRUE(sol.summary.stable);
  ASSERT_EQ(sol.junctions.size(), 1u);
  const JunctionLoads& j = sol.junctions[0];
  ASSERT_EQ(j.force.size(), 3u);
  // The junction sinks straight down and the three legs carry the same load, rotated.
  const Vec3 centre = sol.branches[0].points.rightCols<1>();
  EXPECT_NEAR(centre.x(), 0.0, 1e-10 * length);
  EXPECT_NEAR(centre.y(), 0.0, 1e-10 * length);
  const double weight = 3 * length * 0.1 * 9.81 + kBreakoutMass * 9.81;
  double fmax = 0, mmax = 0;
  for (int k = 0; k < 3; ++k) {
    fmax = std::max(fmax, j.force[k].norm());
    mmax = std::max(mmax, j.moment[k].norm());
  }
  for (int k = 1; k < 3; ++k) {
    const Eigen::Matrix3d back = RotZ(-2 * M_PI * k / 3);
    EXPECT_LT((back * j.force[k] - j.force[0]).norm(), 1e-10 * fmax) << k;
    EXPECT_LT((back * j.moment[k] - j.moment[0]).norm(), 1e-10 * std::max(mmax, weight * length)) << k;
    EXPECT_LT((sol.branches[k].points.rightCols<1>() - centre).norm(), 1e-10 * length);
  }
  // The forces on the breakout balance its weight; the moments balance (its frame is in
  // equilibrium), and the branches pull up on it.
  EXPECT_LT(j.force_residual.norm(), 1e-10 * weight);
  EXPECT_LT(j.moment_residual.norm(), 1e-10 * weight * length);
  for (int k = 0; k < 3; ++k) EXPECT_GT(j.force[k].z(), 0.0);
  // All of the weight goes to the three clamps, equally.
  Vec3 sum = Vec3::Zero();
  for (const SupportReaction& r : sol.reactions) sum += r.force;
  EXPECT_NEAR(sum.z(), weight, 1e-10 * weight);
  for (const SupportReaction& r : sol.reactions) EXPECT_NEAR(r.force.z(), weight / 3, 1e-9 * weight);
  // Internal forces: at the clamp the first element holds the clamp node (reaction plus its
  // half element of weight) in balance; at the breakout the last one is what the junction
  // pulls on the leg; the hanging legs are in tension all along.
  ASSERT_EQ(sol.internal_force.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const Eigen::Matrix3Xd& n = sol.internal_force[k];
    ASSERT_EQ(n.cols(), sol.branches[k].size() - 1);
    const double h = length / n.cols();
    const Vec3 first_node_weight(0, 0, -0.5 * h * 0.1 * 9.81);
    EXPECT_LT((n.col(0) + sol.reactions[k].force + first_node_weight).norm(), 1e-10 * weight) << k;
    EXPECT_LT((n.rightCols<1>() + j.force[k]).norm(), 1e-10 * weight) << k;
    const Polyline& p = sol.branches[k];
    for (int e = 0; e < n.cols(); ++e)
      EXPECT_GT(n.col(e).dot(p.points.col(e + 1) - p.points.col(e)), 0.0) << k << " " << e;
  }
}

// A junction joining only two collinear branches (a splice) is the rod it represents: the same
// nodes, the same equilibrium, to solver accuracy.
TEST(Network, TwoBranchSpliceEqualsTheSingleRod) {
  const double length = 1.0, split = 0.4, h = 0.02;
  const Vec3 a(0, 0, 0), b(0.8, 0.1, 0.05);
  const Vec3 tip_load(0.0, 0.02, -0.01);
  RodSpec rod;
  rod.length = length;
  rod.material = TestMaterial();
  rod.supports = {Clamp(0.0, a, Vec3::UnitX()), Clamp(length, b, Vec3::UnitX())};
  rod.point_loads = {{split, tip_load}};  // also puts a node at the splice
  const RodModel model = CompileRodModel(rod, Discretisation{h, {}, 0});
  const Polyline route = StraightRoute(a, Vec3(length, 0, 0));
  RodState st = MakeInitialState(model, route);
  const StaticsSummary single = SolveStatics(model, &st, StaticsOptions{});
  ASSERT_TRUE(single.converged()) << single.BriefReport();
  const Eigen::Matrix3Xd r_single = st.NodePositions(model);

  NetworkSpec net;
  net.junctions.push_back({"splice", 0.0, 0.0});
  BranchSpec first, second;
  first.name = "first";
  first.length = split;
  first.material = rod.material;
  first.route = StraightRoute(a, Vec3(split, 0, 0));
  first.supports = {rod.supports[0]};
  first.end_junction = 0;
  second.name = "second";
  second.length = length - split;
  second.material = rod.material;
  second.route = StraightRoute(Vec3(split, 0, 0), Vec3(length, 0, 0));
  SupportSpec end = rod.supports[1];
  end.s = length - split;
  second.supports = {end};
  second.point_loads = {{0.0, tip_load}};
  second.start_junction = 0;
  net.branches = {first, second};
  NetworkOptions opt;
  opt.element_length = h;
  const NetworkSolution sol = SolveNetwork(net, opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  ASSERT_EQ(sol.branches[0].size() + sol.branches[1].size() - 1, r_single.cols());
  double worst = 0.0;
  for (int k = 0; k < sol.branches[0].size(); ++k)
    worst = std::max(worst, (sol.branches[0].points.col(k) - r_single.col(k)).norm());
  const int offset = sol.branches[0].size() - 1;
  for (int k = 0; k < sol.branches[1].size(); ++k)
    worst = std::max(worst, (sol.branches[1].points.col(k) - r_single.col(offset + k)).norm());
  EXPECT_LT(worst, 1e-8);
  std::printf("splice vs single rod: max node distance %.3g m\n", worst);
  // The same internal forces element by element (the single rod's from its own extraction).
  const Eigen::Matrix3Xd n_single = ExtractSolution(model, st, single).internal_force;
  ASSERT_EQ(sol.internal_force.size(), 2u);
  ASSERT_EQ(sol.internal_force[0].cols() + sol.internal_force[1].cols(), n_single.cols());
  Eigen::Matrix3Xd n_net(3, n_single.cols());
  n_net << sol.internal_force[0], sol.internal_force[1];
  const double scale = n_single.colwise().norm().maxCoeff();
  EXPECT_LT((n_net - n_single).colwise().norm().maxCoeff(), 1e-6 * scale);
}

TEST(Network, InvalidOptionsAreASummaryThatSaysWhy) {
  for (auto broken : {+[](NetworkOptions* o) { o->element_length = 0.0; },
                      +[](NetworkOptions* o) { o->element_length = std::nan(""); },
                      +[](NetworkOptions* o) { o->refinement = -1; },
                      +[](NetworkOptions* o) { o->contact_tolerance = 1.5; },
                      +[](NetworkOptions* o) { o->max_contact_rounds = 0; },
                      +[](NetworkOptions* o) { o->statics.max_iterations = 0; }}) {
    NetworkOptions opt;
    broken(&opt);
    std::string why;
    ASSERT_FALSE(opt.IsValid(&why));
    const NetworkSolution sol = SolveNetwork(YJunction(0.3), opt);
    EXPECT_EQ(sol.summary.termination, TerminationType::kInvalidOptions);
    EXPECT_NE(sol.summary.message.find(why), std::string::npos) << sol.summary.message;
    EXPECT_FALSE(sol.converged());
    EXPECT_TRUE(sol.branches.empty());
  }
  EXPECT_TRUE(NetworkOptions{}.IsValid(nullptr));
}

TEST(Network, BrokenNetworksNameTheBranch) {
  NetworkSpec y = YJunction(0.3);
  NetworkSpec lone = y;
  lone.junctions.push_back({"dangling", 0.0, 0.0});
  lone.branches[2].end_junction = 1;
  EXPECT_THROW_WITH(CompileNetworkModel(lone, 0.01), InvalidInput,
                    "junction 'dangling' joins only branch 'leg2'");
  NetworkSpec apart = y;
  apart.junctions.push_back({"other", 0.0, 0.0});
  BranchSpec extra = apart.branches[0];
  extra.name = "island";
  extra.end_junction = 1;
  BranchSpec extra2 = extra;
  extra2.name = "island2";
  apart.branches.push_back(extra);
  apart.branches.push_back(extra2);
  EXPECT_THROW_WITH(CompileNetworkModel(apart, 0.01), InvalidInput,
                    "branch 'island' is not connected to branch 'leg0'");
  NetworkSpec short_leg = y;
  short_leg.branches[1].length = 0.005;  // leg0 + leg1 = 0.305 m, their clamps are 0.312 m apart
  EXPECT_THROW_WITH(CompileNetworkModel(short_leg, 0.01), InvalidInput, "branch 'leg1'");
  EXPECT_THROW_WITH(CompileNetworkModel(short_leg, 0.01), InvalidInput, "too short");
  NetworkSpec loop = y;
  loop.branches[1].start_junction = 0;
  loop.branches[1].supports.clear();
  EXPECT_THROW_WITH(CompileNetworkModel(loop, 0.01), InvalidInput, "closed loop");
  NetworkSpec nan = y;
  nan.branches[0].material.bending_stiffness = std::nan("");
  EXPECT_THROW_WITH(CompileNetworkModel(nan, 0.01), InvalidInput, "branch 'leg0': bending stiffness");
}

}  // namespace
}  // namespace cablefit
