#include "occt_tube.h"

#include <BRepAdaptor_CompCurve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopExp_Explorer.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include <cmath>
#include <optional>
#include <string>

#include "cablefit/core/base/cubic_spline_fit.h"
#include "cablefit/core/base/errors.h"
#include "occt_pipe_surface.h"
#include "tube_recovery.h"

namespace cablefit {
namespace {

// The swept surface's approximation: quintic B-spline pieces within a thousandth of the
// diameter of the exact pipe (2 um on a 2 mm wire, far below any drawing's precision).
constexpr int kTubeMaxDegree = 5;
constexpr int kTubeMaxSegments = 2000;
constexpr double kTubeRelativeTolerance = 1e-3;

bool IsValidTube(const TopoDS_Shape& shape) {
  int faces = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) ++faces;
  return faces >= 3 && BRepCheck_Analyzer(shape).IsValid();
}

// Whether the reader takes `shape` back as a tube of `diameter` [mm]: the sweep's surface
// approximation can meet its tolerance and still wander (a corrected-Frenet sweep along a
// nearly straight spline gave a surface whose cross-sections were no circles), and the relaxed
// STEP must read back as the same cables. Sampled as the reader samples (2 mm).
bool ReadsBackAsTube(const TopoDS_Shape& shape, double diameter) {
  TubeRecoveryOptions options;
  options.sample_spacing = 2.0;
  options.min_aspect = 0;
  const std::optional<RecoveredTube> tube = RecoverTube(shape, options);
  return tube && std::abs(2 * tube->radius - diameter) <= kTubeRelativeTolerance * diameter;
}

// The spine's curve when it is one untrimmed, unmoved B-spline edge; null otherwise.
Handle(Geom_BSplineCurve) SingleBSpline(const TopoDS_Wire& spine) {
  TopExp_Explorer ex(spine, TopAbs_EDGE);
  if (!ex.More()) return nullptr;
  const TopoDS_Edge edge = TopoDS::Edge(ex.Current());
  ex.Next();
  if (ex.More()) return nullptr;
  TopLoc_Location location;
  double first = 0.0, last = 0.0;
  const Handle(Geom_BSplineCurve) curve =
      Handle(Geom_BSplineCurve)::DownCast(BRep_Tool::Curve(edge, location, first, last));
  if (curve.IsNull() || !location.IsIdentity() ||
      std::abs(first - curve->FirstParameter()) > Precision::PConfusion() ||
      std::abs(last - curve->LastParameter()) > Precision::PConfusion())
    return nullptr;
  return curve;
}

}  // namespace

TopoDS_Edge MakeSplineEdge(const Eigen::Matrix3Xd& points, double tolerance) {
  const int n = static_cast<int>(points.cols());
  if (n < 2) throw InvalidInput("a centreline needs at least 2 points");
  if (!points.allFinite()) throw InvalidInput("a centreline has non-finite points");
  TColgp_Array1OfPnt pts(1, n);
  for (int i = 0; i < n; ++i) pts.SetValue(i + 1, gp_Pnt(points(0, i), points(1, i), points(2, i)));
  try {
    // Cubic, C2: smooth enough for a sweep; higher degrees with many knots make the pipe
    // surface approximation fail. A straight pair of points gives a line.
    GeomAPI_PointsToBSpline fit(pts, n == 2 ? 1 : 3, n == 2 ? 1 : 3,
                                n == 2 ? GeomAbs_C0 : GeomAbs_C2, tolerance);
    if (!fit.IsDone()) throw InvalidInput("could not fit a B-spline through the centreline");
    return BRepBuilderAPI_MakeEdge(fit.Curve()).Edge();
  } catch (const Standard_Failure& e) {
    throw InvalidInput(std::string("could not fit a B-spline through the centreline: ") +
                       e.GetMessageString());
  }
}

TopoDS_Edge MakeTubeSpineEdge(const Eigen::Matrix3Xd& points, double tolerance) {
  const int n = static_cast<int>(points.cols());
  if (n >= 4 && points.allFinite()) {
    if (const std::optional<CubicSpline> fit = FitCubicSpline(points, tolerance, n)) {
      const int m = static_cast<int>(fit->poles.cols());
      TColgp_Array1OfPnt poles(1, m);
      for (int i = 0; i < m; ++i)
        poles.SetValue(i + 1, gp_Pnt(fit->poles(0, i), fit->poles(1, i), fit->poles(2, i)));
      const int distinct = static_cast<int>(fit->interior_knots.size()) + 2;
      TColStd_Array1OfReal knots(1, distinct);
      TColStd_Array1OfInteger multiplicities(1, distinct);
      for (int k = 0; k < distinct; ++k) {
        knots.SetValue(k + 1, k == 0 ? 0.0
                              : k == distinct - 1 ? 1.0
                                                  : fit->interior_knots[static_cast<size_t>(k - 1)]);
        multiplicities.SetValue(k + 1, k == 0 || k == distinct - 1 ? 4 : 1);
      }
      try {
        return BRepBuilderAPI_MakeEdge(new Geom_BSplineCurve(poles, knots, multiplicities, 3)).Edge();
      } catch (const Standard_Failure&) {
        // OCCT's fit below.
      }
    }
  }
  return MakeSplineEdge(points, tolerance);
}

TopoDS_Shape MakeTubeSolid(const TopoDS_Wire& spine, double diameter) {
  if (!(diameter > 0)) throw InvalidInput("a tube needs a positive diameter");
  // A spine of one B-spline edge (what MakeSplineEdge gives) gets its surface directly: exact
  // circles, poles from the spine's own, no sweep (tens of times faster, a third of the size).
  if (const Handle(Geom_BSplineCurve) centre = SingleBSpline(spine); !centre.IsNull()) {
    if (std::optional<TopoDS_Shape> tube =
            MakePipeSurfaceTube(centre, 0.5 * diameter, kTubeRelativeTolerance * diameter);
        tube && IsValidTube(*tube))
      return *tube;
  }
  std::string problem = "could not sweep the tube along the centreline";
  try {
    BRepAdaptor_CompCurve curve(spine);
    gp_Pnt start;
    gp_Vec tangent;
    curve.D1(curve.FirstParameter(), start, tangent);
    if (tangent.Magnitude() < 1e-12) throw InvalidInput("the centreline has a zero tangent at its start");
    const gp_Circ circle(gp_Ax2(start, gp_Dir(tangent)), 0.5 * diameter);
    const TopoDS_Wire profile =
        BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire();
    // Never BRepOffsetAPI_MakePipe with a disc: in OCCT 7.6 BRepFill_Pipe::MakeShape ignores a
    // failed BRepFill_Sweep and calls ShapeType() on the empty faces it left (null read,
    // SIGSEGV). The pipe shell checks the sweep's status, so a failure is an answer here.
    // Corrected Frenet first (a smooth frame); the discrete trihedron where it fails: on a
    // nearly straight stretch with sub-micrometre noise (a mesh skeleton) the Frenet normal is
    // undefined and the corrected-Frenet sweep's surface approximation gives up.
    TopoDS_Shape valid;  // a valid sweep the reader would not take back, if nothing better
    for (const bool discrete : {false, true}) {
      try {
        BRepOffsetAPI_MakePipeShell shell(spine);
        if (discrete) {
          shell.SetDiscreteMode();
        } else {
          shell.SetMode(/*IsFrenet=*/false);
        }
        shell.Add(profile);
        // OCCT's defaults (degree 11, 30 segments) give surfaces whose poles stray far from the
        // tube (hundreds of mm around a 16 mm cable), which other CAD systems and our own
        // reader handle badly: quintic pieces, as many as the tolerance needs.
        shell.SetMaxDegree(kTubeMaxDegree);
        shell.SetMaxSegments(kTubeMaxSegments);
        shell.SetTolerance(kTubeRelativeTolerance * diameter);
        shell.Build();
        if (shell.IsDone() && shell.MakeSolid() && IsValidTube(shell.Shape())) {
          if (ReadsBackAsTube(shell.Shape(), diameter)) return shell.Shape();
          if (valid.IsNull()) valid = shell.Shape();
        }
      } catch (const Standard_Failure& e) {
        problem = std::string("could not sweep the tube: ") + e.GetMessageString();
      }
    }
    if (!valid.IsNull()) return valid;
  } catch (const Standard_Failure& e) {
    throw InvalidInput(std::string("could not sweep the tube: ") + e.GetMessageString());
  }
  throw InvalidInput(problem);
}

}  // namespace cablefit
