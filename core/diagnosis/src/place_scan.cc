#include "place_scan.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

// Marquardt's damping of the step, relative to each column's own weight: enough to keep a
// column that the others nearly repeat from taking a huge step, too little to shorten the others.
constexpr double kDamping = 1e-3;

// The added effect's response is measured with a step of its typical size (scale): a point
// force of a few percent of the cable's weight is well inside the linear range, and far above
// the solver's tolerance, which a difference step of 1e-4 scales is not.
constexpr double kResponseStep = 1.0;

}  // namespace

LinearisedStep DampedGaussNewton(const Eigen::VectorXd& residual, const Eigen::MatrixXd& columns) {
  const Eigen::MatrixXd n = columns.transpose() * columns;
  Eigen::MatrixXd damped = n;
  const double floor = 1e-12 * std::max(n.trace(), 1e-300);
  for (Eigen::Index i = 0; i < n.rows(); ++i) damped(i, i) += kDamping * n(i, i) + floor;
  LinearisedStep out;
  out.step = damped.ldlt().solve(-columns.transpose() * residual);
  out.cost = 0.5 * (residual + columns * out.step).squaredNorm();
  return out;
}

std::vector<int> BestSeparatedPlaces(const std::vector<double>& cost,
                                     const std::vector<double>& where, double separation,
                                     int count) {
  const int n = static_cast<int>(cost.size());
  std::vector<int> order;
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(cost[static_cast<size_t>(i)])) continue;
    // A local least among its neighbours along the cable (the places are in order).
    const bool below_left =
        i == 0 || !(cost[static_cast<size_t>(i - 1)] < cost[static_cast<size_t>(i)]);
    const bool below_right =
        i + 1 == n || !(cost[static_cast<size_t>(i + 1)] < cost[static_cast<size_t>(i)]);
    if (below_left && below_right) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return cost[static_cast<size_t>(a)] < cost[static_cast<size_t>(b)];
  });
  std::vector<int> taken;
  for (int i : order) {
    if (static_cast<int>(taken.size()) >= count) break;
    bool near = false;
    for (int t : taken)
      near = near ||
             std::abs(where[static_cast<size_t>(i)] - where[static_cast<size_t>(t)]) < separation;
    if (!near) taken.push_back(i);
  }
  return taken;
}

std::vector<Eigen::VectorXd> ScanPlaces(const FitContext& ctx, const EffectModel& pair,
                                        const std::vector<EffectModel>& singles, int fitted,
                                        const Eigen::VectorXd& fitted_x, const FitPoint& point,
                                        int count, const std::vector<PlaceExclusion>& exclusions,
                                        int* solves) {
  CABLEFIT_CHECK(pair.is_combination() && (fitted == 0 || fitted == 1),
                 "a pair and one of its parts");
  const int placed = 1 - fitted;
  const EffectModel& fm = singles[static_cast<size_t>(pair.parts[static_cast<size_t>(fitted)])];
  const EffectModel& pm = singles[static_cast<size_t>(pair.parts[static_cast<size_t>(placed)])];
  const int f_off = pair.part_offsets[static_cast<size_t>(fitted)];
  const int p_off = pair.part_offsets[static_cast<size_t>(placed)];
  const Eigen::Index nf = fm.scale.size();
  const size_t na = pm.amplitudes.size();
  if (!point.ok || pm.scan_places.empty() || na == 0 || point.jacobian.cols() != nf) return {};
  // The fitted part's columns, in units of its scales: the same at every place (the added
  // effect is at zero strength).
  Eigen::MatrixXd columns(point.offsets.size(), nf + static_cast<Eigen::Index>(na));
  columns.leftCols(nf) = point.jacobian * fm.scale.asDiagonal();
  const size_t places = pm.scan_places.size();
  std::vector<double> cost(places, INFINITY), where(places, 0.0);
  std::vector<Eigen::VectorXd> start(places);
  for (size_t k = 0; k < places; ++k) {
    const Eigen::VectorXd& place = pm.scan_places[k];
    where[k] = place[0];
    bool excluded = false;
    for (const PlaceExclusion& e : exclusions)
      excluded = excluded || std::abs(place[0] - e.centre) < e.radius;
    if (excluded) continue;
    Eigen::VectorXd x(pair.scale.size());
    x.segment(f_off, nf) = fitted_x;
    x.segment(p_off, place.size()) = place;
    bool ok = true;
    for (size_t a = 0; a < na && ok; ++a) {
      const int i = pm.amplitudes[a];
      const double h = kResponseStep * pm.scale[i];
      Eigen::VectorXd xa = x;
      xa[p_off + i] += h;
      RodSimulator sim = point.sim;  // warm at the fit: the added force is a small change
      Eigen::VectorXd r;
      ++*solves;
      ok = FitOffsets(ctx, &sim, pair.apply(xa), &r) && r.size() == point.offsets.size();
      if (ok)
        columns.col(nf + static_cast<Eigen::Index>(a)) = (r - point.offsets) * (pm.scale[i] / h);
    }
    if (!ok) continue;
    const LinearisedStep step = DampedGaussNewton(point.offsets, columns);
    cost[k] = step.cost;
    x.segment(f_off, nf) += step.step.head(nf).cwiseProduct(fm.scale);
    for (size_t a = 0; a < na; ++a) {
      const int i = pm.amplitudes[a];
      x[p_off + i] = step.step[nf + static_cast<Eigen::Index>(a)] * pm.scale[i];
    }
    start[k] = std::move(x);
  }
  // Places apart by a tenth of the cable are different basins (residual_bends' separation).
  std::vector<Eigen::VectorXd> out;
  for (int k : BestSeparatedPlaces(cost, where, 0.1 * ctx.length, count))
    out.push_back(start[static_cast<size_t>(k)]);
  return out;
}

}  // namespace cablefit
