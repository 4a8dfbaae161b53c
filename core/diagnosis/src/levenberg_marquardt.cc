#include "levenberg_marquardt.h"

#include <Eigen/Dense>
#include <cmath>

namespace cablefit {

LmResult MinimiseLeastSquares(const std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd*)>& residual,
                              const Eigen::VectorXd& x0, const Eigen::VectorXd& scale,
                              const LmOptions& options) {
  LmResult res;
  res.x = x0;
  Eigen::VectorXd r;
  ++res.evaluations;
  if (!residual(res.x, &r)) return res;
  res.ok = true;
  res.cost = 0.5 * r.squaredNorm();
  const int n = static_cast<int>(x0.size());
  if (n == 0) {
    res.converged = true;
    return res;
  }
  double mu = -1.0, nu = 2.0;
  for (int it = 0; it < options.max_iterations; ++it) {
    res.iterations = it + 1;
    Eigen::MatrixXd jac(r.size(), n);
    bool jac_ok = true;
    for (int k = 0; k < n; ++k) {
      Eigen::VectorXd xp = res.x;
      const double h = options.relative_step * scale[k];
      xp[k] += h;
      Eigen::VectorXd rp;
      ++res.evaluations;
      if (!residual(xp, &rp) || rp.size() != r.size()) {
        xp[k] = res.x[k] - h;
        ++res.evaluations;
        if (!residual(xp, &rp) || rp.size() != r.size()) {
          jac_ok = false;
          break;
        }
        jac.col(k) = (r - rp) / h;
      } else {
        jac.col(k) = (rp - r) / h;
      }
    }
    if (!jac_ok) break;
    // Work in scaled parameters so the damping treats every parameter alike.
    const Eigen::MatrixXd js = jac * scale.asDiagonal();
    const Eigen::MatrixXd a = js.transpose() * js;
    const Eigen::VectorXd g = js.transpose() * r;
    if (mu < 0) mu = 1e-3 * std::max(a.diagonal().maxCoeff(), 1e-300);
    bool improved = false;
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
        res.x = xn;
        r = rn;
        res.cost = cn;
        improved = true;
        if (decrease < options.cost_tolerance) {
          res.converged = true;
          return res;
        }
        break;
      }
      mu *= nu;
      nu *= 2.0;
    }
    if (!improved) {
      res.converged = true;
      break;
    }
  }
  return res;
}

}  // namespace cablefit
