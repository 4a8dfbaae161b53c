// A round tube built directly as one B-spline surface: the circle carried along a B-spline
// centreline by a rotation-minimising frame, capped by two planar discs. No general sweep: the
// surface's poles follow from the centreline's own poles (BRepOffsetAPI_MakePipeShell
// approximates the same pipe by fitting a surface through many sampled sections, which took
// ~50 ms a cable and made the STEP files large).
#pragma once

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Shape.hxx>

#include <optional>

namespace cablefit {

/// A solid tube of `radius` around `centre` (a non-rational, non-periodic B-spline; same unit
/// as `radius`): the lateral surface S(u, v) = C(u) + r (cos v N(u) + sin v B(u)) is the tensor
/// product of C's B-spline basis (its knots refined where the frame needs it) with the exact
/// rational quadratic circle, N and B the rotation-minimising frame interpolated in that basis
/// until every section is a circle of `radius` square to the centreline within `tolerance`.
/// Capped by planar discs at both ends. nullopt when the centreline has a zero tangent, the
/// frame cannot be interpolated within `tolerance` in a few refinements, or the faces cannot be
/// built: the caller then sweeps the tube the general way.
std::optional<TopoDS_Shape> MakePipeSurfaceTube(const Handle(Geom_BSplineCurve)& centre,
                                                double radius, double tolerance);

}  // namespace cablefit
