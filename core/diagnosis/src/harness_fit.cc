#include "harness_fit.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "cablefit/core/base/cancellation.h"
#include "curve_projection.h"

namespace cablefit::internal {

std::vector<Eigen::Matrix3Xd> PointOffsets(const std::vector<BranchPoints>& points,
                                           const std::vector<Polyline>& shapes) {
  std::vector<Eigen::Matrix3Xd> out;
  for (size_t b = 0; b < points.size(); ++b) {
    const BranchPoints& p = points[b];
    if (p.points.cols() == 0) {
      out.emplace_back(3, 0);
      continue;
    }
    const Polyline& c = shapes[b];
    // The whole branch is searched: a junction or clip that moved shifts every arc length.
    const double length = c.s[c.size() - 1] - c.s[0];
    out.push_back(ProjectOntoCurve(c, p.points, p.s, length).offset);
  }
  return out;
}

HarnessResidual::HarnessResidual(const NetworkSpec& nominal, const std::vector<BranchPoints>& points,
                                 double element_length)
    : nominal_(&nominal), points_(&points) {
  options_.element_length = element_length;
  for (const BranchPoints& p : points) size_ += 3 * static_cast<int>(p.points.cols());
}

Eigen::VectorXd HarnessResidual::Offsets(const std::vector<Polyline>& shapes) const {
  const std::vector<Eigen::Matrix3Xd> offsets = PointOffsets(*points_, shapes);
  Eigen::VectorXd r(size_);
  int at = 0;
  for (size_t b = 0; b < points_->size(); ++b) {
    const BranchPoints& p = (*points_)[b];
    for (Eigen::Index i = 0; i < p.points.cols(); ++i, at += 3) r.segment<3>(at) = p.weight[i] * offsets[b].col(i);
  }
  return r;
}

bool HarnessResidual::Evaluate(const HarnessEffectModel* model, const Eigen::VectorXd& x,
                               Eigen::VectorXd* r, std::vector<Polyline>* shapes) {
  CheckCancelled();
  NetworkSpec spec = *nominal_;
  if (model) model->change(x, &spec);
  NetworkOptions opt = options_;
  if (last_.converged() && last_.branches.size() == spec.branches.size()) {
    opt.initial_routes = last_.branches;
    opt.initial_normals = last_.element_normals;
  }
  ++solves_;
  NetworkSolution sol;
  try {
    sol = SolveNetwork(spec, opt);
    if (!sol.converged() && !opt.initial_routes.empty()) {
      // From the drawing, as the nominal was solved: a warm start can sit on another branch.
      opt.initial_routes.clear();
      opt.initial_normals.clear();
      ++solves_;
      sol = SolveNetwork(spec, opt);
    }
  } catch (const InvalidInput&) {
    return false;  // the change made an invalid harness (a clip pushed off its branch)
  }
  if (!sol.converged()) return false;
  *r = Offsets(sol.branches);
  if (!r->allFinite()) return false;
  if (shapes) *shapes = sol.branches;
  last_ = std::move(sol);
  return true;
}

HarnessFit FitHarnessModel(const HarnessEffectModel& model, const Eigen::VectorXd& start,
                           const NetworkSpec& nominal, const std::vector<BranchPoints>& points,
                           double element_length, int max_iterations) {
  HarnessResidual residual(nominal, points, element_length);
  LmOptions lm;
  lm.max_iterations = max_iterations;
  lm.relative_step = 1e-3;
  lm.max_broyden_updates = 2;
  const LmResult res = MinimiseLeastSquares(
      [&](const Eigen::VectorXd& x, Eigen::VectorXd* r) { return residual.Evaluate(&model, x, r); },
      start, model.scale, lm);
  HarnessFit out;
  out.ok = res.ok;
  out.x = res.x;
  if (res.ok) {
    out.ok = residual.Evaluate(&model, res.x, &out.residual);
    out.cost = out.ok ? 0.5 * out.residual.squaredNorm() : res.cost;
  }
  out.solves = residual.solves();
  return out;
}

HarnessScreen ScreenHarnessModel(const HarnessEffectModel& model, const Eigen::VectorXd& nominal_residual,
                                 const NetworkSpec& nominal, const std::vector<BranchPoints>& points,
                                 double element_length) {
  HarnessScreen out;
  out.start = model.x0;
  out.predicted_cost = 0.5 * nominal_residual.squaredNorm();
  HarnessResidual residual(nominal, points, element_length);
  const int na = static_cast<int>(model.amplitudes.size());
  Eigen::MatrixXd jac(nominal_residual.size(), na);
  // Steps of a tenth of each amplitude's typical size: the effect's own scale, not round-off.
  for (int k = 0; k < na; ++k) {
    const int i = model.amplitudes[static_cast<size_t>(k)];
    Eigen::VectorXd x = model.x0;
    const double h = 0.1 * model.scale[i];
    x[i] += h;
    Eigen::VectorXd r;
    if (!residual.Evaluate(&model, x, &r)) {
      out.solves = residual.solves();
      return out;
    }
    jac.col(k) = (r - nominal_residual) / h;
  }
  out.solves = residual.solves();
  const Eigen::VectorXd dx = jac.colPivHouseholderQr().solve(-nominal_residual);
  if (!dx.allFinite()) return out;
  out.predicted_cost = 0.5 * (nominal_residual + jac * dx).squaredNorm();
  for (int k = 0; k < na; ++k) {
    const int i = model.amplitudes[static_cast<size_t>(k)];
    // A linearised step is trusted up to a few typical sizes of the effect.
    out.start[i] += std::clamp(dx[k], -5.0 * model.scale[i], 5.0 * model.scale[i]);
  }
  return out;
}

}  // namespace cablefit::internal
