// A KBL segment's centre curve: control points and a degree, no knot vector. Read as an
// unclamped B-spline with uniform knots t_i = i, i = 0..n+p (n control points, degree p),
// evaluated on its valid interval [t_p, t_n] = [p, n]: the VW samples then start and
// end on their nodes and are as long as their Virtual_length (a Bezier reading of the same
// points starts hundreds of metres away). De Boor's algorithm: Piegl & Tiller, The NURBS Book,
// 2nd ed., algorithm A2.1 (span) and eq. 2.5 / A3.1 (evaluation).
#pragma once

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// The point at parameter t in [degree, n_points] of the uniform unclamped B-spline through
/// `control` (3 x n_points [any length unit]). Requires n_points > degree >= 1.
Vec3 EvaluateUniformBSpline(const Eigen::Matrix3Xd& control, int degree, double t);

/// The curve sampled at `samples_per_span` points per knot span (endpoints included), s by
/// chords from 0, in the control points' unit. Throws InvalidInput when degree < 1 or there are
/// not more control points than the degree.
Polyline SampleUniformBSpline(const Eigen::Matrix3Xd& control, int degree, int samples_per_span);

}  // namespace cablefit
