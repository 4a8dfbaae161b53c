// ReadCadFile: STEP/IGES through XDE, assembly walked with names and colours; curves and tube
// solids become cables, everything else is kept as solids.
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "cad_shape_handle.h"
#include "crash_probe.h"
#include "curve_routes.h"
#include "occt_session.h"
#include "tube_recovery.h"
#include "xde_document.h"

namespace cablefit {
namespace {

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

Polyline ToPolyline(const Eigen::Matrix3Xd& points_occt) {
  Polyline p;
  p.points = points_occt * kMetresPerOcctUnit;
  p.ParameteriseByChords(0.0);
  return p;
}

TriangleMesh Tessellate(const TopoDS_Shape& shape, double relative_deflection) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  const double size = box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
  BRepMesh_IncrementalMesh(shape, relative_deflection * size, false, 0.5, false);
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
    const TopoDS_Face& face = TopoDS::Face(ex.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull()) continue;
    const int base = static_cast<int>(vertices.size());
    const gp_Trsf trsf = loc.Transformation();
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      const gp_Pnt p = tri->Node(i).Transformed(trsf);
      vertices.emplace_back(p.X() * kMetresPerOcctUnit, p.Y() * kMetresPerOcctUnit,
                            p.Z() * kMetresPerOcctUnit);
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int i = 1; i <= tri->NbTriangles(); ++i) {
      int a, b, c;
      tri->Triangle(i).Get(a, b, c);
      if (reversed) std::swap(b, c);  // keep counter-clockwise seen from outside
      faces.emplace_back(base + a - 1, base + b - 1, base + c - 1);
    }
  }
  TriangleMesh mesh;
  mesh.vertices.resize(3, static_cast<Eigen::Index>(vertices.size()));
  for (size_t i = 0; i < vertices.size(); ++i) mesh.vertices.col(static_cast<Eigen::Index>(i)) = vertices[i];
  mesh.faces.resize(3, static_cast<Eigen::Index>(faces.size()));
  for (size_t i = 0; i < faces.size(); ++i) mesh.faces.col(static_cast<Eigen::Index>(i)) = faces[i];
  return mesh;
}

class DrawingBuilder {
 public:
  DrawingBuilder(Handle(TDocStd_Document) doc, const CadReadOptions& options,
                 HarnessDrawing* drawing)
      : doc_(std::move(doc)),
        shapes_(XCAFDoc_DocumentTool::ShapeTool(doc_->Main())),
        options_(options),
        drawing_(drawing) {}

  void WalkFreeShapes() {
    TDF_LabelSequence roots;
    shapes_->GetFreeShapes(roots);
    for (TDF_LabelSequence::Iterator it(roots); it.More(); it.Next()) {
      Walk(it.Value(), TopLoc_Location(), "", std::nullopt);
    }
  }

 private:
  struct Style {
    std::string name;
    std::optional<SrgbColor> color;
  };

  // Instance names/colours override the product's; an unnamed part takes its parent's name.
  void Walk(const TDF_Label& label, const TopLoc_Location& location, const std::string& parent,
            std::optional<SrgbColor> inherited) {
    std::string name = LabelName(label);
    if (const auto c = LabelColor(doc_, label)) inherited = c;
    TDF_Label referred;
    if (XCAFDoc_ShapeTool::IsReference(label) && XCAFDoc_ShapeTool::GetReferredShape(label, referred)) {
      const std::string product = LabelName(referred);
      // STEP instance names are often generated ("NAUO12"): prefer the product's name.
      if (!product.empty()) name = product;
      WalkShape(referred, location * XCAFDoc_ShapeTool::GetLocation(label), name.empty() ? parent : name,
            inherited);
      return;
    }
    WalkShape(label, location, name.empty() ? parent : name, inherited);
  }

  void WalkShape(const TDF_Label& label, const TopLoc_Location& location, const std::string& name,
             std::optional<SrgbColor> color) {
    if (const auto c = LabelColor(doc_, label)) color = c;
    if (XCAFDoc_ShapeTool::IsAssembly(label)) {
      TDF_LabelSequence components;
      XCAFDoc_ShapeTool::GetComponents(label, components);
      for (TDF_LabelSequence::Iterator it(components); it.More(); it.Next()) {
        Walk(it.Value(), location, name, color);
      }
      return;
    }
    const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label).Moved(location);
    if (shape.IsNull()) return;
    AddShape(label, shape, name.empty() ? "unnamed" : name, color);
  }

  // A part's solids may carry their own names/colours as sub-shape labels.
  Style SubStyle(const TDF_Label& part, const TopoDS_Shape& sub, const Style& fallback) {
    TDF_Label sub_label;
    Style style = fallback;
    if (shapes_->FindSubShape(part, sub.Located(TopLoc_Location()), sub_label) ||
        shapes_->FindSubShape(part, sub, sub_label)) {
      const std::string n = LabelName(sub_label);
      if (!n.empty()) style.name = n;
      if (const auto c = LabelColor(doc_, sub_label)) style.color = c;
    }
    return style;
  }

  void AddShape(const TDF_Label& label, const TopoDS_Shape& shape, const std::string& name,
                const std::optional<SrgbColor>& color) {
    const Style style{name, color};
    std::vector<DrawnCable> cables;
    const std::vector<CurveRoute> routes =
        ExtractCurveRoutes(shape, options_.sample_spacing / kMetresPerOcctUnit,
                           std::max(options_.junction_tolerance / kMetresPerOcctUnit, 1e-6));
    for (const CurveRoute& route : routes) {
      DrawnCable cable;
      cable.name = style.name;
      cable.centreline = ToPolyline(route.points);
      cable.source = CableSourceKind::kCurve;
      cable.fit_error = route.max_chord_error * kMetresPerOcctUnit;
      SetColor(&cable, style.color);
      cables.push_back(std::move(cable));
    }
    // Solids, then shells that bound no solid (a tube drawn as a surface).
    std::vector<TopoDS_Shape> bodies;
    for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) bodies.push_back(ex.Current());
    for (TopExp_Explorer ex(shape, TopAbs_SHELL, TopAbs_SOLID); ex.More(); ex.Next()) {
      bodies.push_back(ex.Current());
    }
    TubeRecoveryOptions tube_options;
    tube_options.sample_spacing = options_.sample_spacing / kMetresPerOcctUnit;
    tube_options.min_area_fraction = options_.min_tube_area_fraction;
    tube_options.min_aspect = options_.min_tube_aspect;
    for (const TopoDS_Shape& body : bodies) {
      const Style body_style = bodies.size() > 1 ? SubStyle(label, body, style) : style;
      if (const auto tube = RecoverTube(body, tube_options)) {
        DrawnCable cable;
        cable.name = body_style.name;
        cable.centreline = ToPolyline(tube->centres);
        cable.diameter = 2 * tube->radius * kMetresPerOcctUnit;
        cable.source = CableSourceKind::kTube;
        cable.fit_error = tube->rms_residual * kMetresPerOcctUnit;
        SetColor(&cable, body_style.color);
        cables.push_back(std::move(cable));
      } else {
        DrawnSolid solid;
        solid.name = body_style.name;
        if (body_style.color) {
          solid.has_color = true;
          solid.color = *body_style.color;
        }
        solid.mesh = Tessellate(body, options_.mesh_relative_deflection);
        solid.shape = std::make_shared<const CadShapeHandle>(CadShapeHandle{body});
        drawing_->solids.push_back(std::move(solid));
      }
    }
    if (cables.size() > 1) {  // one part holding several routes: keep the names apart
      for (size_t i = 0; i < cables.size(); ++i) {
        cables[i].name += '#';  // appended piecewise: GCC 12 -Wrestrict misfires on "#" + string
        cables[i].name += std::to_string(i + 1);
      }
    }
    for (auto& c : cables) drawing_->cables.push_back(std::move(c));
  }

  static void SetColor(DrawnCable* cable, const std::optional<SrgbColor>& color) {
    cable->has_color = color.has_value();
    if (color) cable->color = *color;
  }

  Handle(TDocStd_Document) doc_;
  Handle(XCAFDoc_ShapeTool) shapes_;
  const CadReadOptions& options_;
  HarnessDrawing* drawing_;
};

std::string StepLengthUnit(STEPCAFControl_Reader& reader) {
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.ChangeReader().FileUnits(lengths, angles, solid_angles);
  if (lengths.IsEmpty()) return "mm";
  std::string unit = Lower(lengths.First().ToCString());
  if (unit == "millimetre" || unit == "millimeter") return "mm";
  if (unit == "metre" || unit == "meter") return "m";
  if (unit == "centimetre" || unit == "centimeter") return "cm";
  return unit;
}

Handle(TDocStd_Document) ReadDocument(const std::string& path, bool iges, std::string* unit) {
  Handle(TDocStd_Document) doc = NewXcafDocument();
  if (iges) {
    IGESCAFControl_Reader reader;
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
      throw FileError(path, "not a readable IGES file");
    }
    if (!reader.Transfer(doc)) throw FileError(path, "IGES transfer failed");
    const Handle(IGESData_IGESModel) model = reader.IGESModel();
    const Handle(TCollection_HAsciiString) name =
        model.IsNull() ? Handle(TCollection_HAsciiString)() : model->GlobalSection().UnitName();
    *unit = name.IsNull() ? "mm" : Lower(name->ToCString());
  } else {
    STEPCAFControl_Reader reader;
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
      throw FileError(path, "not a readable STEP file");
    }
    if (reader.ChangeReader().NbRootsForTransfer() == 0) {
      throw FileError(path, "the STEP file contains no shapes");
    }
    if (!reader.Transfer(doc)) throw FileError(path, "STEP transfer failed");
    *unit = StepLengthUnit(reader);
  }
  return doc;
}

}  // namespace

HarnessDrawing ReadCadFile(const std::string& path, const CadReadOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw InvalidInput("CAD read options: " + why);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path, "no such file");
  if (std::filesystem::file_size(path, ec) == 0) throw FileError(path, "the file is empty");
  // OCCT holds every entity of a STEP/IGES file in memory, about 25x the file's size (measured
  // on a STEP of 10^5 entities): the limit keeps one read under ~6.5 GB.
  constexpr std::uintmax_t kMaxCadBytes = std::uintmax_t{256} << 20;
  if (const std::uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxCadBytes)
    throw FileError(path, "is " + std::to_string(size) + " bytes, more than the limit of " +
                              std::to_string(kMaxCadBytes) + " bytes for a CAD file");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw FileError(path, "cannot open the file");
  }
  const std::string ext = Lower(std::filesystem::path(path).extension().string());
  const bool iges = ext == ".igs" || ext == ".iges";
  if (!iges && ext != ".step" && ext != ".stp" && ext != ".p21") {
    throw FileError(path, "unknown CAD extension '" + ext + "' (expected .step, .stp, .iges, .igs)");
  }
  InitOcctSession();
  ProbeInChildProcess(path, iges ? "the IGES reader" : "the STEP reader", [&] {
    HarnessDrawing probe;
    DrawingBuilder builder(ReadDocument(path, iges, &probe.length_unit), options, &probe);
    builder.WalkFreeShapes();
  });
  HarnessDrawing drawing;
  drawing.source_path = path;
  try {
    Handle(TDocStd_Document) doc = ReadDocument(path, iges, &drawing.length_unit);
    DrawingBuilder builder(doc, options, &drawing);
    builder.WalkFreeShapes();
  } catch (const Standard_Failure& e) {
    throw FileError(path, std::string("OCCT could not read the file: ") + e.GetMessageString());
  }
  if (drawing.cables.empty() && drawing.solids.empty()) {
    throw FileError(path, "the file contains no shapes");
  }
  if (drawing.cables.empty()) {
    throw FileError(path, "no cable curves or tube solids found (" +
                              std::to_string(drawing.solids.size()) + " other solids)");
  }
  FindJunctions(&drawing, options.junction_tolerance);
  return drawing;
}

}  // namespace cablefit
