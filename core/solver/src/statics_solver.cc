#include "cablefit/core/solver/statics_solver.h"
#include "cablefit/core/solver/internal/kkt_evaluation.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "cablefit/core/rod/internal/block_tree.h"
#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "constraint_basis.h"
#include "kkt_ldlt.h"
#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/rod_energy.h"
#include "cablefit/core/rod/internal/support_targets.h"

namespace cablefit {
namespace {

using Clock = std::chrono::steady_clock;

// Line search (Nocedal & Wright, "Numerical Optimization", 2nd ed., Alg. 3.1 and sec. 15.4).
// Sufficient decrease: the textbook Armijo constant; small so that a Newton step near the
// solution, whose decrease is about half the model's, is never rejected.
constexpr double kArmijoDecrease = 1e-4;
// Step halvings before a line search gives up: 2^-40 ~ 1e-12 of the Newton step is below what
// changes a double-precision frame, so further halving cannot find a better point.
constexpr int kMaxBacktracks = 40;
// Merit changes within this fraction of its value are round-off, not an increase.
constexpr double kMeritRoundOff = 1e-14;
// A full step that at least halves the KKT residual is accepted even if the merit rejects it
// (Maratos effect): Newton's local quadratic convergence cuts it by far more than that.
constexpr double kMaratosResidualReduction = 0.5;
// The exact-penalty weight must exceed |lambda|_inf (N&W Thm 17.3); the margin keeps it above
// the multipliers of the next iterations, the floor keeps it positive with no load on a row.
constexpr double kPenaltyMargin = 1.5;
constexpr double kPenaltyFloor = 1e-12;  // times force_scale [N]

// Inertia correction (N&W sec. 3.4, "modified Newton"): the first shift is at round-off level of
// the Hessian's scale so a barely indefinite Hessian is barely changed; each retry multiplies
// it by ten, and a shift beyond 1e6 x the scale means the step would be steepest descent with
// a vanishing length: the set-up is singular, not merely non-convex.
constexpr double kFirstHessianShift = 1e-8;  // times the Hessian's scale
constexpr double kHessianShiftGrowth = 10.0;
constexpr double kMaxHessianShift = 1e6;     // times the Hessian's scale

// Relative size below which a number is round-off in double precision (pivots of the Schur
// complement, the converged gradient against the stiffest frame's Hessian entry).
constexpr double kRoundOff = 1e-12;
// A Newton step shorter than this [rad] cannot change a double-precision unit quaternion.
constexpr double kStepRoundOff = 1e-15;
// Short thick cables (aspect ~3, a wire stub of a connector) stall with their position
// constraints at ~1e-9 of the length: the KKT solve's accuracy, not a lack of iterations (seen:
// 60 iterations oscillating between 5e-12 and 4e-11 m on a 25 mm, 8 mm thick cable). A residual
// that has not halved for kStagnationIterations iterations while below kStagnationFloor x length
// (a hundredth of a micrometre per metre) and a converged gradient is that floor: converged.
constexpr double kStagnationFloor = 1e-8;
constexpr int kStagnationIterations = 8;
// The same floor seen in the steps: a large network (7653 elements) ends its solves with steps of
// 1e-8..1e-7 rad that trade a gradient of 1e-11..5e-7 N m against constraints of 1e-10 m, for
// ten iterations and more, before both happen to fall below tolerance. Steps that rotate no frame
// by more than kRoundOffRotation (positions move by less than a tenth of a micrometre per metre
// of cable) for kRoundOffSteps iterations without the KKT residual halving, with the constraints
// below the stagnation floor, are that floor: converged.
constexpr double kRoundOffRotation = 1e-7;  // [rad]
constexpr int kRoundOffSteps = 3;

// Continuation in the support poses (and loads): the first step goes a quarter of the way, a
// step that converged within kEasyStepIterations Newton iterations lets the next one grow by
// kStepGrowth up to kMaxStep, a failed one is halved; below kMinStep it is stalled (the
// path has a fold there that a smaller step does not pass either). Steps below kSnapStep get
// kSnapIterationFactor times the Newton iterations: the room to snap through such a fold.
constexpr double kFirstContinuationStep = 0.25;
constexpr double kMaxContinuationStep = 0.5;
constexpr double kMinContinuationStep = 1e-4;
constexpr double kContinuationStepGrowth = 1.5;
constexpr int kEasyStepIterations = 6;
constexpr double kSnapStep = 0.01;
constexpr int kSnapIterationFactor = 8;

// Leaving a saddle: kicks of growing size [rad per frame]. The smallest stays within the basin
// of a nearby stable state, the largest is still small enough to keep the cable's shape class;
// a fixed seed keeps every run reproducible.
constexpr double kEscapeKicks[] = {0.01, 0.03, 0.1};
constexpr unsigned kEscapeSeed = 12345;

// Pseudo-transient continuation (Kelley & Keyes, SIAM J. Numer. Anal. 35 (1998); Coffey, Kelley &
// Keyes, SIAM J. Sci. Comput. 25 (2003) for the constrained case): implicit Euler steps of the
// gradient flow, (H + shift I) dx = -g with the constraints kept, shift = 1 / pseudo-time step.
// The flow only goes downhill, so it passes folds a continuation in the load parameter stalls at;
// it is the globaliser when that stalls. The first shift is a thousandth of the Hessian scale (a
// step of a few degrees per frame on the stiffest frame). A full step taken lets the pseudo-time
// step grow tenfold, a step the line search had to cut shrinks it fourfold: switched evolution
// relaxation by the residual alone turned the flow into Newton's method 25 steps into a 30-turn
// coil, which then crawled at cut steps for thousands of iterations. Below the floor the steps
// are Newton's. A line search that fails raises the shift tenfold instead of ending the solve
// (a shorter pseudo-time step is closer to the flow). The flow needs far more steps than Newton:
// the 30-turn coil took 1340, hence kPseudoTransientIterationFactor x the Newton budget.
constexpr double kPseudoTransientFirstShift = 1e-3;
constexpr double kPseudoTransientShiftCut = 0.1;
constexpr double kPseudoTransientShiftGrowth = 4.0;
constexpr double kPseudoTransientRaise = 10.0;
constexpr double kPseudoTransientFloor = 1e-8;
constexpr int kPseudoTransientIterationFactor = 60;

struct Evaluation {
  double energy = 0.0;
  Eigen::VectorXd gradient;  // energy gradient (no constraint term), masked entries zeroed
  Eigen::VectorXd c;            // in the rows' basis (constraint_basis.h)
  internal::SparseJacobian jac;  // in the rows' basis
  internal::BlockTree hessian;
};

std::vector<char> FreeMask(const RodModel& model) {
  std::vector<char> free(3 * model.items.size(), 1);
  for (size_t i = 0; i < model.items.size(); ++i)
    for (int d = 0; d < 3; ++d)
      if (model.items[i].masked[d]) free[3 * i + d] = 0;
  return free;
}

void Evaluate(const RodModel& model, const RodState& state, bool with_hessian,
              const Eigen::VectorXd* lambda, const std::vector<char>& free, Evaluation* ev,
              bool with_jacobian = true) {
  internal::EnergyAccumulator acc;
  const int n = static_cast<int>(model.items.size());
  acc.Reset(model, with_hessian ? &ev->hessian : nullptr);
  internal::AddBendingEnergy(model, state, &acc);
  internal::AddLoadEnergy(model, state, &acc);
  internal::AddSupportSpringEnergy(model, state, &acc);
  ev->energy = acc.value;
  ev->gradient = acc.gradient;
  for (int k = 0; k < 3 * n; ++k)
    if (!free[k]) ev->gradient[k] = 0.0;
  if (!with_jacobian) {
    internal::EvaluatePositionConstraints(model, state, &ev->c, nullptr);
  } else {
    internal::EvaluatePositionConstraints(model, state, &ev->c, &ev->jac);
    ev->jac.prune([&free](Eigen::Index, Eigen::Index col, double) { return free[col] != 0; });
  }
  if (with_hessian && lambda) internal::AddConstraintCurvature(model, state, *lambda, &ev->hessian);
}

// Per constraint row: the axial compliance of its support's stretch [m/N] (0 = rigid row).
Eigen::VectorXd RowCompliance(const RodModel& model) {
  Eigen::VectorXd comp = Eigen::VectorXd::Zero(model.num_constraints);
  for (const RodSupport& sp : model.supports) {
    if (sp.constraint_row < 0) continue;
    comp.segment(sp.constraint_row, sp.constraint_rows).setConstant(sp.compliance);
  }
  return comp;
}

// The constraint residual: c on rigid rows, c - C lambda on compliant ones (an extensible
// stretch is in balance when its end has moved by its stretch, C times its force).
Eigen::VectorXd ConstraintResidual(const Eigen::VectorXd& c, const Eigen::VectorXd& compliance,
                                   const Eigen::VectorXd& lambda) {
  if (c.size() == 0 || lambda.size() != c.size()) return c;
  return c - compliance.cwiseProduct(lambda);
}

// The merit of a state: energy, plus for rigid rows the exact penalty nu |c|_1 and for
// compliant rows their stretch energy c^2 / (2 C), which makes them ordinary energy terms.
double PenaltyTerms(const Eigen::VectorXd& c, const Eigen::VectorXd& compliance, double nu) {
  double phi = 0.0;
  for (Eigen::Index i = 0; i < c.size(); ++i) {
    phi += compliance[i] > 0 ? 0.5 * c[i] * c[i] / compliance[i] : nu * std::abs(c[i]);
  }
  return phi;
}

double Merit(const RodModel& model, const RodState& state, double nu,
             const std::vector<char>& free, const Eigen::VectorXd& compliance,
             const ConstraintBasis& basis) {
  Evaluation ev;
  Evaluate(model, state, false, nullptr, free, &ev, /*with_jacobian=*/false);
  return ev.energy + PenaltyTerms(basis.ToPhysical(ev.c), compliance, nu);
}

// Replaces masked rows/columns by the identity so the tree keeps one uniform block structure.
void MaskHessian(const std::vector<char>& free, internal::BlockTree* h) {
  const int n = h->size();
  for (int i = 0; i < n; ++i) {
    const int p = h->Parent(i);
    for (int d = 0; d < 3; ++d) {
      if (!free[3 * i + d]) {
        h->Diag(i).row(d).setZero();
        h->Diag(i).col(d).setZero();
        h->Diag(i)(d, d) = 1.0;
        if (p >= 0) h->Coupling(i).row(d).setZero();
      }
      if (p >= 0 && !free[3 * p + d]) h->Coupling(i).col(d).setZero();
    }
  }
}

void ShiftFree(const std::vector<char>& free, double mu, internal::BlockTree* h) {
  for (int i = 0; i < h->size(); ++i)
    for (int d = 0; d < 3; ++d)
      if (free[3 * i + d]) h->Diag(i)(d, d) += mu;
}

void ApplyStep(const RodModel& model, const Eigen::VectorXd& step, double alpha, RodState* state) {
  for (size_t i = 0; i < model.items.size(); ++i) {
    const Eigen::Vector3d th = alpha * step.segment<3>(3 * i);
    if (th.squaredNorm() == 0.0) continue;
    state->q[i] = internal::quat::Multiply(state->q[i], internal::quat::Exp(th)).normalized();
  }
  internal::AlignQuaternionSigns(model, state);
}

struct KktSolve {
  bool ok = false;
  bool factored = false;        // by the KktLdlt, which can then solve other right-hand sides
  int negative_directions = 0;  // of the reduced Hessian (unstable directions on the manifold)
  Eigen::VectorXd step;         // 3n
  Eigen::VectorXd lambda;       // m, in the rows' basis
  Eigen::VectorXd physical_lambda;  // m, the physical multipliers (-reactions)
};

// The same system through the Schur complement S = C H^-1 C^T (O(n m) + O(m^3)): its inertia
// is inertia(H) + inertia(-S) and, unlike the block elimination, it can regularise rank-deficient
// support rows. Used only when KktLdlt reports them.
KktSolve SolveKktBySchurComplement(const internal::BlockTree& h_masked, const Evaluation& ev,
                                   const std::vector<char>& free, double mu,
                                   const ConstraintBasis& basis) {
  KktSolve out;
  internal::BlockTree h = h_masked;
  if (mu != 0.0) ShiftFree(free, mu, &h);
  internal::BlockTreeLdlt ldlt;
  if (!ldlt.Factorize(h, 0.0)) return out;
  const int m = static_cast<int>(ev.c.size());
  const int n3 = static_cast<int>(ev.gradient.size());
  internal::BlockTreeLdlt::RowMajorMatrix rhs(n3, 1 + m);
  rhs.col(0) = ev.gradient;
  if (m > 0) rhs.rightCols(m) = ev.jac.transpose();
  ldlt.SolveInPlace(rhs);
  int neg = ldlt.NegativeCount();
  if (m > 0) {
    Eigen::MatrixXd s = ev.jac * rhs.rightCols(m);
    s = (0.5 * (s + s.transpose())).eval();
    s += basis.DenseCompliance();
    const Eigen::VectorXd r = ev.c - ev.jac * rhs.col(0);
    // S = C H^-1 C^T by LDL^T (O(m^3/3)); its pivots' signs give its inertia (Sylvester).
    Eigen::LDLT<Eigen::MatrixXd> ldlt_s(s);
    const Eigen::VectorXd d = ldlt_s.vectorD();
    const double scale = std::max(1e-300, d.cwiseAbs().maxCoeff());
    int pos = 0;
    bool rank_deficient = ldlt_s.info() != Eigen::Success;
    for (int k = 0; k < m && !rank_deficient; ++k) {
      if (std::abs(d[k]) <= kRoundOff * scale) rank_deficient = true;
      if (d[k] > 0) ++pos;
    }
    if (!rank_deficient) {
      out.lambda = ldlt_s.solve(r);
    } else {
      // Rank-deficient constraints (a taut straight stretch between two supports cannot change
      // its end distance to first order) are regularised: the step then leaves those residual
      // directions to the next iterations instead of failing; a truly over-constrained set-up
      // still fails on its constraint residual.
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(s);
      Eigen::VectorXd ev_s = eig.eigenvalues();
      const double escale = std::max(1e-300, ev_s.cwiseAbs().maxCoeff());
      pos = 0;
      for (int k = 0; k < m; ++k) {
        if (std::abs(ev_s[k]) <= kRoundOff * escale) ev_s[k] = kRoundOff * escale;
        if (ev_s[k] > 0) ++pos;
      }
      out.lambda = eig.eigenvectors() *
                   (ev_s.cwiseInverse().asDiagonal() * (eig.eigenvectors().transpose() * r));
    }
    neg += pos - m;
    out.step = -(rhs.col(0) + rhs.rightCols(m) * out.lambda);
  } else {
    out.lambda.resize(0);
    out.step = -rhs.col(0);
  }
  out.negative_directions = neg;
  out.ok = true;
  return out;
}

// The Newton system by the O(n) block elimination of the whole KKT matrix (kkt_ldlt.h).
KktSolve SolveKkt(KktLdlt* kkt, const RodModel& model, const internal::BlockTree& h_masked,
                  const Evaluation& ev, const std::vector<char>& free, double mu,
                  const ConstraintBasis& basis) {
  KktSolve out;
  switch (kkt->Factorize(model, h_masked, ev.jac, basis, free, mu)) {
    case KktLdlt::Status::kSingularPivot:
      return KktSolve{};
    case KktLdlt::Status::kRankDeficient:
      out = SolveKktBySchurComplement(h_masked, ev, free, mu, basis);
      break;
    case KktLdlt::Status::kOk:
      kkt->Solve(ev.gradient, ev.c, &out.step, &out.lambda);
      out.negative_directions = kkt->NegativeCount() - static_cast<int>(ev.c.size());
      out.ok = true;
      out.factored = true;
      break;
  }
  if (out.ok) out.physical_lambda = basis.MultipliersToPhysical(out.lambda);
  return out;
}

double HessianScale(const internal::BlockTree& h) {
  double s = 0.0;
  for (int i = 0; i < h.size(); ++i) s = std::max(s, h.Diag(i).diagonal().cwiseAbs().maxCoeff());
  return std::max(s, 1e-300);
}

}  // namespace

namespace internal {

KktEvaluation EvaluateKkt(const RodModel& model, const RodState& state,
                          const Eigen::VectorXd& lambda, bool dense_hessian) {
  std::vector<char> all_free(3 * model.items.size(), 1);
  Evaluation ev;
  Evaluate(model, state, dense_hessian, &lambda, all_free, &ev);
  KktEvaluation out;
  out.energy = ev.energy;
  out.gradient = ev.gradient;
  out.constraints = ev.c;
  out.jacobian = Eigen::MatrixXd(ev.jac);
  if (dense_hessian) {
    const int n = ev.hessian.size();
    out.hessian = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (int i = 0; i < n; ++i) {
      out.hessian.block<3, 3>(3 * i, 3 * i) = ev.hessian.Diag(i);
      const int p = ev.hessian.Parent(i);
      if (p < 0) continue;
      out.hessian.block<3, 3>(3 * i, 3 * p) = ev.hessian.Coupling(i);
      out.hessian.block<3, 3>(3 * p, 3 * i) = ev.hessian.Coupling(i).transpose();
    }
  }
  return out;
}

void RotateFrames(const RodModel& model, const Eigen::VectorXd& theta, RodState* state) {
  ApplyStep(model, theta, 1.0, state);
}

}  // namespace internal

bool StaticsOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (max_iterations < 1) return fail("max_iterations must be >= 1");
  if (!(gradient_tolerance > 0)) return fail("gradient_tolerance must be > 0");
  if (!(constraint_tolerance > 0)) return fail("constraint_tolerance must be > 0");
  if (!(max_step_rotation > 0)) return fail("max_step_rotation must be > 0");
  if (max_continuation_steps < 0) return fail("max_continuation_steps must be >= 0");
  return true;
}

const char* ToString(TerminationType t) {
  switch (t) {
    case TerminationType::kConverged:
      return "converged";
    case TerminationType::kNoConvergence:
      return "no_convergence";
    case TerminationType::kLineSearchFailure:
      return "line_search_failure";
    case TerminationType::kInvalidOptions:
      return "invalid_options";
  }
  return "?";
}

std::string StaticsSummary::BriefReport() const {
  std::ostringstream os;
  os << ToString(termination) << ": " << iterations << " Newton iterations, " << continuation_steps
     << " continuation steps, |grad| " << gradient_norm << " N m, |c| " << constraint_norm
     << " m, energy " << final_energy << " J, " << (stable ? "stable" : "UNSTABLE") << ", "
     << seconds * 1e3 << " ms";
  if (!message.empty()) os << " (" << message << ")";
  return os.str();
}

namespace {

/// Like Ceres' Solve: invalid options are a summary that says why, not an abort or a throw.
bool RejectInvalidOptions(const StaticsOptions& options, StaticsSummary* sum) {
  std::string why;
  if (options.IsValid(&why)) return false;
  *sum = StaticsSummary{};
  sum->termination = TerminationType::kInvalidOptions;
  sum->message = "invalid statics options: " + why;
  return true;
}

// Second-order correction (Nocedal & Wright, "Numerical Optimization", 2nd ed., sec. 15.4 and
// Alg. 18.3). A support's position is the sum of the rotated elements between it and its
// reference, so across a long stretch (a branch of a harness tree) a step that is small in
// every frame still misses the linearised constraint by ~ length x rotation^2: the merit
// rejects it and the line search crawls at 1/32 steps. The correction d solves the same KKT
// system (already factorised) for the constraint error the linearisation left, e = c(x + p) -
// (c(x) + J p), so x + p + d is on the linearised constraint to higher order; it is taken when
// it meets the sufficient decrease the full step was asked for. `state` holds x + p on entry;
// on success it holds x + p + d.
bool SecondOrderCorrection(const RodModel& model, const KktLdlt& kkt_ldlt, const Evaluation& ev,
                           const Eigen::VectorXd& step, const Eigen::VectorXd& c_trial, double nu,
                           const std::vector<char>& free, const Eigen::VectorXd& compliance,
                           const ConstraintBasis& basis, double phi_wanted, RodState* state) {
  const Eigen::VectorXd error = c_trial - (ev.c + ev.jac * step);
  Eigen::VectorXd correction, unused;
  kkt_ldlt.Solve(Eigen::VectorXd::Zero(ev.gradient.size()), error, &correction, &unused);
  if (!correction.allFinite()) return false;
  for (int k = 0; k < correction.size(); ++k)
    if (!free[k]) correction[k] = 0.0;
  ApplyStep(model, correction, 1.0, state);
  return Merit(model, *state, nu, free, compliance, basis) <= phi_wanted;
}

// The stability verdict from `ev`, evaluated (with its Hessian) at the state in question.
void StabilityAt(const RodModel& model, const std::vector<char>& free, Evaluation* ev,
                 const ConstraintBasis& basis, KktLdlt* kkt_ldlt, StaticsSummary* summary) {
  MaskHessian(free, &ev->hessian);  // idempotent: it may have been masked for a step already
  const KktSolve kkt = SolveKkt(kkt_ldlt, model, ev->hessian, *ev, free, 0.0, basis);
  summary->stable = kkt.ok && kkt.negative_directions == 0;
  summary->negative_directions = kkt.ok ? kkt.negative_directions : -1;
}

}  // namespace

namespace {

// Newton's method on the KKT system; with `pseudo_time_shift` > 0 (relative to the Hessian
// scale) pseudo-transient continuation that turns into Newton's method as it converges.
StaticsSummary SolveStaticsNewton(const RodModel& model, RodState* state,
                                  const StaticsOptions& options, double pseudo_time_shift) {
  const auto t0 = Clock::now();
  StaticsSummary sum;
  if (RejectInvalidOptions(options, &sum)) return sum;
  const std::vector<char> free = FreeMask(model);
  const double L = model.length;
  const double gtol = options.gradient_tolerance * model.force_scale * L;
  const double ctol = options.constraint_tolerance * L;
  if (state->lambda.size() != model.num_constraints) state->lambda.setZero(model.num_constraints);
  const Eigen::VectorXd compliance = RowCompliance(model);
  internal::ApplySupportTargets(model, state);
  Evaluation ev;
  KktLdlt kkt_ldlt;  // analysed at the first iteration, reused while the pattern holds
  double nu = 0.0;
  bool first = true;
  double best_constraint = std::numeric_limits<double>::infinity();
  int best_constraint_iter = 0;
  double best_kkt = std::numeric_limits<double>::infinity();
  int best_kkt_iter = 0;
  int round_off_steps = 0;  // consecutive steps below kRoundOffRotation
  const bool pseudo_transient = pseudo_time_shift > 0;
  // The rows' basis (constraint_basis.h) depends on the supports' frames only, which stay put
  // during a solve (ApplySupportTargets above).
  const ConstraintBasis basis(model, *state);
  for (int iter = 0;; ++iter) {
    CheckCancelled();  // a batch item's --timeout
    const Eigen::VectorXd lambda_rows = basis.MultipliersToRows(state->lambda);
    Evaluate(model, *state, true, &lambda_rows, free, &ev);
    if (first) {
      sum.initial_energy = ev.energy;
      first = false;
    }
    const Eigen::VectorXd c_phys = basis.ToPhysical(ev.c);
    const Eigen::VectorXd grad_l =
        model.num_constraints > 0
            ? Eigen::VectorXd(ev.gradient + ev.jac.transpose() * lambda_rows)
            : ev.gradient;
    sum.gradient_norm = grad_l.lpNorm<Eigen::Infinity>();
    sum.constraint_norm =
        ev.c.size() ? ConstraintResidual(c_phys, compliance, state->lambda).lpNorm<Eigen::Infinity>()
                    : 0.0;
    sum.final_energy = ev.energy;
    sum.iterations = iter;
    // Round-off floor: a gradient below 1e-12 of the stiffest frame's Hessian entry is as
    // converged as double precision allows (fine discretisations of stiff cables reach it first).
    const double gtol_eff = std::max(gtol, kRoundOff * HessianScale(ev.hessian));
    if (sum.gradient_norm <= gtol_eff && sum.constraint_norm <= ctol) {
      sum.termination = TerminationType::kConverged;
      break;
    }
    if (sum.constraint_norm < 0.5 * best_constraint) {
      best_constraint = sum.constraint_norm;
      best_constraint_iter = iter;
    }
    if (sum.gradient_norm <= gtol_eff && sum.constraint_norm <= kStagnationFloor * L &&
        iter - best_constraint_iter >= kStagnationIterations) {
      sum.termination = TerminationType::kConverged;
      sum.message = "constraints held to the solver's round-off floor (" +
                    std::to_string(sum.constraint_norm) + " m)";
      break;
    }
    const double kkt_residual = std::max(sum.gradient_norm / gtol_eff, sum.constraint_norm / ctol);
    if (kkt_residual < 0.5 * best_kkt) {
      best_kkt = kkt_residual;
      best_kkt_iter = iter;
    }
    if (round_off_steps >= kRoundOffSteps && iter - best_kkt_iter >= kRoundOffSteps &&
        sum.constraint_norm <= kStagnationFloor * L) {
      sum.termination = TerminationType::kConverged;
      sum.message = "Newton steps at the solver's round-off floor (|grad| " +
                    std::to_string(sum.gradient_norm) + " N m)";
      break;
    }
    if (iter >= options.max_iterations) {
      sum.termination = TerminationType::kNoConvergence;
      sum.message = "iteration limit";
      break;
    }
    MaskHessian(free, &ev.hessian);
    const double scale = HessianScale(ev.hessian);
    const double kkt0 = std::max(sum.gradient_norm / gtol, sum.constraint_norm / ctol);
    KktSolve kkt;
    // Inertia correction. A Hessian that is not finite (loads beyond any physical size) has no
    // shift that helps: the loop would never reach its bound, so it fails at once.
    double shift = 0.0;  // the one the step was solved with
    for (double mu = pseudo_time_shift * scale; std::isfinite(scale);) {
      CheckCancelled();
      kkt = SolveKkt(&kkt_ldlt, model, ev.hessian, ev, free, mu, basis);
      shift = mu;
      if (kkt.ok && kkt.negative_directions == 0) break;
      mu = mu == 0.0 ? kFirstHessianShift * scale : kHessianShiftGrowth * mu;
      if (mu > kMaxHessianShift * scale) {
        kkt.ok = false;
        break;
      }
    }
    if (!kkt.ok) {
      sum.termination = TerminationType::kLineSearchFailure;
      sum.message = "KKT system singular (supports over-constrain the cable?)";
      break;
    }
    // Limit the largest frame rotation of one step.
    double max_rot = 0.0;
    for (size_t i = 0; i < model.items.size(); ++i)
      max_rot = std::max(max_rot, kkt.step.segment<3>(3 * i).norm());
    // Only a Newton step tells how far the solution is: a shifted one (pseudo-time, inertia
    // correction beyond round-off) is short because of its shift.
    const bool newton_step = shift <= kFirstHessianShift * scale;
    round_off_steps = newton_step && max_rot <= kRoundOffRotation ? round_off_steps + 1 : 0;
    Eigen::VectorXd step = kkt.step;
    if (max_rot > options.max_step_rotation) step *= options.max_step_rotation / max_rot;
    const double step_norm = step.lpNorm<Eigen::Infinity>();
    if (step_norm < kStepRoundOff && sum.constraint_norm <= ctol) {
      sum.termination = TerminationType::kConverged;
      sum.message = "step below round-off";
      break;
    }
    nu = std::max(nu, kPenaltyMargin * (kkt.physical_lambda.size()
                                            ? kkt.physical_lambda.lpNorm<Eigen::Infinity>()
                                            : 0.0) +
                          kPenaltyFloor * model.force_scale);
    double rigid_c1 = 0.0, compliant_slope = 0.0;
    if (ev.c.size()) {
      const Eigen::VectorXd jac_step = basis.ToPhysical(ev.jac * step);
      for (Eigen::Index i = 0; i < ev.c.size(); ++i) {
        if (compliance[i] > 0) {
          compliant_slope += c_phys[i] / compliance[i] * jac_step[i];
        } else {
          rigid_c1 += std::abs(c_phys[i]);
        }
      }
    }
    const double phi0 = ev.energy + PenaltyTerms(c_phys, compliance, nu);
    const double slope = ev.gradient.dot(step) + compliant_slope - nu * rigid_c1;
    const RodState start = *state;
    double alpha = 1.0;
    bool accepted = false;
    for (int ls = 0; ls < kMaxBacktracks; ++ls, alpha *= 0.5) {
      *state = start;
      ApplyStep(model, step, alpha, state);
      const double phi = Merit(model, *state, nu, free, compliance, basis);
      if (phi <= phi0 + kArmijoDecrease * alpha * std::min(slope, 0.0) +
                     kMeritRoundOff * std::abs(phi0)) {
        accepted = true;
        break;
      }
      if (ls == 0) {
        // Near the solution the merit can reject good Newton steps (Maratos effect): accept a
        // full step that reduces the KKT residual markedly.
        Evaluation trial;
        Evaluate(model, *state, false, nullptr, free, &trial);
        const Eigen::VectorXd gl =
            model.num_constraints > 0
                ? Eigen::VectorXd(trial.gradient + trial.jac.transpose() * kkt.lambda)
                : trial.gradient;
        const double kkt1 = std::max(
            gl.lpNorm<Eigen::Infinity>() / gtol,
            (trial.c.size() ? ConstraintResidual(basis.ToPhysical(trial.c), compliance,
                                                 kkt.physical_lambda)
                                  .lpNorm<Eigen::Infinity>()
                            : 0.0) /
                ctol);
        if (kkt1 < kMaratosResidualReduction * kkt0) {
          accepted = true;
          break;
        }
        if (kkt.factored && trial.c.size() &&
            SecondOrderCorrection(model, kkt_ldlt, ev, step, trial.c, nu, free, compliance, basis,
                                  phi0 + kArmijoDecrease * std::min(slope, 0.0), state)) {
          ++sum.second_order_corrections;
          accepted = true;
          break;
        }
        *state = start;
      }
    }
    if (!accepted && pseudo_transient &&
        pseudo_time_shift * kPseudoTransientRaise <= kMaxHessianShift) {
      *state = start;
      pseudo_time_shift =
          std::max(kPseudoTransientRaise * pseudo_time_shift, kPseudoTransientFirstShift);
      continue;
    }
    if (pseudo_transient) {
      // The pseudo-time step grows while the flow's full steps are taken and shrinks when the
      // line search had to cut one: far from equilibrium the flow stays a flow instead of
      // turning into a Newton iteration that crawls at cut steps.
      pseudo_time_shift = alpha == 1.0 ? pseudo_time_shift * kPseudoTransientShiftCut
                                       : std::max(pseudo_time_shift * kPseudoTransientShiftGrowth,
                                                  kPseudoTransientFloor);
      if (pseudo_time_shift < kPseudoTransientFloor) pseudo_time_shift = 0.0;
    }
    if (!accepted) {
      *state = start;
      sum.termination = TerminationType::kLineSearchFailure;
      sum.message = "no step decreased the merit function";
      break;
    }
    state->lambda = kkt.physical_lambda;
  }
  // Every way to convergence leaves `ev` evaluated at the final state (the same call as
  // EvaluateStability's) and `kkt_ldlt` analysed for its pattern: the verdict costs one
  // factorisation, not a second evaluation and analysis (a fifth of a warm-started solve).
  if (sum.converged()) StabilityAt(model, free, &ev, basis, &kkt_ldlt, &sum);
  sum.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return sum;
}

// The pseudo-transient solve at the state's targets and factors, with its larger budget.
StaticsSummary SolvePseudoTransient(const RodModel& model, RodState* state,
                                    const StaticsOptions& options) {
  StaticsOptions flow = options;
  flow.max_iterations = kPseudoTransientIterationFactor * options.max_iterations;
  return SolveStaticsNewton(model, state, flow, kPseudoTransientFirstShift);
}

}  // namespace

StaticsSummary SolveStaticsDirect(const RodModel& model, RodState* state,
                                  const StaticsOptions& options) {
  return SolveStaticsNewton(model, state, options, 0.0);
}

void EvaluateStability(const RodModel& model, const RodState& state, StaticsSummary* summary) {
  const std::vector<char> free = FreeMask(model);
  const ConstraintBasis basis(model, state);
  const Eigen::VectorXd lambda_rows = basis.MultipliersToRows(state.lambda);
  Evaluation ev;
  Evaluate(model, state, true, &lambda_rows, free, &ev);
  KktLdlt kkt_ldlt;
  StabilityAt(model, free, &ev, basis, &kkt_ldlt, summary);
}

namespace {

// What a continuation ramps from the start state to the full problem.
enum class Homotopy {
  kPoses,          // support poses only (or with loads when options.ramp_loads)
  // Rest curvature from the drawn (start) shape's own to the real one, loads from zero and
  // support poses from the drawn ones: its t = 0 is solved by the drawing exactly, so the path
  // starts at an equilibrium instead of asking a straight-rest cable to hold the drawn shape.
  kDrawnRest,
};

}  // namespace

StaticsSummary SolveStaticsFrom(const RodModel& model, RodState* state,
                                const StaticsOptions& options, bool try_direct = true,
                                Homotopy homotopy = Homotopy::kPoses);
StaticsSummary SolveStaticsAndEscape(const RodModel& model, RodState* state,
                                     const StaticsOptions& options);

namespace {

// Why a failed solve had no chance: two supports holding position with no more cable between
// them than their distance (a cable drawn straight between two clamps). An inextensible cable
// cannot hang there under a transverse load, and the Newton system is singular in that stretch.
std::string TautStretch(const RodModel& model) {
  for (size_t k = 0; k < model.supports.size(); ++k) {
    const RodSupport& sp = model.supports[k];
    if (sp.constraint_row < 0 || sp.sliding || sp.contact || sp.compliance > 0) continue;
    const int ref = sp.reference >= 0 ? sp.reference : model.anchor_support;
    if (ref < 0 || ref == static_cast<int>(k)) continue;
    const RodSupport& from = model.supports[ref];
    if (from.sliding || from.contact) continue;
    double path = 0.0;
    model.ForEachPathElementFrom(sp.reference >= 0 ? from.node : -1, sp.node,
                                 [&](int j, int) { path += model.element_length[j]; });
    const double chord = (sp.position - from.position).norm();
    if (path > 0 && path <= chord * (1 + 1e-6)) {
      std::ostringstream os;
      os.precision(6);
      os << "the supports at s=" << from.s << " m and s=" << sp.s << " m are " << chord
         << " m apart with " << path
         << " m of cable between them: taut, an inextensible cable cannot hang there (give it "
            "slack or let one slide)";
      return os.str();
    }
  }
  return "";
}

}  // namespace

StaticsSummary SolveStatics(const RodModel& model, RodState* state, const StaticsOptions& options) {
  StaticsSummary sum;
  if (RejectInvalidOptions(options, &sum)) return sum;
  sum = SolveStaticsAndEscape(model, state, options);
  if (!sum.converged()) {
    const std::string taut = TautStretch(model);
    if (!taut.empty()) sum.message = taut + "; " + sum.message;
  }
  return sum;
}

StaticsSummary SolveStaticsAndEscape(const RodModel& model, RodState* state,
                                     const StaticsOptions& options) {
  const RodState start = *state;
  // When the direct solve fails, the path that starts at a solved point goes first: the start
  // taken as stress-free. The continuations below start from a straight-rest cable held in the
  // drawn shape, which a coil or a kinked drawing does not reach; they remain as fallbacks.
  StaticsSummary sum = SolveStaticsFrom(model, state, options, true, Homotopy::kDrawnRest);
  if (!sum.converged()) {
    // Its direct solve is the one that just failed (same start, targets and loads; the solve is
    // deterministic), so only the continuation is run.
    RodState retry = start;
    StaticsSummary poses = SolveStaticsFrom(model, &retry, options, /*try_direct=*/false);
    poses.iterations += sum.iterations;
    if (poses.converged()) {
      *state = retry;
      sum = poses;
    } else {
      poses.message = "from the drawn shape as rest shape: " + sum.message + "; " + poses.message;
      sum = poses;
    }
  }
  if (!sum.converged() && !options.ramp_loads) {
    // A start far from any loaded equilibrium (e.g. a default shape under a heavy, anisotropic
    // load): relax it weightless first and bring the loads in by continuation.
    // Its direct solve is the one that just failed (same start, targets and full loads; the
    // solve is deterministic), so only the continuation is run.
    RodState retry = start;
    StaticsOptions ramped = options;
    ramped.ramp_loads = true;
    StaticsSummary second = SolveStaticsFrom(model, &retry, ramped, /*try_direct=*/false);
    second.iterations += sum.iterations;
    if (second.converged()) {
      *state = retry;
      sum = second;
    } else {
      sum.iterations = second.iterations;
    }
  }
  if (!options.escape_unstable || !sum.converged() || sum.stable) return sum;
  // A saddle: small deterministic pseudo-random rotations break the symmetry that held the
  // solver there; the line search then only goes downhill, towards a stable state.
  std::mt19937 rng(kEscapeSeed);
  std::normal_distribution<double> nd(0.0, 1.0);
  const std::vector<char> free = FreeMask(model);
  for (double amplitude : kEscapeKicks) {
    RodState trial = *state;
    Eigen::VectorXd kick(3 * model.items.size());
    for (int k = 0; k < kick.size(); ++k) kick[k] = free[k] ? amplitude * nd(rng) : 0.0;
    ApplyStep(model, kick, 1.0, &trial);
    StaticsSummary again = SolveStaticsDirect(model, &trial, options);
    again.iterations += sum.iterations;
    if (again.converged() && again.stable && again.final_energy < sum.final_energy) {
      *state = trial;
      again.message = "left an unstable equilibrium";
      return again;
    }
  }
  return sum;
}

StaticsSummary SolveStaticsFrom(const RodModel& model, RodState* state,
                                const StaticsOptions& options, bool try_direct,
                                Homotopy homotopy) {
  const auto t0 = Clock::now();
  RodState start = *state;
  const bool drawn_rest = homotopy == Homotopy::kDrawnRest;
  if (drawn_rest) {
    // The drawn shape's support poses, whatever targets the state held (the equilibrium at
    // t = 0 needs the supports where the drawing has them).
    internal::SetSupportTargets(model, 0.0, start, &start);
    internal::ApplySupportTargets(model, &start);
    start.drawn_curvature = internal::DrawnCurvature(model, start);
  }
  const bool ramp_loads = options.ramp_loads || drawn_rest;
  StaticsSummary sum;
  int total_iterations = 0;
  if (try_direct) {
    RodState direct = start;
    internal::SetSupportTargets(model, 1.0, start, &direct);
    direct.load_factor = 1.0;
    direct.natural_factor = 1.0;
    sum = SolveStaticsDirect(model, &direct, options);
    total_iterations = sum.iterations;
    if (sum.converged()) {
      *state = direct;
      sum.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      return sum;
    }
  }
  // Continuation from the start state's own poses (and, if asked, from zero load).
  RodState cur = start;
  std::vector<double> fold_at;
  double pseudo_transient_from = -1.0;  // t where the gradient flow took over, if it did
  double t = 0.0, dt = kFirstContinuationStep;
  int steps = 0;
  bool at_start = true;
  while (true) {
    if (steps >= options.max_continuation_steps || dt < kMinContinuationStep) {
      // The path folds back here (or winds on): from the last state on it, the gradient flow of
      // the full problem goes downhill to an equilibrium past the fold. A caller that allows no
      // continuation (a warm re-solve on a budget) gets none of this either.
      if (options.max_continuation_steps == 0) {
        sum.termination = TerminationType::kNoConvergence;
        sum.message = "continuation stalled at t=" + std::to_string(t);
        break;
      }
      RodState flow = cur;
      internal::SetSupportTargets(model, 1.0, start, &flow);
      flow.load_factor = 1.0;
      flow.natural_factor = 1.0;
      flow.drawn_factor = 0.0;
      StaticsSummary step = SolvePseudoTransient(model, &flow, options);
      total_iterations += step.iterations;
      if (step.converged()) {
        sum = step;
        flow.drawn_curvature.clear();
        *state = flow;
        pseudo_transient_from = t;
        break;
      }
      sum.termination = TerminationType::kNoConvergence;
      sum.message = "continuation stalled at t=" + std::to_string(t) +
                    " (and pseudo-transient continuation from there: " + step.message + ")";
      break;
    }
    const double t_next = at_start ? 0.0 : std::min(1.0, t + dt);
    RodState trial = cur;
    internal::SetSupportTargets(model, t_next, start, &trial);
    trial.load_factor = ramp_loads ? t_next : 1.0;
    trial.natural_factor = ramp_loads ? t_next : 1.0;
    trial.drawn_factor = drawn_rest ? 1.0 - t_next : 0.0;
    // A step already cut this small sits at a fold of the path (a stretch snapping through, a
    // buckle flipping): closer steps fail the same way, but Newton given room crosses to the
    // state beyond. A 20-segment harness 3 % longer than drawn: 19 of 20 segments failed.
    StaticsOptions step_options = options;
    if (dt < kSnapStep) step_options.max_iterations = kSnapIterationFactor * options.max_iterations;
    StaticsSummary step = SolveStaticsDirect(model, &trial, step_options);
    total_iterations += step.iterations;
    ++steps;
    ReportProgress(options.progress, t_next, "continuation");
    if (step.converged()) {
      // A step that converged only once cut below kSnapStep (with the room to snap) crossed a
      // fold of the path: the state beyond it is on another branch than the drawing's.
      if (!at_start && dt < kSnapStep) fold_at.push_back(t_next);
      cur = trial;
      t = t_next;
      at_start = false;
      if (t >= 1.0) {
        sum = step;
        cur.drawn_curvature.clear();
        cur.drawn_factor = 0.0;
        *state = cur;
        break;
      }
      if (step.iterations <= kEasyStepIterations)
        dt = std::min(kMaxContinuationStep, dt * kContinuationStepGrowth);
    } else {
      if (at_start) {
        sum = step;
        sum.message = "could not relax the initial shape: " + step.message;
        break;
      }
      dt *= 0.5;
    }
  }
  sum.continuation_steps = steps;
  sum.iterations = total_iterations;
  sum.folds_passed = static_cast<int>(fold_at.size()) + (pseudo_transient_from >= 0 ? 1 : 0);
  if (sum.converged() && (drawn_rest || !fold_at.empty() || pseudo_transient_from >= 0)) {
    std::ostringstream os;
    os.precision(3);
    if (drawn_rest) os << "relaxed from the drawn shape as rest shape";
    for (double f : fold_at) os << (os.tellp() > 0 ? "; " : "") << "passed a fold at t=" << f;
    if (pseudo_transient_from >= 0)
      os << (os.tellp() > 0 ? "; " : "") << "continuation stalled at t=" << pseudo_transient_from
         << ", pseudo-transient continuation reached the equilibrium";
    sum.message = os.str();
  }
  sum.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return sum;
}

}  // namespace cablefit
