#include "occt_tube.h"

#include <BRepAdaptor_CompCurve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepOffsetAPI_MakePipe.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include "cablefit/core/errors.h"

namespace cablefit {

TopoDS_Edge MakeSplineEdge(const Eigen::Matrix3Xd& points, double tolerance) {
  const int n = static_cast<int>(points.cols());
  if (n < 2) throw InvalidInput("a centreline needs at least 2 points");
  if (!points.allFinite()) throw InvalidInput("a centreline has non-finite points");
  TColgp_Array1OfPnt pts(1, n);
  for (int i = 0; i < n; ++i) pts.SetValue(i + 1, gp_Pnt(points(0, i), points(1, i), points(2, i)));
  try {
    // Degree 3..8, C2: smooth enough for a sweep, and exact for a straight pair of points.
    GeomAPI_PointsToBSpline fit(pts, n == 2 ? 1 : 3, 8, n == 2 ? GeomAbs_C0 : GeomAbs_C2,
                                tolerance);
    if (!fit.IsDone()) throw InvalidInput("could not fit a B-spline through the centreline");
    return BRepBuilderAPI_MakeEdge(fit.Curve()).Edge();
  } catch (const Standard_Failure& e) {
    throw InvalidInput(std::string("could not fit a B-spline through the centreline: ") +
                       e.GetMessageString());
  }
}

TopoDS_Shape MakeTubeSolid(const TopoDS_Wire& spine, double diameter) {
  if (!(diameter > 0)) throw InvalidInput("a tube needs a positive diameter");
  try {
    BRepAdaptor_CompCurve curve(spine);
    gp_Pnt start;
    gp_Vec tangent;
    curve.D1(curve.FirstParameter(), start, tangent);
    if (tangent.Magnitude() < 1e-12) throw InvalidInput("the centreline has a zero tangent at its start");
    const gp_Circ circle(gp_Ax2(start, gp_Dir(tangent)), 0.5 * diameter);
    const TopoDS_Wire profile =
        BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire();
    const TopoDS_Face disc = BRepBuilderAPI_MakeFace(profile, /*OnlyPlane=*/true).Face();
    BRepOffsetAPI_MakePipe pipe(spine, disc);
    pipe.Build();
    if (!pipe.IsDone()) throw InvalidInput("could not sweep the tube along the centreline");
    return pipe.Shape();
  } catch (const Standard_Failure& e) {
    throw InvalidInput(std::string("could not sweep the tube: ") + e.GetMessageString());
  }
}

}  // namespace cablefit
