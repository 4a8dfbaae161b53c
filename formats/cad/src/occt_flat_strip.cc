#include "occt_flat_strip.h"

#include <BRepAdaptor_CompCurve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <string>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

// As the round tube's (occt_tube.cc): quintic pieces within a thousandth of the thickness.
constexpr int kStripMaxDegree = 5;
constexpr int kStripMaxSegments = 2000;
constexpr double kStripRelativeTolerance = 1e-3;

// The profile around `origin` in the plane spanned by the wide axis `u` and `v` (both unit).
TopoDS_Wire Profile(const gp_Pnt& origin, const gp_Vec& u, const gp_Vec& v, const FlatProfile& p) {
  const auto at = [&](double a, double b) { return origin.Translated(a * u + b * v); };
  BRepBuilderAPI_MakeWire wire;
  const double t = 0.5 * p.thickness;
  if (p.rounded_edges) {
    const double a = 0.5 * (p.width - p.thickness);
    if (a > 0) wire.Add(BRepBuilderAPI_MakeEdge(at(-a, -t), at(a, -t)).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(at(a, -t), at(a + t, 0), at(a, t)).Value()).Edge());
    if (a > 0) wire.Add(BRepBuilderAPI_MakeEdge(at(a, t), at(-a, t)).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(at(-a, t), at(-a - t, 0), at(-a, -t)).Value()).Edge());
  } else {
    const double w = 0.5 * p.width;
    const gp_Pnt c[4] = {at(-w, -t), at(w, -t), at(w, t), at(-w, t)};
    for (int k = 0; k < 4; ++k) wire.Add(BRepBuilderAPI_MakeEdge(c[k], c[(k + 1) % 4]).Edge());
  }
  return wire.Wire();
}

bool IsValidStrip(const TopoDS_Shape& shape) {
  int faces = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) ++faces;
  return faces >= 4 && BRepCheck_Analyzer(shape).IsValid();
}

}  // namespace

TopoDS_Shape MakeFlatStripSolid(const TopoDS_Wire& spine, const TopoDS_Wire& guide,
                                const FlatProfile& profile) {
  if (!(profile.thickness > 0) || !(profile.width >= profile.thickness))
    throw InvalidInput("a flat strip needs a width at least its thickness and a positive thickness");
  std::string problem = "could not sweep the flat strip along the centreline";
  try {
    BRepAdaptor_CompCurve curve(spine), beside(guide);
    gp_Pnt start, guide_start;
    gp_Vec tangent;
    curve.D1(curve.FirstParameter(), start, tangent);
    beside.D0(beside.FirstParameter(), guide_start);
    if (tangent.Magnitude() < 1e-12) throw InvalidInput("the centreline has a zero tangent at its start");
    tangent.Normalize();
    gp_Vec u(start, guide_start);
    u -= u.Dot(tangent) * tangent;
    if (u.Magnitude() < 1e-9 * profile.width)
      throw InvalidInput("the flat strip's wide axis is along its centreline at the start");
    u.Normalize();
    const TopoDS_Wire section = Profile(start, u, tangent.Crossed(u), profile);
    // The guide meets each plane square to the spine once when it runs close beside it: the
    // plane's intersection is exact, while curvilinear equivalence (the same fraction of the
    // guide's length) tilts the section where the guide is longer or shorter than the spine
    // (a 10 x 2 mm strip turned half a turn along a 0.3 m bend: 5 % of its volume off).
    for (const bool curvilinear : {false, true}) {
      try {
        BRepOffsetAPI_MakePipeShell shell(spine);
        shell.SetMode(guide, curvilinear, BRepFill_NoContact);
        shell.Add(section);
        shell.SetMaxDegree(kStripMaxDegree);
        shell.SetMaxSegments(kStripMaxSegments);
        shell.SetTolerance(kStripRelativeTolerance * profile.thickness);
        shell.Build();
        if (shell.IsDone() && shell.MakeSolid() && IsValidStrip(shell.Shape())) return shell.Shape();
      } catch (const Standard_Failure& e) {
        problem = std::string("could not sweep the flat strip: ") + e.GetMessageString();
      }
    }
  } catch (const Standard_Failure& e) {
    throw InvalidInput(std::string("could not sweep the flat strip: ") + e.GetMessageString());
  }
  throw InvalidInput(problem);
}

}  // namespace cablefit
