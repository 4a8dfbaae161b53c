// The O(n) block elimination of the Newton system (core/solver/src/kkt_ldlt.h) against
// a dense solve of the same KKT matrix: step, multipliers and inertia, for a
// single rod held by every kind of support, for a rod network with a breakout,
// off equilibrium (indefinite Hessian) and with a shift; for a harness of
// extensible branches whose rows are eliminated in another basis than the
// physical one (constraint_basis.h) against the dense physical system; and its
// refusal of rank-deficient rows (a taut straight stretch).
#include "kkt_ldlt.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <memory>
#include <random>

#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/solver/internal/kkt_evaluation.h"
#include "cablefit/core/solver/statics_solver.h"
#include "network_test_util.h"

namespace cablefit {
namespace {

using internal::EvaluateKkt;
using internal::KktEvaluation;
using internal::RotateFrames;

// The masked system the solver factorises: held rotations are identity rows of
// H and zero columns of J.
struct System {
  internal::BlockTree h;
  internal::SparseJacobian jac;
  std::vector<char> free;
  Eigen::VectorXd g, c;
  Eigen::MatrixXd dense_h, dense_j, dense_c;  // dense_c: the rows' compliance
  std::shared_ptr<ConstraintBasis> basis;
};

System MaskedSystem(const RodModel& model, const RodState& state, const Eigen::VectorXd& lambda) {
  const KktEvaluation e = EvaluateKkt(model, state, lambda, /*dense_hessian=*/true);
  System s;
  const int n = static_cast<int>(model.items.size());
  s.free.assign(3 * n, 1);
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d)
      if (model.items[i].masked[d]) s.free[3 * i + d] = 0;
  s.dense_h = e.hessian;
  s.dense_j = e.jacobian;
  s.g = e.gradient;
  for (int k = 0; k < 3 * n; ++k) {
    if (s.free[k]) continue;
    s.dense_h.row(k).setZero();
    s.dense_h.col(k).setZero();
    s.dense_h(k, k) = 1.0;
    s.dense_j.col(k).setZero();
    s.g[k] = 0.0;
  }
  s.c = e.constraints;
  s.basis = std::make_shared<ConstraintBasis>(model, state);
  s.dense_c = s.basis->DenseCompliance();
  s.h.ResizeTree(model.item_parent, model.item_order);
  for (int i = 0; i < n; ++i) {
    s.h.Diag(i) = s.dense_h.block<3, 3>(3 * i, 3 * i);
    if (s.h.Parent(i) >= 0) s.h.Coupling(i) = s.dense_h.block<3, 3>(3 * i, 3 * s.h.Parent(i));
  }
  s.jac = s.dense_j.sparseView();
  return s;
}

struct DenseAnswer {
  Eigen::VectorXd step, lambda;
  int negative = 0;
};

DenseAnswer SolveDense(const System& s, double shift) {
  const int n3 = static_cast<int>(s.g.size());
  const int m = static_cast<int>(s.c.size());
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n3 + m, n3 + m);
  k.topLeftCorner(n3, n3) = s.dense_h;
  for (int i = 0; i < n3; ++i)
    if (s.free[i]) k(i, i) += shift;
  k.topRightCorner(n3, m) = s.dense_j.transpose();
  k.bottomLeftCorner(m, n3) = s.dense_j;
  k.bottomRightCorner(m, m) = -s.dense_c;
  Eigen::VectorXd rhs(n3 + m);
  rhs << -s.g, -s.c;
  const Eigen::VectorXd x = k.fullPivLu().solve(rhs);
  DenseAnswer a;
  a.step = x.head(n3);
  a.lambda = x.tail(m);
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues();
  for (int i = 0; i < ev.size(); ++i) a.negative += ev[i] < 0;
  return a;
}

// Returns the unstable directions of the system (negative eigenvalues beyond
// the m rows).
int ExpectSameSolution(const RodModel& model, const System& s, double shift) {
  KktLdlt kkt;
  EXPECT_EQ(kkt.Factorize(model, s.h, s.jac, *s.basis, s.free, shift), KktLdlt::Status::kOk);
  Eigen::VectorXd step, lambda;
  kkt.Solve(s.g, s.c, &step, &lambda);
  const DenseAnswer d = SolveDense(s, shift);
  EXPECT_EQ(kkt.NegativeCount(), d.negative);
  EXPECT_LT((step - d.step).norm(), 1e-8 * d.step.norm());
  EXPECT_LT((lambda - d.lambda).norm(), 1e-8 * d.lambda.norm());
  return d.negative - static_cast<int>(s.c.size());
}

// The system's own right-hand side (unless it is ~0, at an equilibrium), and a
// random one.
int ExpectSameAnswer(const RodModel& model, const System& s, double shift, bool own_rhs = true) {
  const int unstable = own_rhs ? ExpectSameSolution(model, s, shift) : 0;
  System r = s;
  std::mt19937 rng(7);
  std::normal_distribution<double> nd(0.0, 1.0);
  for (int k = 0; k < r.g.size(); ++k) r.g[k] = s.free[k] ? nd(rng) : 0.0;
  for (int k = 0; k < r.c.size(); ++k) r.c[k] = 1e-3 * nd(rng);
  ExpectSameSolution(model, r, shift);
  return unstable;
}

// A 1 m cable held by a clamp, a pin, a clip, a sliding clip and a clamp, with
// a point load.
RodSpec FiveSupportRod() {
  RodSpec r;
  r.length = 1.0;
  r.material = testing::TestMaterial(0.02, 0.12);
  auto support = [](SupportKind kind, double s, const Vec3& p, const Vec3& t) {
    SupportSpec sp;
    sp.kind = kind;
    sp.s = s;
    sp.position = p;
    sp.tangent = t;
    sp.normal = t.unitOrthogonal();
    return sp;
  };
  r.supports.push_back(support(SupportKind::kClamp, 0.0, Vec3(0, 0, 0), Vec3(1, 0, 0.2)));
  r.supports.push_back(support(SupportKind::kPin, 0.2, Vec3(0.18, 0.03, 0.0), Vec3::UnitX()));
  r.supports.push_back(support(SupportKind::kClip, 0.45, Vec3(0.4, 0.05, -0.05), Vec3(1, 0.3, 0)));
  SupportSpec sliding = support(SupportKind::kClip, 0.7, Vec3(0.6, 0.1, 0.0), Vec3(1, 0, -0.3));
  sliding.sliding = true;
  r.supports.push_back(sliding);
  r.supports.push_back(support(SupportKind::kClamp, 1.0, Vec3(0.85, 0.0, 0.1), Vec3(0, -1, 1)));
  r.point_loads.push_back({0.55, Vec3(0.0, 0.3, -0.2)});
  return r;
}

// Random rotations and multipliers: far from equilibrium, so H is usually
// indefinite.
void Perturb(const RodModel& model, double amplitude, unsigned seed, RodState* state,
             Eigen::VectorXd* lambda) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  Eigen::VectorXd theta(3 * model.items.size());
  for (int k = 0; k < theta.size(); ++k) theta[k] = amplitude * nd(rng);
  RotateFrames(model, theta, state);
  lambda->resize(model.num_constraints);
  for (int k = 0; k < lambda->size(); ++k) (*lambda)[k] = 2.0 * nd(rng);
}

// Compares both solvers at states perturbed from `state` (one per seed), unshifted and with
// `shift`; returns how many of them are unstable.
int CheckPerturbedStates(const RodModel& model, const RodState& state, double amplitude,
                         std::initializer_list<unsigned> seeds, double shift) {
  int unstable = 0;
  for (unsigned seed : seeds) {
    RodState off = state;
    Eigen::VectorXd lambda;
    Perturb(model, amplitude, seed, &off, &lambda);
    const System s = MaskedSystem(model, off, lambda);
    unstable += ExpectSameAnswer(model, s, 0.0);
    ExpectSameAnswer(model, s, shift);
  }
  return unstable;
}

TEST(KktLdlt, SingleRodWithEveryKindOfSupportMatchesTheDenseSolve) {
  const RodSpec spec = FiveSupportRod();
  Discretisation disc;
  disc.element_length = 0.02;
  const RodModel model = CompileRodModel(spec, disc);
  RodState state = MakeInitialState(model, DefaultInitialCurve(spec));
  StaticsSummary sum = SolveStatics(model, &state, StaticsOptions{});
  ASSERT_TRUE(sum.converged()) << sum.BriefReport();
  // At the stable equilibrium: m negative pivots exactly.
  System at_rest = MaskedSystem(model, state, state.lambda);
  ExpectSameAnswer(model, at_rest, 0.0, /*own_rhs=*/false);
  {
    KktLdlt kkt;
    ASSERT_EQ(kkt.Factorize(model, at_rest.h, at_rest.jac, *at_rest.basis, at_rest.free, 0.0),
              KktLdlt::Status::kOk);
    EXPECT_EQ(kkt.NegativeCount(), model.num_constraints);
  }
  EXPECT_GT(CheckPerturbedStates(model, state, 0.3, {1u, 2u, 3u}, 0.5), 0)
      << "the perturbed states should include indefinite ones";
}

TEST(KktLdlt, NetworkWithABreakoutAndClipsMatchesTheDenseSolve) {
  NetworkSpec spec;
  spec.junctions.push_back({"breakout", 0.0, 0.01});
  const Vec3 centre(0.3, 0.0, -0.05);
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * M_PI * k / 3 + 0.2;
    const Vec3 far(0.3 + 0.35 * std::cos(a), 0.35 * std::sin(a), 0.0);
    BranchSpec b;
    b.name = "leg" + std::to_string(k);
    b.length = (centre - far).norm() * 1.05;
    b.material = testing::TestMaterial(0.03 + 0.01 * k, 0.1);
    b.route = testing::StraightRoute(far, centre);
    b.supports.push_back(testing::Clamp(0.0, far, (centre - far).normalized()));
    SupportSpec clip;
    clip.kind = SupportKind::kClip;
    clip.s = 0.5 * b.length;
    clip.position = far + 0.5 * (centre - far) + Vec3(0, 0, -0.01);
    clip.tangent = centre - far;
    b.supports.push_back(clip);
    b.end_junction = 0;
    spec.branches.push_back(b);
  }
  const NetworkModel net = CompileNetworkModel(spec, 0.02);
  const RodModel& model = net.rod;
  RodState state = DrawnNetworkState(net);
  EXPECT_GT(CheckPerturbedStates(model, state, 0.2, {4u, 5u}, 2.0), 0)
      << "the perturbed states should include indefinite ones";
}

// A trunk with branches ending in clamped connectors and no support of its own, every branch
// extensible (EA): the connectors' rows are eliminated measured from each other (the rows'
// basis), their physics measured up the tree. The elimination in that basis with its compliance
// T C T^T gives the step and, carried back, the multipliers of the dense physical system.
TEST(KktLdlt, RowsInAnotherBasisGiveThePhysicalSystemsSolution) {
  NetworkSpec spec;
  const int legs = 5;
  Vec3 previous(0, 0, 0);
  for (int k = 0; k <= legs; ++k) {
    const Vec3 next(0.15 * (k + 1), 0.01 * k, 0.0);
    BranchSpec trunk;
    trunk.name = "trunk" + std::to_string(k);
    trunk.length = (next - previous).norm() * 1.02;
    trunk.material = testing::TestMaterial(0.03, 0.1);
    trunk.material.axial_stiffness = 2e3;
    trunk.route = testing::StraightRoute(previous, next);
    if (k == 0) trunk.supports.push_back(testing::Clamp(0.0, previous, next - previous));
    if (k == legs) trunk.supports.push_back(testing::Clamp(trunk.length, next, next - previous));
    if (k > 0) trunk.start_junction = k - 1;
    if (k < legs) {
      trunk.end_junction = k;
      spec.junctions.push_back({"j" + std::to_string(k), 0.0, 0.0});
    }
    spec.branches.push_back(trunk);
    if (k < legs) {
      const Vec3 leaf = next + Vec3(0.02, 0.2 * (k % 2 ? 1 : -1), -0.05);
      BranchSpec leg;
      leg.name = "leg" + std::to_string(k);
      leg.length = (leaf - next).norm() * 1.03;
      leg.material = testing::TestMaterial(0.02, 0.08);
      leg.material.axial_stiffness = 1e3;
      leg.route = testing::StraightRoute(next, leaf);
      leg.start_junction = k;
      leg.supports.push_back(testing::Clamp(leg.length, leaf, leaf - next));
      spec.branches.push_back(leg);
    }
    previous = next;
  }
  const NetworkModel net = CompileNetworkModel(spec, 0.02);
  const RodModel& model = net.rod;
  bool another_basis = false;
  for (const RodSupport& sp : model.supports) another_basis = another_basis || !sp.row_chain.empty();
  ASSERT_TRUE(another_basis) << "the connectors should be measured from each other";
  RodState state = DrawnNetworkState(net);
  Eigen::VectorXd lambda;
  Perturb(model, 0.1, 9u, &state, &lambda);
  const System s = MaskedSystem(model, state, lambda);
  ASSERT_FALSE(s.basis->identity());
  ASSERT_FALSE(s.basis->compliance_coupling().empty());
  for (double shift : {0.0, 1.0}) {
    KktLdlt kkt;
    ASSERT_EQ(kkt.Factorize(model, s.h, s.jac, *s.basis, s.free, shift), KktLdlt::Status::kOk);
    Eigen::VectorXd step, lambda_rows;
    kkt.Solve(s.g, s.c, &step, &lambda_rows);
    // The physical system: rows and Jacobian carried back by T^-1, the diagonal compliance.
    const int m = model.num_constraints;
    Eigen::MatrixXd j_phys(m, s.dense_j.cols());
    for (int col = 0; col < s.dense_j.cols(); ++col)
      j_phys.col(col) = s.basis->ToPhysical(s.dense_j.col(col));
    Eigen::VectorXd c_diag = Eigen::VectorXd::Zero(m);
    for (const RodSupport& sp : model.supports)
      if (sp.constraint_row >= 0) c_diag.segment(sp.constraint_row, sp.constraint_rows).setConstant(sp.compliance);
    EXPECT_GT(c_diag.maxCoeff(), 0.0);
    System phys = s;
    phys.dense_j = j_phys;
    phys.c = s.basis->ToPhysical(s.c);
    phys.dense_c = c_diag.asDiagonal();
    const DenseAnswer d = SolveDense(phys, shift);
    EXPECT_LT((step - d.step).norm(), 1e-8 * d.step.norm()) << shift;
    EXPECT_LT((s.basis->MultipliersToPhysical(lambda_rows) - d.lambda).norm(), 1e-8 * d.lambda.norm())
        << shift;
    EXPECT_EQ(kkt.NegativeCount(), d.negative) << shift;
    // And back: the rows' multipliers from the physical ones.
    EXPECT_LT((s.basis->MultipliersToRows(d.lambda) - lambda_rows).norm(), 1e-8 * lambda_rows.norm());
  }
}

TEST(KktLdlt, TautStraightStretchIsReportedRankDeficient) {
  // Clamped at both ends exactly its length apart, drawn straight: the distance
  // between the clamps cannot change to first order, so that row of J is zero.
  // Weightless, so the straight shape is an equilibrium (under gravity a taut
  // inextensible cable has none).
  RodSpec r;
  r.length = 0.5;
  r.material = testing::TestMaterial();
  r.gravity = Vec3::Zero();
  r.supports.push_back(testing::Clamp(0.0, Vec3::Zero(), Vec3::UnitX()));
  r.supports.push_back(testing::Clamp(0.5, Vec3(0.5, 0, 0), Vec3::UnitX()));
  const RodModel model = CompileRodModel(r);
  RodState state = MakeInitialState(model, DefaultInitialCurve(r));
  const System s = MaskedSystem(model, state, Eigen::VectorXd::Zero(model.num_constraints));
  KktLdlt kkt;
  EXPECT_EQ(kkt.Factorize(model, s.h, s.jac, *s.basis, s.free, 0.0), KktLdlt::Status::kRankDeficient);
  // The solver still gives its verdict (the Schur complement regularises that
  // row).
  StaticsSummary sum = SolveStatics(model, &state, StaticsOptions{});
  EXPECT_TRUE(sum.converged()) << sum.BriefReport();
  EXPECT_TRUE(sum.stable) << sum.BriefReport();
}

}  // namespace
}  // namespace cablefit
