// Distance of observed points to a simulated centreline: each point is projected onto the
// nearest segment of a finely sampled curve, searching near its own arc-length estimate.
#pragma once

#include <Eigen/Core>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

struct CurveProjection {
  Eigen::Matrix3Xd offset;   // 3 x n [m] point minus its closest curve point
  Eigen::VectorXd s;         // n [m] arc length of the closest curve point
};

/// `curve` must be parameterised by arc length and fine (spacing well below the curvature
/// radius). `s_guess` (n) centres the search window of half-width `window` [m].
CurveProjection ProjectOntoCurve(const Polyline& curve, const Eigen::Matrix3Xd& points,
                                 const Eigen::VectorXd& s_guess, double window);

}  // namespace cablefit
