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

/// A round tube's spine: the cubic B-spline of FitCubicSpline (core/base: least squares with
/// as few poles as hold `tolerance`, ~4x faster than MakeSplineEdge's OCCT fit; the tube's
/// surface is built on the spine's poles, so few poles make a small file); MakeSplineEdge's
/// fit for fewer than 4 points or should that fail. Throws InvalidInput as MakeSplineEdge.
TopoDS_Edge MakeTubeSpineEdge(const Eigen::Matrix3Xd& points, double tolerance);

/// A solid tube of `diameter` along `spine`, capped: for a spine of one B-spline edge the
/// pipe surface built directly (MakePipeSurfaceTube); else, or where that fails, swept by a
/// circle normal to the spine's start (BRepOffsetAPI_MakePipeShell: corrected Frenet frame,
/// else the discrete trihedron).
/// Throws InvalidInput when neither sweep gives a valid solid.
TopoDS_Shape MakeTubeSolid(const TopoDS_Wire& spine, double diameter);

}  // namespace cablefit
