// Generator of tests/data/flat/flat_cables.step (run by hand: cablefit_make_flat_cables PATH),
// a made-up input of flat cables: a 10 x 2 mm rectangular ribbon along a spline that rises,
// turns and levels out, and a flat house wire (a 12 x 4.4 mm stadium jacket with its three
// 2.4 mm cores drawn as solids of their own inside it).
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

#include <stdexcept>
#include <string>

#include <cstdio>

#include "occt_tube.h"
#include "xde_document.h"

namespace cablefit {
namespace {

using Eigen::Vector3d;

gp_Pnt P(const Vector3d& v) { return gp_Pnt(v.x(), v.y(), v.z()); }

// The profile at the spine's start, `offset` [mm] along the wide axis `u`: a w x t rectangle,
// a stadium (half-round edges) or, with t = w, a circle.
TopoDS_Wire Profile(const Vector3d& origin, const Vector3d& tangent, const Vector3d& u, double w,
                    double t, bool rounded) {
  const Vector3d v = tangent.cross(u).normalized();
  BRepBuilderAPI_MakeWire wire;
  if (rounded) {
    const double a = 0.5 * (w - t), r = 0.5 * t;
    const Vector3d p1 = origin - a * u - r * v, p2 = origin + a * u - r * v;
    const Vector3d p3 = origin + a * u + r * v, p4 = origin - a * u + r * v;
    if (a > 0) wire.Add(BRepBuilderAPI_MakeEdge(P(p1), P(p2)).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(P(p2), P(origin + (a + r) * u), P(p3)).Value()).Edge());
    if (a > 0) wire.Add(BRepBuilderAPI_MakeEdge(P(p3), P(p4)).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(P(p4), P(origin - (a + r) * u), P(p1)).Value()).Edge());
  } else {
    const Vector3d c[4] = {origin - 0.5 * w * u - 0.5 * t * v, origin + 0.5 * w * u - 0.5 * t * v,
                           origin + 0.5 * w * u + 0.5 * t * v, origin - 0.5 * w * u + 0.5 * t * v};
    for (int k = 0; k < 4; ++k) wire.Add(BRepBuilderAPI_MakeEdge(P(c[k]), P(c[(k + 1) % 4])).Edge());
  }
  return wire.Wire();
}

// A profile swept along the spline through `spine` (3 x n [mm]) by a corrected-Frenet frame,
// `offset` [mm] off the spine along the wide axis `u` (perpendicular to the start tangent).
TopoDS_Shape Sweep(const Eigen::Matrix3Xd& spine, const Vector3d& u, double w, double t,
                   bool rounded, double offset = 0.0) {
  const TopoDS_Wire path = BRepBuilderAPI_MakeWire(MakeSplineEdge(spine, 1e-6)).Wire();
  const Vector3d tangent = (spine.col(1) - spine.col(0)).normalized();
  BRepOffsetAPI_MakePipeShell shell(path);
  shell.SetMode(/*IsFrenet=*/false);
  shell.Add(Profile(spine.col(0) + offset * u, tangent, u, w, t, rounded));
  shell.Build();
  if (!shell.IsDone() || !shell.MakeSolid()) throw std::runtime_error("the sweep failed");
  return shell.Shape();
}

// A 10 x 2 mm ribbon along a spline that rises, turns and levels out, about 360 mm long.
Eigen::Matrix3Xd RibbonSpine() {
  Eigen::Matrix3Xd p(3, 5);
  p << 0, 80, 160, 240, 300,  //
      0, 0, 20, 70, 110,     //
      100, 120, 130, 130, 130;
  return p;
}

// A flat house wire: a 12 x 4.4 mm stadium jacket with three 2.4 mm cores, 0.5 m in the y = 200
// plane, sagging a little.
Eigen::Matrix3Xd HouseWireSpine() {
  Eigen::Matrix3Xd p(3, 4);
  p << 0, 150, 350, 500,  //
      200, 200, 200, 200,  //
      100, 80, 80, 100;
  return p;
}

void WriteFlatCables(const std::string& path) {
  Handle(TDocStd_Document) doc = NewXcafDocument();
  const Eigen::Matrix3Xd ribbon = RibbonSpine();
  const Vector3d t0 = (ribbon.col(1) - ribbon.col(0)).normalized();
  const Vector3d u0 = Vector3d::UnitY().cross(t0).cross(t0).normalized().cross(t0);  // level
  AddNamedShape(doc, Sweep(ribbon, u0, 10, 2, false), "ribbon", SrgbColor{0.8, 0.7, 0.2});
  const Eigen::Matrix3Xd house = HouseWireSpine();
  const Vector3d hu = Vector3d::UnitY();  // flat side up
  AddNamedShape(doc, Sweep(house, hu, 12, 4.4, true), "house wire", SrgbColor{0.9, 0.9, 0.9});
  int k = 0;
  for (const double offset : {-3.6, 0.0, 3.6})
    AddNamedShape(doc, Sweep(house, hu, 2.4, 2.4, true, offset), "core " + std::to_string(++k),
                  SrgbColor{0.6, 0.3, 0.1});
  WriteStepAtomically(doc, path, "AP214IS");
}

}  // namespace
}  // namespace cablefit

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: cablefit_make_flat_cables OUT.step\n");
    return 2;
  }
  cablefit::WriteFlatCables(argv[1]);
  return 0;
}
