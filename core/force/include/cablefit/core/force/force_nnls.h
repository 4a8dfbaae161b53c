// Linear least squares with non-negativity on chosen unknowns: the active-set method of
// Lawson & Hanson, "Solving Least Squares Problems" (1974), ch. 23 (algorithm NNLS), with the
// unconstrained unknowns eliminated first by projecting onto the complement of their columns.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace cablefit {

/// Minimises |A x - b|^2 subject to x_j >= 0 for every j with nonnegative[j] == true.
/// A: m x n, b: m, nonnegative: n flags. Returns x (n). Rank-deficient free columns get the
/// minimum-norm solution.
Eigen::VectorXd SolvePartlyNonNegativeLeastSquares(const Eigen::MatrixXd& A,
                                                   const Eigen::VectorXd& b,
                                                   const std::vector<bool>& nonnegative);

}  // namespace cablefit
