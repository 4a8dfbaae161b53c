#include "model_selection.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace cablefit::internal {

ModelRanking RankModels(const std::vector<ModelFit>& fits, int residuals, double noise_sigma,
                        double null_margin, const std::vector<bool>& rejected) {
  ModelRanking out;
  double best_cost = INFINITY;
  for (const ModelFit& f : fits)
    if (f.ok) best_cost = std::min(best_cost, f.cost);
  if (!std::isfinite(best_cost)) return out;
  // The best model's residual variance (8: about the most parameters a model has, a pair of
  // curvature spans), floored by the recording's noise.
  out.sigma2 = std::max(2.0 * best_cost / std::max(1, residuals - 8), noise_sigma * noise_sigma);
  const double log_n = std::log(static_cast<double>(residuals));
  auto bic = [&](std::size_t i) {
    return 2.0 * fits[i].cost / out.sigma2 + fits[i].parameters * log_n;
  };
  std::map<int, std::size_t> best_of;
  for (std::size_t i = 0; i < fits.size(); ++i) {
    if (!fits[i].ok) continue;
    auto it = best_of.find(fits[i].group);
    if (it == best_of.end() || bic(i) < bic(it->second)) best_of[fits[i].group] = i;
  }
  auto is_rejected = [&](std::size_t i) { return i < rejected.size() && rejected[i]; };
  for (const auto& [group, i] : best_of) {
    RankedModel r;
    r.fit = i;
    r.bic = bic(i);
    r.criterion = r.bic + fits[i].effects * null_margin;
    out.ranked.push_back(r);
  }
  std::sort(out.ranked.begin(), out.ranked.end(), [](const RankedModel& a, const RankedModel& b) {
    return std::make_pair(a.criterion, a.fit) < std::make_pair(b.criterion, b.fit);
  });
  double best_held = INFINITY, sum = 0.0;
  for (const RankedModel& r : out.ranked)
    if (!is_rejected(r.fit)) best_held = std::min(best_held, r.criterion);
  for (RankedModel& r : out.ranked) {
    r.score = is_rejected(r.fit) ? 0.0 : std::exp(-0.5 * (r.criterion - best_held));
    sum += r.score;
  }
  for (RankedModel& r : out.ranked) r.score /= sum;
  std::stable_sort(out.ranked.begin(), out.ranked.end(),
                   [](const RankedModel& a, const RankedModel& b) { return a.score > b.score; });
  return out;
}

AdequacyTest TestAdequacy(double cost, int degrees_of_freedom, double noise_sigma,
                          double allowance) {
  AdequacyTest t;
  t.chi_square = 2.0 * cost / (noise_sigma * noise_sigma * allowance * allowance);
  t.limit = ChiSquareQuantile999(degrees_of_freedom);
  t.passed = t.chi_square <= t.limit;
  return t;
}

double ChiSquareQuantile999(double dof) {
  const double z = 3.0902, a = 2.0 / (9.0 * dof);
  return dof * std::pow(1.0 - a + z * std::sqrt(a), 3);
}

}  // namespace cablefit::internal
