// Richardson extrapolation over a sequence of uniformly refined discretisations, and the error
// estimate of the extrapolated centreline. Shared by every simulation (a single rod, a rod
// network): each adds the node centrelines of its levels, branch by branch.
//
// The discrete centreline converges at second order, P_h = u + C h^2 + O(h^3), so
// R = P_h + (P_h - P_2h) / 3 removes the h^2 term (Richardson 1911; Hairer, Norsett & Wanner,
// "Solving ODEs I", sec. II.9). R is formed at the finest level's nodes: the correction, known at
// the coarser level's nodes, is interpolated to the nodes in between (it is O(h^2) and smooth,
// so that costs nothing), which keeps the node spacing of what callers sample at the finest.
//
// The error estimate bounds two parts separately:
//  - at the nodes, from successive extrapolations R_l, R_{l-1}: |R_l - R_{l-1}| / 3. The
//    extrapolated values do not converge at the fourth order an even expansion would give
//    (supports, point loads and clamp frames sit at nodes and add odd-order terms; measured
//    orders on the public sample cases are 2.6 to 3.5 at the default accuracy), so only the
//    second order that the scheme guarantees is assumed: err(R_l) <= |R_l - R_{l-1}| / (2^2 - 1).
//  - between the nodes, where callers read the curve by cubic interpolation (SampleCenterline):
//    the interpolation misses the finest level's odd nodes by some d when built from its even
//    nodes (twice the spacing); at the finest spacing it misses by at most d / 4 (fourth order
//    where the curve is smooth, but second order next to a jump in curvature, e.g. where a
//    natural curvature starts without a ramp).
// With only two levels there is one extrapolation and no second to compare it with: the
// estimate is then the error of the finer level itself, |P_h - P_2h| / 3 (a bound for R where
// it converges faster than P_h), plus the interpolation part.
#pragma once

#include <limits>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// The estimated max position error of an extrapolated centreline, in its two parts [m].
struct RichardsonError {
  double at_nodes = std::numeric_limits<double>::infinity();
  double between_nodes = std::numeric_limits<double>::infinity();
  double total() const { return at_nodes + between_nodes; }
};

class RichardsonLevels {
 public:
  /// Adds the node centrelines (one per branch, s [m] and 3 x n positions [m]) of the next
  /// level. Each of its elements is half of one of the previous level's: node k of a branch at
  /// the previous level is node 2k here.
  void Add(std::vector<Polyline> branches);
  void Clear() { levels_.clear(); }
  int levels() const { return static_cast<int>(levels_.size()); }
  /// Node centrelines of one level, branch by branch.
  const std::vector<Polyline>& Level(int level) const { return levels_[level]; }

  /// The extrapolated centrelines (one per branch) at the nodes of `level` (>= 1), from it
  /// and the level before; the level itself where a branch's levels do not nest.
  std::vector<Polyline> Extrapolated(int level) const;
  /// The same from the last two levels (the last level itself when there is only one).
  std::vector<Polyline> Extrapolated() const;

  /// Estimated error of Extrapolated() (infinite with fewer than two levels).
  RichardsonError EstimatedError() const;

 private:
  std::vector<std::vector<Polyline>> levels_;
};

/// Richardson extrapolation of a value computed at two levels (fine has half the elements'
/// length): removes the h^2 term.
template <class T>
T ExtrapolateRichardson(const T& fine, const T& coarse) {
  return (4.0 * fine - coarse) / 3.0;
}

}  // namespace cablefit
