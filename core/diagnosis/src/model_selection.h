// Model selection among the fitted effects by the Bayesian information criterion, and the test
// whether the best fit explains the recording at all.
//
// BIC = chi^2 + k ln(m) with m residual components, chi^2 = |offsets|^2 / sigma^2 and sigma^2
// the best fit's residual variance, floored by the recording's own noise (a fit cannot be
// better than the recording). Fewer effects are favoured by prior odds: every effect a model
// names pays `null_margin` on top of its BIC (the nominal none, a pair twice), and scores, order
// and choice all include it, so the chosen model is always the best-scored one. Models of one group (one effect at several clamps)
// compete for one candidate: the group's best BIC stands for it.
#pragma once

#include <cstddef>
#include <vector>

namespace cablefit::internal {

/// What the selection needs of one fit.
struct ModelFit {
  int group = 0;         // fits of one group (effect) give one candidate
  int parameters = 0;    // physical parameters counted by the criterion
  double cost = 0.0;     // 1/2 |offsets|^2 [m^2]
  bool ok = false;       // false: the model could not be fitted (not a candidate)
  /// How many effects the model names: 0 for the nominal, 2 for a pair. Each one pays the
  /// margin, so that a second effect must win its place as the first did.
  int effects = 1;
};

struct RankedModel {
  std::size_t fit = 0;     // index into the fits
  double bic = 0.0;        // [-]
  double criterion = 0.0;  // bic + the margin per effect (none for the null model)
  double score = 0.0;      // posterior weight in [0, 1]; 0 for a rejected fit
};

struct ModelRanking {
  double sigma2 = 0.0;               // [m^2] noise variance the BIC used
  std::vector<RankedModel> ranked;   // one per group, best score first
};

/// Ranks `fits` with `residuals` residual components (2 per point: an offset from a curve has
/// two free components) and the recording's `noise_sigma` [m]. A fit marked in `rejected` (may
/// be empty) still sets the noise and stands for its group, but weighs nothing and ranks after
/// the others. Empty `ranked` when no fit is ok.
ModelRanking RankModels(const std::vector<ModelFit>& fits, int residuals, double noise_sigma,
                        double null_margin, const std::vector<bool>& rejected = {});

/// Whether a fit explains the recording: its residual against `allowance` times the noise is
/// chi-square with `degrees_of_freedom` when the model is right.
struct AdequacyTest {
  double chi_square = 0.0;
  double limit = 0.0;  // 99.9 % quantile
  bool passed = false;
};
AdequacyTest TestAdequacy(double cost, int degrees_of_freedom, double noise_sigma,
                          double allowance);

/// Upper 99.9 % quantile of chi-square with `dof` degrees of freedom (Wilson-Hilferty; relative
/// error below 1e-3 for dof >= 100, 0.6 % at 10).
double ChiSquareQuantile999(double dof);

}  // namespace cablefit::internal
