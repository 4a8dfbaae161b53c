// Lawson & Hanson (1974) ch. 23 NNLS with free unknowns projected out, see force_nnls.h.
#include "cablefit/core/force/force_nnls.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

Eigen::VectorXd SolveOnSet(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                           const std::vector<int>& set) {
  Eigen::MatrixXd sub(A.rows(), static_cast<Eigen::Index>(set.size()));
  for (size_t i = 0; i < set.size(); ++i) sub.col(static_cast<Eigen::Index>(i)) = A.col(set[i]);
  return sub.colPivHouseholderQr().solve(b);
}

// Classic NNLS on all unknowns. Columns are assumed normalised (or zero).
Eigen::VectorXd Nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::Index n = A.cols();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(static_cast<size_t>(n), false);
  const double tol = 1e3 * std::numeric_limits<double>::epsilon() * std::max(1.0, b.norm()) *
                     std::max<double>(1.0, static_cast<double>(n));
  const int max_outer = 3 * static_cast<int>(n) + 10;
  for (int outer = 0; outer < max_outer; ++outer) {
    const Eigen::VectorXd w = A.transpose() * (b - A * x);
    Eigen::Index best = -1;
    double best_w = tol;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!passive[static_cast<size_t>(j)] && w[j] > best_w && A.col(j).squaredNorm() > 0.0) {
        best_w = w[j];
        best = j;
      }
    }
    if (best < 0) break;
    passive[static_cast<size_t>(best)] = true;
    for (int inner = 0; inner < max_outer; ++inner) {
      std::vector<int> set;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<size_t>(j)]) set.push_back(static_cast<int>(j));
      }
      if (set.empty()) {  // every passive unknown was driven back to zero
        x.setZero();
        break;
      }
      const Eigen::VectorXd s_set = SolveOnSet(A, b, set);
      bool feasible = true;
      for (Eigen::Index i = 0; i < s_set.size(); ++i) feasible = feasible && s_set[i] > 0.0;
      Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
      for (size_t i = 0; i < set.size(); ++i) s[set[i]] = s_set[static_cast<Eigen::Index>(i)];
      if (feasible) {
        x = s;
        break;
      }
      // Step from x towards s until the first passive unknown hits zero.
      double alpha = 1.0;
      for (int j : set) {
        if (s[j] <= 0.0) alpha = std::min(alpha, x[j] / (x[j] - s[j]));
      }
      x += alpha * (s - x);
      for (int j : set) {
        if (x[j] <= tol * 1e-3) {
          x[j] = 0.0;
          passive[static_cast<size_t>(j)] = false;
        }
      }
    }
  }
  return x;
}

}  // namespace

Eigen::VectorXd SolvePartlyNonNegativeLeastSquares(const Eigen::MatrixXd& A,
                                                   const Eigen::VectorXd& b,
                                                   const std::vector<bool>& nonnegative) {
  CABLEFIT_REQUIRE(A.rows() == b.size(), "least squares: A and b row counts differ");
  CABLEFIT_REQUIRE(static_cast<size_t>(A.cols()) == nonnegative.size(),
                   "least squares: one flag per unknown");
  // Normalise columns so the NNLS tolerances are scale-free; unscale at the end.
  Eigen::VectorXd scale(A.cols());
  Eigen::MatrixXd An = A;
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    const double norm = A.col(j).norm();
    scale[j] = norm > 0.0 ? norm : 1.0;
    An.col(j) /= scale[j];
  }
  std::vector<int> free_cols;
  std::vector<int> nn_cols;
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    (nonnegative[static_cast<size_t>(j)] ? nn_cols : free_cols).push_back(static_cast<int>(j));
  }
  Eigen::MatrixXd Af(A.rows(), static_cast<Eigen::Index>(free_cols.size()));
  for (size_t i = 0; i < free_cols.size(); ++i)
    Af.col(static_cast<Eigen::Index>(i)) = An.col(free_cols[i]);
  Eigen::MatrixXd Ac(A.rows(), static_cast<Eigen::Index>(nn_cols.size()));
  for (size_t i = 0; i < nn_cols.size(); ++i)
    Ac.col(static_cast<Eigen::Index>(i)) = An.col(nn_cols[i]);

  Eigen::VectorXd xc = Eigen::VectorXd::Zero(Ac.cols());
  Eigen::VectorXd xf = Eigen::VectorXd::Zero(Af.cols());
  if (Af.cols() > 0) {
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(Af);
    if (Ac.cols() > 0) {
      // Residual maker M = I - Af Af^+ removes the free unknowns exactly.
      const Eigen::MatrixXd Mc = Ac - Af * cod.solve(Ac);
      const Eigen::VectorXd Mb = b - Af * cod.solve(b);
      xc = Nnls(Mc, Mb);
    }
    xf = cod.solve(b - Ac * xc);
  } else if (Ac.cols() > 0) {
    xc = Nnls(Ac, b);
  }
  Eigen::VectorXd x(A.cols());
  for (size_t i = 0; i < free_cols.size(); ++i) x[free_cols[i]] = xf[static_cast<Eigen::Index>(i)];
  for (size_t i = 0; i < nn_cols.size(); ++i) x[nn_cols[i]] = xc[static_cast<Eigen::Index>(i)];
  return x.cwiseQuotient(scale);
}

}  // namespace cablefit
