// Building cable geometry in OCCT: a B-spline through centreline points, and the tube swept by a
// circle along it. Shared by the writer and the sample tool.
#pragma once

#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

#include <Eigen/Core>

namespace cablefit {

/// A C2 B-spline edge approximating `points` (3 x n [OCCT unit], n >= 2) within `tolerance`
/// (GeomAPI_PointsToBSpline). Throws InvalidInput when the points cannot be approximated.
TopoDS_Edge MakeSplineEdge(const Eigen::Matrix3Xd& points, double tolerance);

/// A solid tube of `diameter` swept along `spine` by a circle normal to the spine's start
/// (BRepOffsetAPI_MakePipeShell: corrected Frenet frame, else the discrete trihedron), capped.
/// Throws InvalidInput when neither sweep gives a valid solid.
TopoDS_Shape MakeTubeSolid(const TopoDS_Wire& spine, double diameter);

}  // namespace cablefit
