#include "levenberg_marquardt.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cablefit {
namespace {

// A small nonlinear least-squares problem with its minimum at (1, 2, -0.5): exponential decays
// sampled at a few times.
struct Decay {
  Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(12, 0.0, 3.0);
  Eigen::VectorXd y;
  int calls = 0;
  Decay() : y(t.size()) {
    for (int i = 0; i < t.size(); ++i) y[i] = Model(Eigen::Vector3d(1.0, 2.0, -0.5), t[i]);
  }
  static double Model(const Eigen::VectorXd& x, double t) { return x[0] * std::exp(-x[1] * t) + x[2]; }
  bool operator()(const Eigen::VectorXd& x, Eigen::VectorXd* r) {
    ++calls;
    r->resize(t.size());
    for (int i = 0; i < t.size(); ++i) (*r)[i] = Model(x, t[i]) - y[i];
    return true;
  }
};

TEST(LevenbergMarquardtTest, DifferenceJacobianLeavesSkippedColumnsAndCountsTheOthers) {
  Decay d;
  const Eigen::Vector3d x(0.5, 1.0, 0.0), scale(1.0, 1.0, 1.0);
  Eigen::VectorXd r;
  d(x, &r);
  Eigen::MatrixXd jac = Eigen::MatrixXd::Constant(r.size(), 3, 7.0);
  int evaluations = 0;
  ASSERT_TRUE(DifferenceJacobian(std::ref(d), x, r, scale, 1e-6, {true, false, true}, &evaluations,
                                 &jac));
  EXPECT_EQ(evaluations, 1);
  EXPECT_EQ(jac.col(0), Eigen::VectorXd::Constant(r.size(), 7.0));
  EXPECT_EQ(jac.col(2), Eigen::VectorXd::Constant(r.size(), 7.0));
  for (int i = 0; i < r.size(); ++i)  // d r / d x1 = -t x0 exp(-x1 t)
    EXPECT_NEAR(jac(i, 1), -d.t[i] * x[0] * std::exp(-x[1] * d.t[i]), 1e-5);
}

TEST(LevenbergMarquardtTest, AKnownStartReachesTheSameMinimumWithFewerEvaluations) {
  const Eigen::Vector3d x0(0.5, 1.0, 0.0), scale(1.0, 1.0, 1.0);
  LmOptions opt;
  opt.max_iterations = 50;
  Decay cold;
  const LmResult a = MinimiseLeastSquares(std::ref(cold), x0, scale, opt);
  ASSERT_TRUE(a.ok && a.converged);
  EXPECT_NEAR(a.x[1], 2.0, 1e-6);

  // The start's residual and two of its Jacobian columns are given: the third one is the only
  // difference the first iteration takes, and the start is not evaluated.
  Decay warm;
  LmStart start;
  warm(x0, &start.residual);
  int evaluations = 0;
  start.jacobian.resize(start.residual.size(), 3);
  ASSERT_TRUE(DifferenceJacobian(std::ref(warm), x0, start.residual, scale, opt.relative_step, {},
                                 &evaluations, &start.jacobian));
  start.known_columns = {true, true, false};
  start.jacobian.col(2).setConstant(1e9);  // not read: it is differenced
  warm.calls = 0;
  const LmResult b = MinimiseLeastSquares(std::ref(warm), x0, scale, opt, &start);
  ASSERT_TRUE(b.ok && b.converged);
  EXPECT_NEAR((b.x - a.x).norm(), 0.0, 1e-6);
  EXPECT_EQ(b.evaluations, warm.calls);
  EXPECT_EQ(b.evaluations, a.evaluations - 3);  // the start and two columns
}

}  // namespace
}  // namespace cablefit
