// Every analytic gradient and Hessian of the rod energy against central finite differences.
#include <gtest/gtest.h>

#include <random>

#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/rod/internal/rod_energy.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/solver/internal/kkt_evaluation.h"
#include "cablefit/core/solver/statics_solver.h"
#include "test_support.h"

namespace cablefit {
namespace {

using internal::DrawnCurvature;
using internal::EvaluateKkt;
using internal::KktEvaluation;
using internal::RotateFrames;

RodSpec RichSpec() {
  RodSpec spec;
  spec.length = 0.5;
  spec.material.bending_stiffness = 0.01;
  spec.material.bending_ratio = 2.0;
  spec.material.principal_angle = 0.4;
  spec.material.torsional_stiffness = 0.007;
  spec.material.linear_density = 0.08;
  spec.gravity = Vec3(0.3, -0.2, -9.81);
  SupportSpec a;
  a.position = Vec3(0, 0, 0);
  a.tangent = Vec3(1, 0, 0.2);
  a.normal = Vec3(0, 0, 1);
  a.compliance = Mat3(Vec3(0.5, 0.3, 0.8).asDiagonal());
  SupportSpec clip;
  clip.kind = SupportKind::kClip;
  clip.s = 0.2;
  clip.position = Vec3(0.15, 0.05, -0.05);
  clip.tangent = Vec3(1, 0.3, 0);
  SupportSpec pin;
  pin.kind = SupportKind::kPin;
  pin.s = 0.33;
  pin.position = Vec3(0.25, 0.1, -0.04);
  SupportSpec b;
  b.s = 0.5;
  b.position = Vec3(0.35, 0.12, 0.02);
  b.tangent = Vec3(0.2, 1, 0);
  b.normal = Vec3(0, 0, 1);
  b.sliding = true;
  spec.supports = {a, clip, pin, b};
  spec.natural_curvature.push_back({0.05, 0.3, 0.02, Vec3(3.0, -1.0, 0.5)});
  spec.point_loads.push_back({0.42, Vec3(0.1, 0.2, -0.3)});
  return spec;
}

// The energy's gradient, Hessian and constraint Jacobian at `state` against central differences.
void ExpectDerivativesMatchFiniteDifferences(const RodModel& model, const RodState& state,
                                             const Eigen::VectorXd& lambda) {
  const int n3 = 3 * static_cast<int>(model.items.size());
  const KktEvaluation at = EvaluateKkt(model, state, lambda, true);
  const double h = 1e-6;
  Eigen::VectorXd fd_grad(n3);
  Eigen::MatrixXd fd_hess(n3, n3), fd_jac(model.num_constraints, n3);
  for (int k = 0; k < n3; ++k) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(n3);
    e[k] = h;
    RodState plus = state, minus = state;
    RotateFrames(model, e, &plus);
    RotateFrames(model, -e, &minus);
    const KktEvaluation ep = EvaluateKkt(model, plus, lambda, false);
    const KktEvaluation em = EvaluateKkt(model, minus, lambda, false);
    fd_grad[k] = (ep.energy - em.energy) / (2 * h);
    const Eigen::VectorXd gp = ep.gradient + ep.jacobian.transpose() * lambda;
    const Eigen::VectorXd gm = em.gradient + em.jacobian.transpose() * lambda;
    fd_hess.col(k) = (gp - gm) / (2 * h);
    fd_jac.col(k) = (ep.constraints - em.constraints) / (2 * h);
  }
  const double gscale = at.gradient.cwiseAbs().maxCoeff();
  EXPECT_TRUE(testing::MatricesNear(at.gradient, fd_grad, 1e-6 * gscale));
  EXPECT_TRUE(testing::MatricesNear(at.jacobian, fd_jac, 1e-8));
  // The exp chart is not symmetric at second order for non-commuting rotations, so compare the
  // symmetric part (what Newton uses) of the finite-difference Hessian.
  const Eigen::MatrixXd fd_sym = 0.5 * (fd_hess + fd_hess.transpose());
  const double hscale = at.hessian.cwiseAbs().maxCoeff();
  EXPECT_TRUE(testing::MatricesNear(at.hessian, fd_sym, 1e-5 * hscale));
}

TEST(RodEnergyTest, GradientAndHessianMatchFiniteDifferences) {
  const RodSpec spec = RichSpec();
  Discretisation disc;
  disc.element_length = 0.05;
  const RodModel model = CompileRodModel(spec, disc);
  RodState state = MakeInitialState(model, DefaultInitialCurve(spec));
  std::mt19937 rng(7);
  std::normal_distribution<double> nd(0.0, 0.2);
  const int n3 = 3 * static_cast<int>(model.items.size());
  Eigen::VectorXd jitter(n3);
  for (int i = 0; i < n3; ++i) jitter[i] = nd(rng);
  RotateFrames(model, jitter, &state);
  Eigen::VectorXd lambda(model.num_constraints);
  for (int i = 0; i < lambda.size(); ++i) lambda[i] = nd(rng);
  ExpectDerivativesMatchFiniteDifferences(model, state, lambda);
  // Half-way along the drawn-rest homotopy: rest curvature partly from another (drawn) shape.
  RodState drawn = state;
  for (int i = 0; i < n3; ++i) jitter[i] = nd(rng);
  RotateFrames(model, jitter, &drawn);
  state.drawn_curvature = DrawnCurvature(model, drawn);
  state.drawn_factor = 0.6;
  state.natural_factor = 0.4;
  ExpectDerivativesMatchFiniteDifferences(model, state, lambda);
  // A junction's rest rotation on some edges (what a network's branch points carry).
  RodModel turned = model;
  for (size_t k = 1; k < turned.edges.size(); k += 3) {
    turned.edges[k].has_rest = true;
    turned.edges[k].rest = Eigen::Vector4d(1.0, nd(rng), nd(rng), nd(rng)).normalized();
  }
  ExpectDerivativesMatchFiniteDifferences(turned, state, lambda);
}

}  // namespace
}  // namespace cablefit
