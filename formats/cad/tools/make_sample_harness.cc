// Generates samples/harness/: a small "legacy" harness drawing as STEP AP214 in millimetres (and
// the same as IGES), an STL of two bent tubes and one of three tubes fused at a branch point. Run: cablefit_make_sample_harness <dir>.
// The committed samples are its output; the expected values in tests/formats/cad come from the geometry written here.
//
// legacy_harness.step holds
//  - assembly "bundle": three routes meeting at the junction (300, 0, 0) mm:
//    "trunk" (a wire of line + quarter arc + line), "branch_a" (a B-spline edge),
//    "branch_b" (a polyline wire of three lines);
//  - "sensor_cable": one B-spline edge;
//  - "hose": a tube solid, diameter 12 mm, swept along a B-spline cut into two edges (two faces);
//  - "clip_box" around branch_a and "clip_ring" (a torus) around sensor_cable.
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <StlAPI_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>

#include "cablefit/core/base/errors.h"
#include "occt_session.h"
#include "occt_tube.h"
#include "xde_document.h"

namespace cablefit {
namespace {

Eigen::Matrix3Xd Points(std::initializer_list<std::initializer_list<double>> xyz) {
  Eigen::Matrix3Xd m(3, static_cast<Eigen::Index>(xyz.size()));
  Eigen::Index i = 0;
  for (const auto& p : xyz) {
    auto it = p.begin();
    m.col(i++) << it[0], it[1], it[2];
  }
  return m;
}

TopoDS_Edge Line(const gp_Pnt& a, const gp_Pnt& b) { return BRepBuilderAPI_MakeEdge(a, b).Edge(); }

TopoDS_Shape Trunk() {  // 100 mm line, quarter arc of radius 50 mm, 200 mm line: 378.5 mm
  BRepBuilderAPI_MakeWire wire;
  wire.Add(Line(gp_Pnt(50, -150, 0), gp_Pnt(50, -50, 0)));
  wire.Add(BRepBuilderAPI_MakeEdge(
               GC_MakeArcOfCircle(gp_Pnt(50, -50, 0), gp_Pnt(100 - 50 * std::sqrt(0.5),
                                                            -50 + 50 * std::sqrt(0.5), 0),
                                  gp_Pnt(100, 0, 0))
                   .Value())
               .Edge());
  wire.Add(Line(gp_Pnt(100, 0, 0), gp_Pnt(300, 0, 0)));
  return wire.Wire();
}

TopoDS_Shape BranchA() {
  return MakeSplineEdge(Points({{300, 0, 0}, {380, 30, 10}, {460, 80, 20}, {540, 110, 30}}), 1e-3);
}

TopoDS_Shape BranchB() {
  BRepBuilderAPI_MakeWire wire;
  wire.Add(Line(gp_Pnt(300, 0, 0), gp_Pnt(380, -60, 0)));
  wire.Add(Line(gp_Pnt(380, -60, 0), gp_Pnt(450, -100, -10)));
  wire.Add(Line(gp_Pnt(450, -100, -10), gp_Pnt(520, -150, -20)));
  return wire.Wire();
}

TopoDS_Shape SensorCable() {
  return MakeSplineEdge(
      Points({{0, 100, 0}, {120, 140, 10}, {250, 150, 30}, {380, 180, 40}, {500, 200, 50}}), 1e-3);
}

TopoDS_Shape Hose() {
  // One smooth B-spline cut into two edges: the swept tube gets two lateral faces (a drawing
  // "split into segments") without a kink at the cut.
  const TopoDS_Edge whole = MakeSplineEdge(
      Points({{0, -300, 0}, {100, -280, 20}, {200, -290, 40}, {300, -270, 40}, {400, -250, 40},
              {500, -260, 20}, {600, -250, 0}}),
      1e-3);
  double t0, t1;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(whole, t0, t1);
  const double cut = 0.5 * (t0 + t1);
  BRepBuilderAPI_MakeWire spine;
  spine.Add(BRepBuilderAPI_MakeEdge(curve, t0, cut).Edge());
  spine.Add(BRepBuilderAPI_MakeEdge(curve, cut, t1).Edge());
  return MakeTubeSolid(spine.Wire(), 12.0);
}

void AddPart(const Handle(TDocStd_Document)& doc, const TDF_Label& assembly,
             const TopoDS_Shape& shape, const std::string& name, SrgbColor color) {
  if (assembly.IsNull()) {
    AddNamedShape(doc, shape, name, color);
    return;
  }
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const TDF_Label part = AddNamedShape(doc, shape, name, color);
  const TDF_Label instance = shapes->AddComponent(assembly, part, TopLoc_Location());
  TDataStd_Name::Set(instance, TCollection_ExtendedString(name.c_str(), true));
}

// The harness with the bundle's three cables as an assembly (STEP) or as top-level parts: OCCT's
// IGES writer drops the names of assembly components, and IGES exporters of harness tools write
// each part as a named top-level entity.
Handle(TDocStd_Document) HarnessDocument(bool bundle_as_assembly) {
  Handle(TDocStd_Document) doc = NewXcafDocument();
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_Label bundle;
  if (bundle_as_assembly) {
    bundle = shapes->NewShape();
    TDataStd_Name::Set(bundle, "bundle");
  }
  AddPart(doc, bundle, Trunk(), "trunk", {0.9, 0.1, 0.1});
  AddPart(doc, bundle, BranchA(), "branch_a", {0.1, 0.6, 0.1});
  AddPart(doc, bundle, BranchB(), "branch_b", {0.1, 0.2, 0.8});
  if (bundle_as_assembly) shapes->UpdateAssemblies();
  AddPart(doc, TDF_Label(), SensorCable(), "sensor_cable", {1.0, 0.8, 0.0});
  AddPart(doc, TDF_Label(), Hose(), "hose", {0.2, 0.2, 0.2});
  // A 20 mm box centred on branch_a's second control point, a ring around sensor_cable.
  AddPart(doc, TDF_Label(), BRepPrimAPI_MakeBox(gp_Pnt(370, 20, 0), 20, 20, 20).Shape(),
          "clip_box", {0.95, 0.95, 0.95});
  AddPart(doc, TDF_Label(),
          BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 100, 0), gp_Dir(1, 0.33, 0)), 8, 2).Shape(),
          "clip_ring", {0.6, 0.3, 0.0});
  return doc;
}

void WriteHarness(const std::string& path) {
  WriteStepAtomically(HarnessDocument(true), path, "AP214IS");
}

// The same drawing as IGES 5.3 with B-rep solids (the other legacy exchange format).
void WriteHarnessIges(const std::string& path) {
  Handle(TDocStd_Document) doc = HarnessDocument(false);
  Interface_Static::SetIVal("write.iges.brep.mode", 1);
  Interface_Static::SetCVal("write.iges.unit", "MM");
  IGESCAFControl_Writer writer;
  writer.SetNameMode(true);
  writer.SetColorMode(true);
  const std::string temp = path + ".tmp";
  if (!writer.Transfer(doc) || !writer.Write(temp.c_str())) throw FileError(path, "could not write IGES");
  std::filesystem::rename(temp, path);
}

void WriteBentTubes(const std::string& path) {
  // Tube 1: 10 mm, line + quarter arc (R 60) + line. Tube 2: 8 mm, an S-shaped B-spline.
  BRepBuilderAPI_MakeWire spine1;
  spine1.Add(Line(gp_Pnt(0, 0, 0), gp_Pnt(100, 0, 0)));
  spine1.Add(BRepBuilderAPI_MakeEdge(
                 GC_MakeArcOfCircle(gp_Pnt(100, 0, 0),
                                    gp_Pnt(100 + 60 * std::sqrt(0.5), 60 - 60 * std::sqrt(0.5), 0),
                                    gp_Pnt(160, 60, 0))
                     .Value())
                 .Edge());
  spine1.Add(Line(gp_Pnt(160, 60, 0), gp_Pnt(160, 200, 0)));
  BRepBuilderAPI_MakeWire spine2;
  spine2.Add(MakeSplineEdge(
      Points({{0, 100, 50}, {60, 130, 50}, {120, 100, 60}, {180, 70, 60}, {240, 100, 50}}), 1e-3));
  BRep_Builder builder;
  TopoDS_Compound both;
  builder.MakeCompound(both);
  builder.Add(both, MakeTubeSolid(spine1.Wire(), 10.0));
  builder.Add(both, MakeTubeSolid(spine2.Wire(), 8.0));
  BRepMesh_IncrementalMesh(both, 0.1, false, 0.5, false);
  StlAPI_Writer writer;
  writer.ASCIIMode() = false;
  const std::string temp = path + ".tmp";
  if (!writer.Write(both, temp.c_str())) throw FileError(path, "could not write STL");
  std::filesystem::rename(temp, path);
}

// Three 10 mm tubes fused where they meet at (0, 0, 0): a branched bundle as one closed mesh.
// Arms: 120 mm along +x, 100 mm at 120 degrees, and 90 mm bending up out of the plane.
void WriteBranchedTubes(const std::string& path) {
  auto straight = [](const gp_Pnt& to) {
    return BRepBuilderAPI_MakeWire(Line(gp_Pnt(0, 0, 0), to)).Wire();
  };
  BRepBuilderAPI_MakeWire bent;
  bent.Add(MakeSplineEdge(Points({{0, 0, 0}, {-30, -30, 0}, {-50, -55, 20}, {-55, -70, 50}}), 1e-3));
  BRepAlgoAPI_Fuse first(MakeTubeSolid(straight(gp_Pnt(120, 0, 0)), 10.0),
                         MakeTubeSolid(straight(gp_Pnt(-50, 50 * std::sqrt(3.0), 0)), 10.0));
  BRepAlgoAPI_Fuse all(first.Shape(), MakeTubeSolid(bent.Wire(), 10.0));
  if (!all.IsDone()) throw FileError(path, "could not fuse the branched tubes");
  BRepMesh_IncrementalMesh(all.Shape(), 0.1, false, 0.5, false);
  StlAPI_Writer writer;
  writer.ASCIIMode() = false;
  const std::string temp = path + ".tmp";
  if (!writer.Write(all.Shape(), temp.c_str())) throw FileError(path, "could not write STL");
  std::filesystem::rename(temp, path);
}

}  // namespace
}  // namespace cablefit

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path dir(argv[1]);
    std::filesystem::create_directories(dir);
    cablefit::InitOcctSession();
    cablefit::WriteHarness((dir / "legacy_harness.step").string());
    cablefit::WriteHarnessIges((dir / "legacy_harness.igs").string());
    cablefit::WriteBentTubes((dir / "bent_tubes.stl").string());
    cablefit::WriteBranchedTubes((dir / "branched_tubes.stl").string());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cablefit_make_sample_harness: %s\n", e.what());
    return 1;
  }
  return 0;
}
