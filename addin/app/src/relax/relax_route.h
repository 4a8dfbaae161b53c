// Geometry on a drawn cable route (a polyline parameterised by chord length): points, tangents
// and a twist-free frame at arc lengths, the arc length nearest a point, distances to the route.
// What `cablefit relax` needs to place supports at their drawn pose and to measure deviation.
#pragma once

#include "cablefit/core/base/box_tree.h"
#include "cablefit/core/base/geometry_types.h"

namespace cablefit::addin {

/// A drawn route with consecutive duplicate points removed and `s` = cumulative chord length
/// from 0. Throws InvalidInput when fewer than two distinct points remain.
Polyline CleanRoute(const Polyline& drawn);  // resampled uniformly, see .cc

/// The route with its corners rounded: positions averaged along the route with a Gaussian of
/// standard deviation `width` / 2 [m] (odd reflection at the ends, so the ends stay where they
/// are and a straight route stays straight). A corner becomes a bend of about `width` radius;
/// a smooth bend of radius R moves by about width^2 / (8 R). Re-parameterised by chords.
Polyline RoundedRoute(const Polyline& route, double width);

/// Point at arc length `s` [m] (linear between samples; clamped to the route). 3 [m].
Vec3 RoutePoint(const Polyline& route, double s);

/// Unit tangent at arc length `s`: derivative of a least-squares cubic in s through the nearest
/// samples (one-sided at the ends), so a finely sampled smooth curve gives its tangent to
/// O(h^3) rather than the O(h) of a chord.
Vec3 RouteTangent(const Polyline& route, double s);

/// Rotation-minimising (twist-free) normals at the route's samples, starting from `d1_start`
/// (projected onto the normal plane): the double-reflection method of Wang, Juettler, Zheng and
/// Liu, "Computation of rotation minimizing frames", ACM TOG 27(1), 2008, eq. (4)-(6).
/// Returns 3 x n unit vectors, each perpendicular to that sample's RouteTangent.
Eigen::Matrix3Xd TransportedNormals(const Polyline& route, const Vec3& d1_start);

/// The normal at arc length `s` from TransportedNormals (linear blend, re-orthogonalised).
Vec3 NormalAt(const Polyline& route, const Eigen::Matrix3Xd& normals, double s);

/// Arc length of the route point nearest `p`; `distance` (optional) receives that distance [m].
/// Measures every segment: for one query. Many points against one route: RouteProjector.
double NearestArcLength(const Polyline& route, const Vec3& p, double* distance = nullptr);

/// NearestArcLength for many points on one route: the route's segments in a BoxTree, so a
/// query measures only the segments whose box could hold a nearer point (a relaxed cable's
/// deviation on a finely sampled drawing: thousands of points against thousands of segments).
/// Same answers as NearestArcLength (ties to the first segment). `route` must outlive it.
class RouteProjector {
 public:
  explicit RouteProjector(const Polyline& route);
  double NearestArcLength(const Vec3& p, double* distance = nullptr) const;

 private:
  const Polyline& route_;
  BoxTree tree_;
};

}  // namespace cablefit::addin
