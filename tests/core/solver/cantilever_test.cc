// Planar cantilever with a dead tip load (elastica): tip deflection against an independent
// high-accuracy shooting solution of EI phi'' = -P cos(phi), phi(0) = 0, phi'(L) = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/core/solver/rod_solution.h"
#include "cablefit/core/solver/statics_solver.h"
#include "test_support.h"

namespace cablefit {
namespace {

// Returns tip (x, z) of the elastica for alpha = P L^2 / EI, L = 1, by RK4 shooting.
Eigen::Vector2d ShootCantilever(double alpha) {
  auto integrate = [alpha](double k0, double* kL) {
    const int n = 20000;
    const double h = 1.0 / n;
    Eigen::Vector4d y(0, k0, 0, 0);  // phi, kappa, x, z
    auto f = [alpha](const Eigen::Vector4d& v) {
      return Eigen::Vector4d(v[1], -alpha * std::cos(v[0]), std::cos(v[0]), -std::sin(v[0]));
    };
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector4d a = f(y), b = f(y + 0.5 * h * a), c = f(y + 0.5 * h * b),
                            d = f(y + h * c);
      y += h / 6 * (a + 2 * b + 2 * c + d);
    }
    *kL = y[1];
    return Eigen::Vector2d(y[2], y[3]);
  };
  double k = alpha * 0.5;
  for (int it = 0; it < 50; ++it) {
    double f0, f1;
    integrate(k, &f0);
    integrate(k + 1e-7, &f1);
    const double dk = -f0 / ((f1 - f0) / 1e-7);
    k += dk;
    if (std::abs(dk) < 1e-14) break;
  }
  double kl;
  return integrate(k, &kl);
}

RodSpec Cantilever(double alpha) {
  RodSpec spec;
  spec.length = 1.0;
  spec.material.bending_stiffness = 1.0;
  spec.material.torsional_stiffness = 0.8;
  spec.material.linear_density = 0.0;
  spec.gravity = Vec3::Zero();
  SupportSpec clamp;
  clamp.tangent = Vec3::UnitX();
  clamp.normal = Vec3::UnitZ();
  spec.supports = {clamp};
  spec.point_loads.push_back({1.0, Vec3(0, 0, -alpha)});
  return spec;
}

TEST(CantileverTest, DefaultAccuracyMeetsOneInHundredThousand) {
  for (double alpha : {0.5, 1.0, 2.0, 5.0, 10.0}) {
    const Eigen::Vector2d ref = ShootCantilever(alpha);
    RodSimulator sim;
    const SimulationResult r = sim.Simulate(Cantilever(alpha));
    ASSERT_TRUE(r.converged);
    const Polyline& c = r.solution.centerline;
    const double tip = c.points(2, c.size() - 1);
    const double rel = std::abs(tip - ref[1]) / std::abs(ref[1]);
    std::printf("alpha %4.1f: tip deflection %.10f (reference %.10f) rel. error %.2e, estimated "
                "%.1e m, elements %d, %d Newton iterations, %.2f ms\n",
                alpha, -tip, -ref[1], rel, r.estimated_error, r.level_elements.back(),
                r.newton_iterations, r.seconds * 1e3);
    EXPECT_LE(rel, 1e-5);
    EXPECT_TRUE(r.accuracy_met);
  }
}

TEST(CantileverTest, ConvergesSecondOrder) {
  for (double alpha : {0.5, 2.0, 10.0}) {
    const Eigen::Vector2d ref = ShootCantilever(alpha);
    double prev = 0;
    for (int n : {8, 16, 32, 64, 128}) {
      Discretisation d;
      d.elements_per_span = {n};
      const RodSpec spec = Cantilever(alpha);
      const RodModel model = CompileRodModel(spec, d);
      RodState st = MakeInitialState(model, DefaultInitialCurve(spec));
      StaticsOptions opt;
      opt.ramp_loads = true;
      const StaticsSummary sum = SolveStatics(model, &st, opt);
      const RodSolution sol = ExtractSolution(model, st, sum);
      const double tip = sol.centerline.points(2, n);
      const double err = std::abs(tip - ref[1]);
      if (prev > 0) {
        std::printf("alpha %g: n %d, error %.3e, observed order %.2f\n", alpha, n, err,
                    std::log2(prev / err));
        EXPECT_NEAR(std::log2(prev / err), 2.0, 0.25);
      }
      prev = err;
      EXPECT_TRUE(sum.converged());
    }
  }
}

}  // namespace
}  // namespace cablefit
