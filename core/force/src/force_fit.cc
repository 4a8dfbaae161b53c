// Candidate fits for force-curve diagnosis (see force_fit.h, force_diagnosis.h for sources).
#include "cablefit/core/force/force_fit.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "cablefit/core/force/force_hysteresis.h"
#include "cablefit/core/force/force_nnls.h"

namespace cablefit {

int ComplexityRank(ForceEffect effect) {
  switch (effect) {
    case ForceEffect::kNone:
      return 0;
    case ForceEffect::kStiffness:
      return 1;
    case ForceEffect::kHysteresis:
      return 2;
  }
  return 0;
}

namespace {

// Slip displacements of the Iwan grid [x unit], log-spaced over the recorded range.
std::vector<double> SlipGrid(const Eigen::VectorXd& x, const ForceDiagnosisOptions& options) {
  const double range = x.maxCoeff() - x.minCoeff();
  const int m = options.hysteresis_grid_size;
  std::vector<double> grid;
  for (int j = 0; j < m; ++j) {
    const double t = m == 1 ? 1.0 : static_cast<double>(j) / (m - 1);
    grid.push_back(range * options.min_slip_fraction *
                   std::pow(options.max_slip_fraction / options.min_slip_fraction, t));
  }
  return grid;
}

}  // namespace

ForceCandidate FitForceCandidate(ForceEffect effect, const ForceFitProblem& problem,
                                 const ForceDiagnosisOptions& options) {
  const Eigen::Index n = problem.y.size();
  const double dn = static_cast<double>(n);
  const double sigma_offset = options.offset_prior_fraction * problem.peak;  // [unit]
  const double rss_floor = dn * std::pow(options.noise_floor_fraction * problem.peak, 2);

  // Columns: [ratio] [offset] [slip force of each grid element]; `none` fixes ratio = 1.
  std::vector<double> grid;
  if (effect == ForceEffect::kHysteresis) grid = SlipGrid(problem.x, options);
  const bool has_ratio = effect != ForceEffect::kNone;
  const Eigen::Index cols = (has_ratio ? 1 : 0) + 1 + static_cast<Eigen::Index>(grid.size());
  const Eigen::Index offset_col = has_ratio ? 1 : 0;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + 1, cols);  // last row: offset prior
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n + 1);
  std::vector<bool> nonnegative(static_cast<size_t>(cols), true);
  nonnegative[static_cast<size_t>(offset_col)] = false;
  b.head(n) = has_ratio ? problem.y : Eigen::VectorXd(problem.y - problem.nominal);
  if (has_ratio) A.col(0).head(n) = problem.nominal;
  A.col(offset_col).head(n).setOnes();
  for (size_t j = 0; j < grid.size(); ++j) {
    A.col(offset_col + 1 + static_cast<Eigen::Index>(j)).head(n) =
        UnitJenkinsResponse(grid[j], problem.x, 0.0);
  }

  // Profiled noise: the prior row weight is sigma / sigma_offset with sigma^2 = RSS / n, which
  // is the stationarity condition of n ln(RSS) + c^2 / sigma_offset^2. Start from a weak prior.
  double sigma = 1e-3 * sigma_offset;
  Eigen::VectorXd theta;
  double rss = 0.0;
  for (int iter = 0; iter < 30; ++iter) {
    A(n, offset_col) = sigma / sigma_offset;
    theta = SolvePartlyNonNegativeLeastSquares(A, b, nonnegative);
    rss = std::max((A.topRows(n) * theta - b.head(n)).squaredNorm(), rss_floor);
    const double next = std::sqrt(rss / dn);
    const bool settled = std::abs(next - sigma) <= 1e-6 * next;
    sigma = next;
    if (settled) break;
  }

  ForceCandidate out;
  out.effect = effect;
  out.rss = rss;
  const double ratio = has_ratio ? theta[0] : 1.0;
  const double offset = theta[offset_col];
  out.fitted = ratio * problem.nominal + Eigen::VectorXd::Constant(n, offset);
  int active = 0;
  double total_slip = 0.0;
  for (size_t j = 0; j < grid.size(); ++j) {
    const double f = theta[offset_col + 1 + static_cast<Eigen::Index>(j)];
    if (f <= 0.0) continue;
    ++active;
    total_slip += f;
    out.elements.push_back({f / grid[j], f});
  }
  if (!out.elements.empty()) out.fitted += IwanResponse(out.elements, problem.x, 0.0);

  out.parameter_count = 1 + (has_ratio ? 1 : 0) + 2 * active;  // each element: k and f
  out.criterion = dn * std::log(rss / dn) + offset * offset / (sigma_offset * sigma_offset) +
                  out.parameter_count * std::log(dn) +
                  options.complexity_margin * ComplexityRank(effect);
  out.parameters["sensor_offset"] = offset;
  if (has_ratio) out.parameters["ratio"] = ratio;
  if (effect == ForceEffect::kHysteresis) {
    out.parameters["loop_area"] = FirstCycleLoopArea(problem.x, out.fitted);
    out.parameters["recorded_loop_area"] = FirstCycleLoopArea(problem.x, problem.y);
    out.parameters["slip_force_total"] = total_slip;
    out.parameters["element_count"] = active;
    for (size_t i = 0; i < out.elements.size(); ++i) {
      out.parameters["k_" + std::to_string(i + 1)] = out.elements[i].stiffness;
      out.parameters["f_slip_" + std::to_string(i + 1)] = out.elements[i].slip_force;
    }
  }
  return out;
}

}  // namespace cablefit
