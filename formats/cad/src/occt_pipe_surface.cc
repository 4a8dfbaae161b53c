#include "occt_pipe_surface.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <BSplCLib.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Ax3.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cablefit {
namespace {

// The rational quadratic circle of Piegl & Tiller (The NURBS Book, 2nd ed., section 7.3): nine
// poles on the square around the unit circle, the corners weighted sqrt(2)/2, knots at quarter
// turns. Exact, so every section of the surface is a circle as exactly as the frame is unit.
constexpr int kCirclePoles = 9;
constexpr double kCircleA[kCirclePoles] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
constexpr double kCircleB[kCirclePoles] = {0, 1, 1, 1, 0, -1, -1, -1, 0};

// Frame steps between neighbouring interpolation parameters: the double reflection method is
// fourth-order accurate, so a few steps per span follow the frame far below any tolerance here.
constexpr int kFrameSubsteps = 8;
// Rounds of knot refinement where the interpolated frame misses the tolerance: a relaxed
// cable's spline already has knots every few millimetres, so one or two rounds are the most
// seen; more means a tangent that turns within a knot span (a kink), which the sweep handles.
constexpr int kMaxRefinements = 6;
constexpr int kMaxPoles = 20000;

struct NormalFrame {
  gp_Vec n, b;  // unit, square to the tangent t, b = t x n
};

gp_Vec AnyNormal(const gp_Vec& t) {
  // The axis least aligned with the tangent, made square to it.
  const double x = std::abs(t.X()), y = std::abs(t.Y()), z = std::abs(t.Z());
  const gp_Vec axis = x <= y && x <= z ? gp_Vec(1, 0, 0) : y <= z ? gp_Vec(0, 1, 0) : gp_Vec(0, 0, 1);
  return (axis - t * axis.Dot(t)).Normalized();
}

// The rotation-minimising frame at `params` (ascending) by the double reflection method (Wang,
// Juettler, Zheng, Liu, "Computation of rotation minimizing frames", ACM ToG 27(1), 2008). A
// frame that does not twist about the centreline keeps the seam of the surface on one side of
// the cable. Empty when the tangent vanishes somewhere.
std::vector<NormalFrame> RotationMinimisingFrames(const Geom_BSplineCurve& c,
                                                  const TColStd_Array1OfReal& params) {
  gp_Pnt x;
  gp_Vec d;
  c.D1(params(params.Lower()), x, d);
  if (d.Magnitude() <= gp::Resolution()) return {};
  gp_Vec t = d.Normalized();
  gp_Vec r = AnyNormal(t);
  std::vector<NormalFrame> frames{{r, t.Crossed(r)}};
  for (int k = params.Lower() + 1; k <= params.Upper(); ++k) {
    for (int s = 1; s <= kFrameSubsteps; ++s) {
      const double u = params(k - 1) + (params(k) - params(k - 1)) * s / kFrameSubsteps;
      gp_Pnt x1;
      gp_Vec d1;
      c.D1(u, x1, d1);
      if (d1.Magnitude() <= gp::Resolution()) return {};
      const gp_Vec t1 = d1.Normalized();
      const gp_Vec v1(x, x1);
      const double c1 = v1.SquareMagnitude();
      gp_Vec r_l = r, t_l = t;
      if (c1 > 0) {
        r_l = r - v1 * (2 / c1 * v1.Dot(r));
        t_l = t - v1 * (2 / c1 * v1.Dot(t));
      }
      const gp_Vec v2 = t1 - t_l;
      const double c2 = v2.SquareMagnitude();
      if (c2 > 0) r_l = r_l - v2 * (2 / c2 * v2.Dot(r_l));
      // Exactly square to the new tangent and of unit length, against rounding.
      const gp_Vec square = r_l - t1 * r_l.Dot(t1);
      if (square.Magnitude() <= gp::Resolution()) return {};
      r = square.Normalized();
      x = x1;
      t = t1;
    }
    frames.push_back({r, t.Crossed(r)});
  }
  return frames;
}

// The frame interpolated in the basis of `c`: poles of N (columns 0..2) and B (3..5) per pole of
// `c`, or empty when the frame or the interpolation fails.
std::vector<double> InterpolatedFrame(const Geom_BSplineCurve& c) {
  const int poles = c.NbPoles(), degree = c.Degree();
  TColStd_Array1OfReal flat(1, poles + degree + 1);
  c.KnotSequence(flat);
  // Greville abscissae: interpolation there is well posed for any knot vector (Schoenberg-
  // Whitney) and reproduces the frame exactly at both ends, where the caps sit.
  TColStd_Array1OfReal params(1, poles);
  BSplCLib::BuildSchoenbergPoints(degree, flat, params);
  const std::vector<NormalFrame> frames = RotationMinimisingFrames(c, params);
  if (frames.empty()) return {};
  std::vector<double> data(static_cast<size_t>(6 * poles));
  for (int i = 0; i < poles; ++i) {
    const NormalFrame& f = frames[static_cast<size_t>(i)];
    double* row = &data[static_cast<size_t>(6 * i)];
    row[0] = f.n.X(), row[1] = f.n.Y(), row[2] = f.n.Z();
    row[3] = f.b.X(), row[4] = f.b.Y(), row[5] = f.b.Z();
  }
  TColStd_Array1OfInteger contact(1, poles);
  contact.Init(0);
  int inversion = 0;
  BSplCLib::Interpolate(degree, flat, params, contact, 6, data[0], inversion);
  if (inversion != 0) return {};
  return data;
}

Handle(Geom_BSplineCurve) FrameCurve(const Geom_BSplineCurve& c, const std::vector<double>& data,
                                     int offset) {
  TColgp_Array1OfPnt poles(1, c.NbPoles());
  for (int i = 0; i < c.NbPoles(); ++i) {
    const double* row = &data[static_cast<size_t>(6 * i + offset)];
    poles.SetValue(i + 1, gp_Pnt(row[0], row[1], row[2]));
  }
  return new Geom_BSplineCurve(poles, c.Knots(), c.Multiplicities(), c.Degree());
}

// The knot spans of `c` where the interpolated frame strays from an orthonormal frame square
// to the tangent by more than `allowed` (relative): a section there would be no circle of the
// radius, or would lean. Checked at quarter points of every span.
std::vector<double> SpansToRefine(const Geom_BSplineCurve& c, const std::vector<double>& data,
                                  double allowed) {
  const Handle(Geom_BSplineCurve) n_curve = FrameCurve(c, data, 0);
  const Handle(Geom_BSplineCurve) b_curve = FrameCurve(c, data, 3);
  std::vector<double> midpoints;
  for (int k = 1; k < c.NbKnots(); ++k) {
    const double a = c.Knot(k), b = c.Knot(k + 1);
    double worst = 0.0;
    for (const double w : {0.25, 0.5, 0.75}) {
      const double u = a + w * (b - a);
      gp_Pnt x;
      gp_Vec d;
      c.D1(u, x, d);
      if (d.Magnitude() <= gp::Resolution()) return {a};  // refined until the caller gives up
      const gp_Vec t = d.Normalized();
      const gp_Vec n(n_curve->Value(u).XYZ()), bn(b_curve->Value(u).XYZ());
      worst = std::max({worst, std::abs(n.Magnitude() - 1), std::abs(bn.Magnitude() - 1),
                        std::abs(n.Dot(bn)), std::abs(n.Dot(t)), std::abs(bn.Dot(t))});
    }
    if (worst > allowed) midpoints.push_back(0.5 * (a + b));
  }
  return midpoints;
}

// A planar disc closing the tube at `centre`, its normal `outward`, bounded by `rim`.
std::optional<TopoDS_Face> Cap(const gp_Pnt& centre, const gp_Vec& outward, const TopoDS_Edge& rim) {
  BRepBuilderAPI_MakeWire wire(rim);
  if (!wire.IsDone()) return std::nullopt;
  BRepBuilderAPI_MakeFace face(gp_Pln(gp_Ax3(centre, gp_Dir(outward))), wire.Wire(),
                               /*Inside=*/true);
  if (!face.IsDone()) return std::nullopt;
  TopTools_ListOfShape edges;
  edges.Append(rim);
  BRepLib::BuildPCurveForEdgesOnPlane(edges, face.Face());
  return face.Face();
}

}  // namespace

std::optional<TopoDS_Shape> MakePipeSurfaceTube(const Handle(Geom_BSplineCurve)& centre,
                                                double radius, double tolerance) {
  if (centre.IsNull() || centre->IsRational() || centre->IsPeriodic() || !(radius > 0) ||
      !(tolerance > 0))
    return std::nullopt;
  try {
    const Handle(Geom_BSplineCurve) c = Handle(Geom_BSplineCurve)::DownCast(centre->Copy());
    std::vector<double> frame;
    for (int round = 0;; ++round) {
      frame = InterpolatedFrame(*c);
      if (frame.empty()) return std::nullopt;
      const std::vector<double> refine = SpansToRefine(*c, frame, tolerance / radius);
      if (refine.empty()) break;
      if (round == kMaxRefinements || c->NbPoles() + static_cast<int>(refine.size()) > kMaxPoles)
        return std::nullopt;
      for (const double u : refine) c->InsertKnot(u);
    }
    const int poles = c->NbPoles();
    TColgp_Array2OfPnt surface_poles(1, poles, 1, kCirclePoles);
    TColStd_Array2OfReal weights(1, poles, 1, kCirclePoles);
    for (int i = 0; i < poles; ++i) {
      const gp_XYZ p = c->Pole(i + 1).XYZ();
      const double* row = &frame[static_cast<size_t>(6 * i)];
      const gp_XYZ n(row[0], row[1], row[2]), b(row[3], row[4], row[5]);
      for (int j = 0; j < kCirclePoles; ++j) {
        // The same arithmetic for the first and last column: they must be identical for the
        // surface to count as closed (Geom_BSplineSurface::IsVClosed) and get a seam.
        surface_poles.SetValue(i + 1, j + 1, gp_Pnt(p + radius * (kCircleA[j] * n + kCircleB[j] * b)));
        weights.SetValue(i + 1, j + 1, j % 2 == 1 ? M_SQRT1_2 : 1.0);
      }
    }
    TColStd_Array1OfReal v_knots(1, 5);
    TColStd_Array1OfInteger v_mults(1, 5);
    for (int k = 0; k < 5; ++k) {
      v_knots.SetValue(k + 1, 0.5 * M_PI * k);
      v_mults.SetValue(k + 1, k == 0 || k == 4 ? 3 : 2);
    }
    const Handle(Geom_BSplineSurface) surface =
        new Geom_BSplineSurface(surface_poles, weights, c->Knots(), v_knots, c->Multiplicities(),
                                v_mults, c->Degree(), 2);
    if (!surface->IsVClosed()) return std::nullopt;
    BRepBuilderAPI_MakeFace lateral(surface, Precision::Confusion());
    if (!lateral.IsDone()) return std::nullopt;
    const TopoDS_Face side = lateral.Face();

    // The two rims: the face's edges that are neither its seam nor degenerate.
    const double u0 = c->FirstParameter(), u1 = c->LastParameter();
    gp_Pnt c0, c1;
    gp_Vec d0, d1;
    c->D1(u0, c0, d0);
    c->D1(u1, c1, d1);
    const gp_Pnt rim0 = surface_poles(1, 1), rim1 = surface_poles(poles, 1);
    std::optional<TopoDS_Face> cap0, cap1;
    for (TopExp_Explorer ex(side, TopAbs_EDGE); ex.More(); ex.Next()) {
      const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
      if (BRep_Tool::IsClosed(e, side) || BRep_Tool::Degenerated(e)) continue;
      const gp_Pnt v = BRep_Tool::Pnt(TopExp::FirstVertex(e));
      if (v.Distance(rim0) <= v.Distance(rim1)) {
        if (!cap0) cap0 = Cap(c0, -d0, e);
      } else if (!cap1) {
        cap1 = Cap(c1, d1, e);
      }
    }
    if (!cap0 || !cap1) return std::nullopt;
    // The surface's own normal S_u x S_v = t x (-sin v n + cos v b) points into the tube (with
    // b = t x n): reversed, every face of the shell faces out.
    BRep_Builder builder;
    TopoDS_Shell shell;
    builder.MakeShell(shell);
    builder.Add(shell, side.Reversed());
    builder.Add(shell, *cap0);
    builder.Add(shell, *cap1);
    shell.Closed(true);
    TopoDS_Solid solid;
    builder.MakeSolid(solid);
    builder.Add(solid, shell);
    if (!BRepLib::OrientClosedSolid(solid)) return std::nullopt;
    return TopoDS_Shape(solid);
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

}  // namespace cablefit
