// Where a placed effect (a contact) belongs when it joins another effect's fit, to first order.
// A fixed grid of places started at zero strength ranks its basins only after a few nonlinear
// iterations each, and the residual's bends (residual_bends.h) show a point force only where the
// other fit has not absorbed it (a twist preload or a curvature span takes up much of a contact's
// bend and leaves its remains elsewhere). The scan asks every place along the cable instead how
// much of the fit's residual the effect there removes, with the fitted effect refitted alongside
// it, both linearised: two forward solves per place (the response to each force component) on
// the coarse level, against the fit's Jacobian that the pair search has anyway. The best places
// start the joint fit at their linearised optimum.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "effect_fit.h"
#include "shape_effects.h"

namespace cablefit {

/// The Gauss-Newton step of the residual `residual` (m) over `columns` (m x k, the Jacobian in
/// units of each parameter's scale), lightly damped (a column the others nearly repeat stays
/// small), and the linearised cost 1/2 |residual + columns step|^2 it leaves.
struct LinearisedStep {
  Eigen::VectorXd step;  // k, in units of the scales
  double cost = 0.0;     // [m^2]
};
LinearisedStep DampedGaussNewton(const Eigen::VectorXd& residual, const Eigen::MatrixXd& columns);

/// The `count` places of least `cost`, each a local least at least `separation` from the ones
/// taken (`where`: each place's position along the cable); indices, best first.
std::vector<int> BestSeparatedPlaces(const std::vector<double>& cost,
                                     const std::vector<double>& where, double separation,
                                     int count);

/// Starts of `pair` with part `fitted` (0 or 1) at its single fit `fitted_x`, whose state on the
/// coarse level is `point`, and the other part (a placed effect with `scan_places`) at the
/// `count` places where it removes most of what the fit leaves, both at their linearised optimum.
/// Places nearer than `exclusions`' radius to its centre (both [m]: the same effect fitted
/// already, the place a fit has tried) are skipped. `solves` counts the forward solves.
struct PlaceExclusion {
  double centre = 0.0;
  double radius = 0.0;
};
std::vector<Eigen::VectorXd> ScanPlaces(const FitContext& ctx, const EffectModel& pair,
                                        const std::vector<EffectModel>& singles, int fitted,
                                        const Eigen::VectorXd& fitted_x, const FitPoint& point,
                                        int count, const std::vector<PlaceExclusion>& exclusions,
                                        int* solves);

}  // namespace cablefit
