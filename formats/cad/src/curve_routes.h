// Cable routes drawn as curves: the free edges of a shape (not bounding any face), chained end to
// end into routes and split at branch points.
#pragma once

#include <TopoDS_Shape.hxx>
#include <vector>

#include <Eigen/Core>

namespace cablefit {

struct CurveRoute {
  Eigen::Matrix3Xd points;       // 3 x n [OCCT unit], sampled along the route
  double max_chord_error = 0.0;  // [OCCT unit] largest curve-to-chord distance at mid-samples
};

/// Builds a graph whose nodes are edge end points (merged within `tolerance`) and whose links
/// are the free edges of `shape`; every maximal path between nodes of degree != 2 is a route
/// (a cycle with no such node is one closed route). Each route is sampled at about `spacing`
/// and at least 16 points.
std::vector<CurveRoute> ExtractCurveRoutes(const TopoDS_Shape& shape, double spacing,
                                           double tolerance);

/// A closed curve lying in one plane (points 3 x n, any length unit): the profile sketch a
/// sweep was made from (FreeCAD keeps them beside the swept cable), never a cable route, which
/// would need two ends to hold.
bool IsClosedPlanar(const Eigen::Matrix3Xd& points);

}  // namespace cablefit
