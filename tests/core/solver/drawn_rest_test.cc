// The drawn-rest homotopy: a drawing taken as its own rest shape is an equilibrium at zero load,
// so a continuation from there to the real rest shape and full gravity starts at a solved point.
// Drawings a straight-rest cable cannot be held in without a long way to its equilibrium (a
// helical spring drawn as a curve, a cable drawn with kinks, a stretch drawn nearly taut) relax.
#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/core/base/helix.h"
#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/rod/internal/rod_energy.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/solver/statics_solver.h"
#include "network_test_util.h"

namespace cablefit {
namespace {

using testing::Clamp;
using testing::TestMaterial;

Vec3 EndTangent(const Polyline& c, bool at_end) {
  const int n = c.size();
  return at_end ? Vec3((c.points.col(n - 1) - c.points.col(n - 2)).normalized())
                : Vec3((c.points.col(1) - c.points.col(0)).normalized());
}

// One branch drawn along `route`, clamped at both ends where and as the drawing has them.
NetworkSpec ClampedDrawing(const Polyline& route, const MaterialSpec& material) {
  BranchSpec b;
  b.name = "drawn";
  b.length = route.s[route.size() - 1];
  b.material = material;
  b.route = route;
  const Vec3 t0 = EndTangent(route, false), t1 = EndTangent(route, true);
  const Vec3 n0 = t0.cross(Vec3::UnitZ()).norm() > 0.1 ? Vec3::UnitZ() : Vec3::UnitX();
  const Vec3 n1 = t1.cross(Vec3::UnitZ()).norm() > 0.1 ? Vec3::UnitZ() : Vec3::UnitX();
  b.supports = {Clamp(0.0, route.points.col(0), t0, n0),
                Clamp(b.length, route.points.col(route.size() - 1), t1, n1)};
  NetworkSpec spec;
  spec.name = "drawn";
  spec.branches = {b};
  return spec;
}

// Every clamp holds its drawn position in the solution.
void ExpectEndsHeld(const NetworkSpec& spec, const NetworkSolution& sol) {
  ASSERT_EQ(sol.branches.size(), 1u);
  const Polyline& c = sol.branches[0];
  const Polyline& r = spec.branches[0].route;
  EXPECT_LT((c.points.col(0) - r.points.col(0)).norm(), 1e-6);
  EXPECT_LT((c.points.col(c.size() - 1) - r.points.col(r.size() - 1)).norm(), 1e-6);
}

TEST(DrawnRest, TheDrawingIsAnEquilibriumOfItsOwnRestShapeAtZeroLoad) {
  RodSpec spec;
  spec.name = "spring";
  const Polyline helix = SampleHelix(0.02, 0.015, 3);
  spec.length = helix.s[helix.size() - 1];
  spec.material = TestMaterial();
  spec.supports = {Clamp(0.0, helix.points.col(0), EndTangent(helix, false)),
                   Clamp(spec.length, helix.points.col(helix.size() - 1), EndTangent(helix, true))};
  const RodModel model = CompileRodModel(spec);
  RodState st = MakeInitialState(model, helix);
  st.drawn_curvature = internal::DrawnCurvature(model, st);
  st.drawn_factor = 1.0;
  st.natural_factor = 0.0;
  st.load_factor = 0.0;
  const StaticsSummary at_rest = SolveStaticsDirect(model, &st, StaticsOptions{});
  EXPECT_TRUE(at_rest.converged()) << at_rest.BriefReport();
  EXPECT_EQ(at_rest.iterations, 0) << at_rest.BriefReport();
  EXPECT_NEAR(at_rest.final_energy, 0.0, 1e-12);
  // The same state with the real (straight) rest shape is far from equilibrium.
  st.drawn_factor = 0.0;
  st.natural_factor = 1.0;
  StaticsOptions one;
  one.max_iterations = 1;
  EXPECT_FALSE(SolveStaticsDirect(model, &st, one).converged());
}

TEST(DrawnRest, AHelicalSpringDrawnAsACurveRelaxesBetweenItsClamps) {
  for (const double turns : {2.0, 5.0}) {
    const NetworkSpec spec = ClampedDrawing(SampleHelix(0.02, 0.012, turns), TestMaterial(0.02, 0.05, 0.004));
    NetworkOptions opt;
    opt.element_length = 0.01;
    const NetworkSolution sol = SolveNetwork(spec, opt);
    ASSERT_TRUE(sol.converged()) << turns << " turns: " << sol.summary.BriefReport();
    EXPECT_TRUE(sol.summary.stable) << sol.summary.BriefReport();
    ExpectEndsHeld(spec, sol);
    // The straight-rest cable does not stay coiled: its bending energy is that of the real
    // rest shape, well below the drawn coil's (curvature 1/r all along).
    const double coil_energy = 0.5 * 0.02 * spec.branches[0].length / (0.02 * 0.02);
    EXPECT_LT(sol.summary.final_energy, 0.5 * coil_energy) << sol.summary.BriefReport();
  }
}

TEST(DrawnRest, ACableDrawnWithRightAngleKinksRelaxes) {
  // A zig-zag of 90-degree corners in a vertical plane: its drawn curvature is concentrated in
  // single elements, the hardest start for a straight-rest cable held in it.
  Polyline z;
  const std::vector<Vec3> corners = {Vec3(0, 0, 0), Vec3(0.15, 0, 0), Vec3(0.15, 0, -0.15),
                                     Vec3(0.3, 0, -0.15), Vec3(0.3, 0, 0), Vec3(0.45, 0, 0)};
  z.points.resize(3, static_cast<int>(corners.size()));
  for (size_t k = 0; k < corners.size(); ++k) z.points.col(static_cast<int>(k)) = corners[k];
  z.ParameteriseByChords();
  const NetworkSpec spec = ClampedDrawing(z, TestMaterial());
  NetworkOptions opt;
  opt.element_length = 0.01;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_TRUE(sol.summary.stable) << sol.summary.BriefReport();
  ExpectEndsHeld(spec, sol);
}

TEST(DrawnRest, AStretchDrawnNearlyTautHangs) {
  // A shallow wave across 0.6 m with 0.2 % slack: no room to sag much, and any start other than
  // the right one pulls the stretch straight.
  Polyline w;
  const int n = 121;
  w.points.resize(3, n);
  const double amp = 0.6 * std::sqrt(0.002 * 4) / (2 * M_PI);  // slack ~ (pi a k)^2 / 4 ... small
  for (int k = 0; k < n; ++k) {
    const double x = 0.6 * k / (n - 1);
    w.points.col(k) = Vec3(x, 0, amp * std::sin(2 * M_PI * x / 0.6));
  }
  w.ParameteriseByChords();
  const double slack = w.s[n - 1] / 0.6 - 1;
  ASSERT_GT(slack, 0.0005);
  ASSERT_LT(slack, 0.005);
  const NetworkSpec spec = ClampedDrawing(w, TestMaterial(0.01, 0.1, 0.006));
  NetworkOptions opt;
  opt.element_length = 0.01;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  ExpectEndsHeld(spec, sol);
  EXPECT_LT(sol.branches[0].points.row(2).minCoeff(), -1e-3);  // it hangs under gravity
}


TEST(DrawnRest, ALongSpringPastTheFoldsOfItsPathRelaxes) {
  // 30 turns (3.8 m of cable) between clamps 0.6 m apart: the homotopy from the drawn rest shape
  // folds back at t ~ 0.3 where the coil collapses into loops; no smaller continuation step
  // passes that, and before pseudo-transient continuation took over there it ended with
  // "continuation stalled" and "could not relax the initial shape: iteration limit".
  const NetworkSpec spec =
      ClampedDrawing(SampleHelix(0.02, 0.02, 30), TestMaterial(0.02, 0.05, 0.004));
  NetworkOptions opt;
  opt.element_length = 0.02;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_TRUE(sol.summary.stable) << sol.summary.BriefReport();
  EXPECT_GT(sol.summary.folds_passed, 0) << sol.summary.BriefReport();
  ExpectEndsHeld(spec, sol);
  const double coil_energy = 0.5 * 0.02 * spec.branches[0].length / (0.02 * 0.02);
  EXPECT_LT(sol.summary.final_energy, 0.5 * coil_energy) << sol.summary.BriefReport();
}

}  // namespace
}  // namespace cablefit
