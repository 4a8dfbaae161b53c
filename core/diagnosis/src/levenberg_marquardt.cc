#include "levenberg_marquardt.h"

#include <Eigen/Dense>
#include <cmath>

namespace cablefit {
bool DifferenceJacobian(const ResidualFunction& residual, const Eigen::VectorXd& x,
                        const Eigen::VectorXd& r, const Eigen::VectorXd& scale,
                        double relative_step, const std::vector<bool>& skip, int* evaluations,
                        Eigen::MatrixXd* jac) {
  const int n = static_cast<int>(x.size());
  if (jac->rows() != r.size() || jac->cols() != n) jac->resize(r.size(), n);
  for (int k = 0; k < n; ++k) {
    if (!skip.empty() && skip[static_cast<size_t>(k)]) continue;
    Eigen::VectorXd xp = x;
    const double h = relative_step * scale[k];
    xp[k] += h;
    Eigen::VectorXd rp;
    ++*evaluations;
    if (!residual(xp, &rp) || rp.size() != r.size()) {
      xp[k] = x[k] - h;
      ++*evaluations;
      if (!residual(xp, &rp) || rp.size() != r.size()) return false;
      jac->col(k) = (r - rp) / h;
    } else {
      jac->col(k) = (rp - r) / h;
    }
  }
  return true;
}

LmResult MinimiseLeastSquares(const ResidualFunction& residual, const Eigen::VectorXd& x0,
                              const Eigen::VectorXd& scale, const LmOptions& options,
                              const LmStart* start) {
  LmResult res;
  res.x = x0;
  Eigen::VectorXd r;
  Eigen::MatrixXd jac;
  std::vector<bool> known;
  if (start) {
    r = start->residual;
    jac = start->jacobian;
    known = start->known_columns;
  } else {
    ++res.evaluations;
    if (!residual(res.x, &r)) return res;
  }
  res.ok = true;
  res.cost = 0.5 * r.squaredNorm();
  const int n = static_cast<int>(x0.size());
  if (n == 0) {
    res.converged = true;
    return res;
  }
  double mu = -1.0, nu = 2.0;
  // Between difference Jacobians the Jacobian is carried by Broyden's rank-one update (each
  // difference Jacobian costs one forward solve per parameter; an update costs none). A stop is
  // only believed on a fresh difference Jacobian.
  bool fresh = false;
  int updates = 0;
  for (int it = 0; it < options.max_iterations; ++it) {
    res.iterations = it + 1;
    if (!fresh && (it == 0 || updates >= options.max_broyden_updates)) {
      if (!DifferenceJacobian(residual, res.x, r, scale, options.relative_step,
                              it == 0 ? known : std::vector<bool>{}, &res.evaluations, &jac))
        break;
      fresh = true;
      updates = 0;
    }
    // Work in scaled parameters so the damping treats every parameter alike.
    const Eigen::MatrixXd js = jac * scale.asDiagonal();
    const Eigen::MatrixXd a = js.transpose() * js;
    const Eigen::VectorXd g = js.transpose() * r;
    if (mu < 0) mu = 1e-3 * std::max(a.diagonal().maxCoeff(), 1e-300);
    bool improved = false;
    bool stop = false;
    for (int tries = 0; tries < 12; ++tries) {
      Eigen::MatrixXd damped = a;
      damped.diagonal().array() += mu;
      const Eigen::VectorXd step = scale.asDiagonal() * Eigen::VectorXd(damped.ldlt().solve(-g));
      const Eigen::VectorXd xn = res.x + step;
      Eigen::VectorXd rn;
      ++res.evaluations;
      const bool ok = residual(xn, &rn) && rn.size() == r.size();
      const double cn = ok ? 0.5 * rn.squaredNorm() : INFINITY;
      const Eigen::VectorXd ss = step.cwiseQuotient(scale);
      const double predicted = -(ss.dot(g) + 0.5 * ss.dot(a * ss));
      if (ok && cn < res.cost) {
        const double rho = predicted > 0 ? (res.cost - cn) / predicted : 1.0;
        mu *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
        nu = 2.0;
        const double decrease = (res.cost - cn) / std::max(res.cost, 1e-300);
        if (options.max_broyden_updates > 0) {
          jac += (rn - r - jac * step) * step.transpose() / step.squaredNorm();
          ++updates;
        }
        res.x = xn;
        r = rn;
        res.cost = cn;
        improved = true;
        stop = decrease < options.cost_tolerance;
        break;
      }
      mu *= nu;
      nu *= 2.0;
    }
    if (improved && !stop) {
      fresh = false;
      continue;
    }
    if (fresh) {  // no damped step lowers the cost, or it stalled: on a true Jacobian, a minimum
      res.converged = true;
      break;
    }
    // On an updated Jacobian: try again with a difference Jacobian before stopping.
    updates = options.max_broyden_updates;
  }
  return res;
}

}  // namespace cablefit
