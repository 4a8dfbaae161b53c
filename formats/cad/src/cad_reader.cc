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
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cstring>
#include <map>

#include "breakout_branches.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "cad_read_in_process.h"
#include "cad_shape_handle.h"
#include "core_tails.h"
#include "crash_probe.h"
#include "curve_pieces.h"
#include "curve_routes.h"
#include "drawn_sweeps.h"
#include "flat_cores.h"
#include "flat_recovery.h"
#include "loose_faces.h"
#include "occt_session.h"
#include "rigid_pipes.h"
#include "tube_pieces.h"
#include "tube_recovery.h"
#include "xde_document.h"

namespace cablefit {
namespace {

// Text that reads back as exactly the same double.
std::string ExactText(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

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

double ChainLength(const Eigen::Matrix3Xd& points) {  // 3 x n, any unit
  double length = 0;
  for (Eigen::Index i = 1; i < points.cols(); ++i) length += (points.col(i) - points.col(i - 1)).norm();
  return length;
}

// Names that STEP/IGES exporters write when the user gave none: treated as no name, so that
// such cables get distinct names from their position instead of one shared placeholder.
bool IsPlaceholderName(const std::string& name) {
  const std::string lower = Lower(name);
  static const char* const kPlaceholders[] = {
      "the product name", "none", "n/a", "unnamed",
      // OCCT's IGES reader names unnamed entities by their shape type.
      "compound", "compsolid", "solid", "shell", "face", "wire", "edge", "vertex"};
  if (lower.empty() || lower.rfind("open cascade step translator", 0) == 0) return true;
  return std::any_of(std::begin(kPlaceholders), std::end(kPlaceholders),
                     [&](const char* p) { return lower == p; });
}

class DrawingBuilder {
 public:
  DrawingBuilder(Handle(TDocStd_Document) doc, const CadReadOptions& options,
                 HarnessDrawing* drawing, std::vector<internal::DrawnTube>* tubes)
      : doc_(std::move(doc)),
        shapes_(XCAFDoc_DocumentTool::ShapeTool(doc_->Main())),
        options_(options),
        drawing_(drawing),
        tubes_(tubes) {}

  void WalkFreeShapes() {
    TDF_LabelSequence roots;
    shapes_->GetFreeShapes(roots);
    for (TDF_LabelSequence::Iterator it(roots); it.More(); it.Next()) {
      Walk(it.Value(), TopLoc_Location(), "", std::nullopt);
    }
    AddLooseBodies();
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
    if (IsPlaceholderName(name)) name.clear();
    if (const auto c = LabelColor(doc_, label)) inherited = c;
    TDF_Label referred;
    if (XCAFDoc_ShapeTool::IsReference(label) && XCAFDoc_ShapeTool::GetReferredShape(label, referred)) {
      std::string product = LabelName(referred);
      if (IsPlaceholderName(product)) product.clear();
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
    AddShape(label, shape, name, color);  // an empty name is given one by NameCablesUniquely
  }

  // A part's solids may carry their own names/colours as sub-shape labels.
  Style SubStyle(const TDF_Label& part, const TopoDS_Shape& sub, const Style& fallback) {
    TDF_Label sub_label;
    Style style = fallback;
    if (shapes_->FindSubShape(part, sub.Located(TopLoc_Location()), sub_label) ||
        shapes_->FindSubShape(part, sub, sub_label)) {
      const std::string n = LabelName(sub_label);
      if (!IsPlaceholderName(n)) style.name = n;
      if (const auto c = LabelColor(doc_, sub_label)) style.color = c;
    }
    return style;
  }

  void AddShape(const TDF_Label& label, const TopoDS_Shape& shape, const std::string& name,
                const std::optional<SrgbColor>& color) {
    const Style style{name, color};
    const std::vector<CurveRoute> routes =
        ExtractCurveRoutes(shape, options_.sample_spacing / kMetresPerOcctUnit,
                           std::max(options_.junction_tolerance / kMetresPerOcctUnit, 1e-6));
    for (const CurveRoute& route : routes) {
      if (IsClosedPlanar(route.points)) {
        drawing_->skipped.push_back(
            "'" + (style.name.empty() ? std::string("unnamed") : style.name) +
            "': a closed planar curve (a sketch profile), not a cable route");
        continue;
      }
      DrawnCable cable;
      cable.name = style.name;
      cable.centreline = ToPolyline(route.points);
      cable.source = CableSourceKind::kCurve;
      cable.fit_error = route.max_chord_error * kMetresPerOcctUnit;
      SetColor(&cable, style.color);
      drawing_->cables.push_back(std::move(cable));
    }
    // Solids, then shells that bound no solid (a tube drawn as a surface).
    std::vector<TopoDS_Shape> bodies;
    for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) bodies.push_back(ex.Current());
    for (TopExp_Explorer ex(shape, TopAbs_SHELL, TopAbs_SOLID); ex.More(); ex.Next()) {
      bodies.push_back(ex.Current());
    }
    // Loose faces (IGES surface models: a tube drawn as two half-surfaces) become bodies once the
    // whole file is read (LooseFaceBodies): the faces of one tube may come in several labels.
    const size_t loose_before = loose_.size();
    internal::CollectLooseFaces(shape, static_cast<int>(loose_styles_.size()), &loose_);
    if (loose_.size() > loose_before) loose_styles_.push_back(style);
    if (routes.empty() && bodies.empty() && loose_.size() == loose_before) {
      // Edges of zero length and lone points make no route; a product drawn only with them would
      // otherwise vanish from the output without a word.
      const bool has_points = TopExp_Explorer(shape, TopAbs_EDGE, TopAbs_FACE).More() ||
                              TopExp_Explorer(shape, TopAbs_VERTEX, TopAbs_EDGE).More();
      if (has_points) {
        drawing_->skipped.push_back(
            "'" + (style.name.empty() ? std::string("unnamed") : style.name) +
            "': drawn as a point or a curve of zero length, not a cable");
      }
    }
    std::vector<Style> styles;
    std::vector<internal::TubePiece> pieces;
    for (const TopoDS_Shape& body : bodies) {
      pieces.push_back({body, RecoverTube(body, TubeOptions()), static_cast<int>(styles.size())});
      styles.push_back(bodies.size() > 1 ? SubStyle(label, body, style) : style);
    }
    internal::JoinTubePieces(&pieces);
    for (internal::TubePiece& piece : pieces)
      AddBody(piece.shape, styles[static_cast<size_t>(piece.style)], std::move(piece.tube));
  }

  // The bodies drawn as loose faces, after the walk.
  void AddLooseBodies() {
    for (const internal::LooseBody& body : internal::LooseFaceBodies(loose_))
      AddBody(body.shape, loose_styles_[static_cast<size_t>(body.style)],
              RecoverTube(body.shape, TubeOptions()));
  }

  TubeRecoveryOptions TubeOptions() const {
    TubeRecoveryOptions tube_options;
    tube_options.sample_spacing = options_.sample_spacing / kMetresPerOcctUnit;
    tube_options.min_area_fraction = options_.min_tube_area_fraction;
    // Slenderness is checked by AddBody, to say why a tube is no cable.
    tube_options.min_aspect = 0;
    return tube_options;
  }

  // One body and the tube it is, if it is one: a cable when slender, else a flat cable or a
  // solid part.
  void AddBody(const TopoDS_Shape& body, const Style& body_style,
               std::optional<RecoveredTube> tube) {
    // A stout "tube" may be a slender flat strip whose long faces are round along the route (a
    // strip bent edgewise is a piece of a cylinder as wide as the strip): the strip's matched end
    // faces say which it is.
    if (tube && ChainLength(tube->centres) < options_.min_tube_aspect * 2 * tube->radius) {
      if (std::optional<DrawnCable> flat = FlatCable(body, body_style)) {
        drawing_->cables.push_back(std::move(*flat));
        return;
      }
    }
    internal::DrawnTube record;
    if (tube) {
      record.centres = tube->centres * kMetresPerOcctUnit;
      record.radius = tube->radius * kMetresPerOcctUnit;
      record.inner_radius = tube->inner_radius * kMetresPerOcctUnit;
      record.fit_error = tube->rms_residual * kMetresPerOcctUnit;
      const double length = ChainLength(tube->centres);
      const double slenderness = length / (2 * tube->radius);
      if (slenderness < options_.min_tube_aspect) {
        record.skipped_note = static_cast<int>(drawing_->skipped.size());
        char line[200];
        std::snprintf(line, sizeof line,
                      "a tube %.1f diameters long (%.4g mm across), less than the %.4g of a "
                      "slender cable: kept as a solid part",
                      slenderness, 2 * tube->radius, options_.min_tube_aspect);
        drawing_->skipped.push_back(
            "'" + (body_style.name.empty() ? std::string("unnamed") : body_style.name) +
            "': " + line);
        tube.reset();
      }
    } else if (std::optional<DrawnCable> flat = FlatCable(body, body_style)) {
      drawing_->cables.push_back(std::move(*flat));
      return;
    }
    if (tube) {
      // A sweep approximated loosely (an early cablefit STEP writer's, ringing) is read at the
      // diameter most of it has; say that it is not one diameter throughout.
      if (tube->max_section_radius - tube->min_section_radius > 0.02 * tube->radius) {
        char line[240];
        std::snprintf(line, sizeof line,
                      "'%s': its cross-sections stray from %.4g mm across (%.4g to %.4g mm), a "
                      "loosely approximated sweep: read as a tube of %.4g mm",
                      body_style.name.empty() ? "unnamed" : body_style.name.c_str(),
                      2 * tube->radius, 2 * tube->min_section_radius, 2 * tube->max_section_radius,
                      2 * tube->radius);
        drawing_->warnings.push_back(line);
      }
      DrawnCable cable;
      cable.name = body_style.name;
      cable.centreline = ToPolyline(tube->centres);
      cable.diameter = 2 * tube->radius * kMetresPerOcctUnit;
      cable.inner_diameter = 2 * tube->inner_radius * kMetresPerOcctUnit;
      cable.shape = std::make_shared<const CadShapeHandle>(CadShapeHandle{body});
      cable.source = CableSourceKind::kTube;
      cable.fit_error = tube->rms_residual * kMetresPerOcctUnit;
      SetColor(&cable, body_style.color);
      record.is_cable = true;
      record.index = static_cast<int>(drawing_->cables.size());
      tubes_->push_back(std::move(record));
      drawing_->cables.push_back(std::move(cable));
      return;
    }
    DrawnSolid solid;
    solid.name = body_style.name;
    if (body_style.color) {
      solid.has_color = true;
      solid.color = *body_style.color;
    }
    solid.mesh = Tessellate(body, options_.mesh_relative_deflection);
    solid.shape = std::make_shared<const CadShapeHandle>(CadShapeHandle{body});
    if (record.centres.cols() > 0) {
      record.index = static_cast<int>(drawing_->solids.size());
      tubes_->push_back(std::move(record));
    }
    drawing_->solids.push_back(std::move(solid));
  }

  // A flat (ribbon) cable, or nullopt when `body` is no slender flat strip.
  std::optional<DrawnCable> FlatCable(const TopoDS_Shape& body, const Style& style) {
    FlatRecoveryOptions flat_options;
    flat_options.sample_spacing = options_.sample_spacing / kMetresPerOcctUnit;
    const std::optional<RecoveredFlat> flat = RecoverFlatStrip(body, flat_options);
    if (!flat) return std::nullopt;
    const double length = ChainLength(flat->centres);
    // A short flat strip is a plate or a box (a bracket, a block): a solid, without a note,
    // since such parts are common and nothing about them suggests a cable.
    if (length < options_.min_tube_aspect * flat->width) return std::nullopt;
    DrawnCable cable;
    cable.name = style.name;
    cable.centreline = ToPolyline(flat->centres);
    cable.diameter = flat->width * kMetresPerOcctUnit;
    FlatSection section;
    section.width = flat->width * kMetresPerOcctUnit;
    section.thickness = flat->thickness * kMetresPerOcctUnit;
    section.rounded_edges = flat->rounded_edges;
    section.wide_axes = flat->wide_axes;
    cable.flat = std::move(section);
    cable.shape = std::make_shared<const CadShapeHandle>(CadShapeHandle{body});
    cable.source = CableSourceKind::kTube;
    SetColor(&cable, style.color);
    return cable;
  }

  static void SetColor(DrawnCable* cable, const std::optional<SrgbColor>& color) {
    cable->has_color = color.has_value();
    if (color) cable->color = *color;
  }

  Handle(TDocStd_Document) doc_;
  Handle(XCAFDoc_ShapeTool) shapes_;
  const CadReadOptions& options_;
  HarnessDrawing* drawing_;
  std::vector<internal::DrawnTube>* tubes_;  // every tube recovered, cable or solid part
  std::vector<internal::LooseFaceGroup> loose_;  // the loose faces of every label
  std::vector<Style> loose_styles_;              // their labels' styles
};

// Distance from `p` to the segment a-b.
double SegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// A straight hollow tube with another cable running through its bore is a duct, sleeve or
// grommet the cable is held by, not a cable: it becomes a solid (and so a clip). A bent hollow
// tube around other cables (a conduit over a bundle) stays a cable.
void DemoteDucts(HarnessDrawing* drawing, double relative_deflection) {
  std::vector<DrawnCable>& cables = drawing->cables;
  std::vector<bool> duct(cables.size(), false);
  for (size_t i = 0; i < cables.size(); ++i) {
    const DrawnCable& tube = cables[i];
    if (tube.inner_diameter <= 0 || !tube.shape || tube.centreline.size() < 2) continue;
    const Vec3 a = tube.centreline.points.col(0);
    const Vec3 b = tube.centreline.points.col(tube.centreline.size() - 1);
    const double bore = 0.5 * tube.inner_diameter;
    bool straight = true;
    for (Eigen::Index k = 0; k < tube.centreline.points.cols() && straight; ++k) {
      straight = SegmentDistance(tube.centreline.points.col(k), a, b) < 0.5 * bore;
    }
    if (!straight) continue;
    for (size_t j = 0; j < cables.size() && !duct[i]; ++j) {
      if (j == i) continue;
      const Eigen::Matrix3Xd& p = cables[j].centreline.points;
      for (Eigen::Index k = 0; k < p.cols(); ++k) {
        const Vec3 q = p.col(k);
        // Through the bore, not only touching its end (a pipe elbow welded to it).
        const double along = (q - a).dot((b - a).normalized());
        if (along > bore && along < (b - a).norm() - bore && SegmentDistance(q, a, b) < bore) {
          duct[i] = true;
          break;
        }
      }
    }
  }
  std::vector<DrawnCable> kept;
  for (size_t i = 0; i < cables.size(); ++i) {
    if (!duct[i]) {
      kept.push_back(std::move(cables[i]));
      continue;
    }
    DrawnSolid solid;
    solid.name = cables[i].name;
    solid.has_color = cables[i].has_color;
    solid.color = cables[i].color;
    solid.mesh = Tessellate(cables[i].shape->shape, relative_deflection);
    solid.shape = cables[i].shape;
    drawing->solids.push_back(std::move(solid));
  }
  cables = std::move(kept);
}

// A cable's tube kept as a solid part instead (its name, colour and shape unchanged).
DrawnSolid SolidOfCable(const DrawnCable& cable, const CadReadOptions& options) {
  DrawnSolid solid;
  solid.name = cable.name;
  solid.has_color = cable.has_color;
  solid.color = cable.color;
  solid.mesh = Tessellate(cable.shape->shape, options.mesh_relative_deflection);
  solid.shape = cable.shape;
  return solid;
}

// A cable that its merges made stout (a conductor stub that took its insulation's diameter, a
// short route curve inside a thick sheath) is no more a cable than a tube that was stout to begin
// with: the rod model needs a slender piece, whichever way the cable was recognised (and the
// relaxed STEP, read back, must give the same cables: there it is a tube). Its tube, or the solid
// parts that were merged into a curve, stay as parts.
void DemoteStubs(const CadReadOptions& options, internal::AbsorbedTubes* absorbed,
                 HarnessDrawing* drawing) {
  const size_t cables = drawing->cables.size();
  for (size_t c = 0; c < cables; ++c) {
    const DrawnCable& cable = drawing->cables[c];
    const double length = cable.centreline.size() > 1 ? cable.centreline.s[cable.centreline.size() - 1] : 0;
    if (absorbed->CableMarked(c) || !(cable.diameter > 0) ||
        length >= options.min_tube_aspect * cable.diameter)
      continue;
    char line[200];
    std::snprintf(line, sizeof line,
                  "a %s %.1f diameters long (%.4g mm across), less than the %.4g of a slender "
                  "cable: kept as a solid part",
                  cable.shape ? "tube" : "cable drawn as a curve", length / cable.diameter,
                  1e3 * cable.diameter, options.min_tube_aspect);
    const std::string name = cable.name.empty() ? std::string("unnamed") : cable.name;
    if (cable.shape) drawing->solids.push_back(SolidOfCable(cable, options));
    absorbed->ReleaseSolidsOf(static_cast<int>(c));
    internal::DrawnTube self;
    self.is_cable = true;
    self.index = static_cast<int>(c);
    absorbed->Mark(self, "'" + name + "': " + line, drawing);
  }
}

// Straight hollow tubes fitted with flanges or pipe elbows are rigid pipes (FindRigidPipes): solid
// parts, like the fittings they are drawn with.
void DemoteRigidPipes(const CadReadOptions& options, internal::AbsorbedTubes* absorbed,
                      HarnessDrawing* drawing, const std::vector<internal::DrawnTube>& tubes) {
  for (const internal::RigidPipe& pipe : internal::FindRigidPipes(tubes, *absorbed, *drawing)) {
    const DrawnCable& cable = drawing->cables[static_cast<size_t>(pipe.cable)];
    drawing->solids.push_back(SolidOfCable(cable, options));
    internal::DrawnTube self;
    self.is_cable = true;
    self.index = pipe.cable;
    absorbed->Mark(self, pipe.why, drawing);
  }
}

// A part instanced many times (the profile sketch of every wire) would say the same thing once
// per instance: once, with the count.
void CollapseRepeatedLines(std::vector<std::string>* lines) {
  std::vector<std::string> order;
  std::map<std::string, int> count;
  for (const std::string& line : *lines)
    if (count[line]++ == 0) order.push_back(line);
  for (std::string& line : order) {
    if (const int n = count[line]; n > 1) line += " (" + std::to_string(n) + " times)";
  }
  *lines = std::move(order);
}

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
  const std::lock_guard<std::mutex> lock(OcctExchangeMutex());
  const ScopedOcctSignals signals;
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
  if (const int sig = signals.caught()) {
    throw FileError(path, std::string(iges ? "the IGES reader" : "the STEP reader") +
                              " crashed on this file (signal " + std::to_string(sig) + ": " +
                              ::strsignal(sig) + "); the file is corrupt");
  }
  return doc;
}

}  // namespace

HarnessDrawing ReadCadFile(const std::string& path, const CadReadOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw UsageError("CAD read options: " + why);
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
  if (options.probe_seconds > 0) {
    ProbeFileInChild(path, iges ? "the IGES reader" : "the STEP reader",
                     {"read", path, ExactText(options.sample_spacing),
                      ExactText(options.mesh_relative_deflection),
                      ExactText(options.min_tube_area_fraction),
                      ExactText(options.min_tube_aspect), ExactText(options.junction_tolerance)},
                     options.ProbeSecondsFor(std::filesystem::file_size(path, ec)));
  }
  return internal::ReadCadFileInThisProcess(path, options);
}

namespace internal {

HarnessDrawing ReadCadFileInThisProcess(const std::string& path, const CadReadOptions& options) {
  const std::string ext = Lower(std::filesystem::path(path).extension().string());
  const bool iges = ext == ".igs" || ext == ".iges";
  InitOcctSession();
  HarnessDrawing drawing;
  drawing.source_path = path;
  try {
    Handle(TDocStd_Document) doc = ReadDocument(path, iges, &drawing.length_unit);
    std::vector<DrawnTube> tubes;
    DrawingBuilder builder(doc, options, &drawing, &tubes);
    builder.WalkFreeShapes();
    const std::vector<int> moved = JoinCurvePieces(&drawing, options.junction_tolerance);
    for (DrawnTube& t : tubes)
      if (t.is_cable) t.index = moved[static_cast<size_t>(t.index)];
    AbsorbedTubes absorbed(drawing);
    MergeSweepsIntoCurves(tubes, &drawing, &absorbed);
    MergeCoresIntoFlatJackets(tubes, &drawing, &absorbed);
    MergeCoreTails(tubes, options.min_tube_aspect, options.junction_tolerance, &drawing, &absorbed);
    DemoteStubs(options, &absorbed, &drawing);
    DemoteRigidPipes(options, &absorbed, &drawing, tubes);
    KeepBreakoutBranches(tubes, options.junction_tolerance, &absorbed, &drawing);
    absorbed.RemoveFrom(&drawing);
  } catch (const Standard_Failure& e) {
    throw FileError(path, std::string("OCCT could not read the file: ") + e.GetMessageString());
  }
  DemoteDucts(&drawing, options.mesh_relative_deflection);
  NameCablesUniquely(&drawing);
  CollapseRepeatedLines(&drawing.skipped);
  if (drawing.cables.empty() && drawing.solids.empty()) {
    throw FileError(path, "the file contains no shapes");
  }
  if (drawing.cables.empty()) {
    std::string why = "no cable curves or tube solids found (" +
                      std::to_string(drawing.solids.size()) + " other solids)";
    if (!drawing.skipped.empty()) why += "; " + drawing.skipped.front();
    throw FileError(path, why);
  }
  FindJunctions(&drawing, options.junction_tolerance);
  return drawing;
}

}  // namespace internal
}  // namespace cablefit
