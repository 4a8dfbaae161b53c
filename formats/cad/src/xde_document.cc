#include "xde_document.h"

#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_AsciiString.hxx>
#include <TCollection_ExtendedString.hxx>
#include <TDataStd_Name.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"
#include "occt_session.h"

namespace cablefit {

Handle(TDocStd_Document) NewXcafDocument() {
  InitOcctSession();
  Handle(TDocStd_Document) doc;
  // The application is a process-wide singleton.
  const std::lock_guard<std::mutex> lock(OcctExchangeMutex());
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  return doc;
}

std::string LabelName(const TDF_Label& label) {
  Handle(TDataStd_Name) name;
  if (label.IsNull() || !label.FindAttribute(TDataStd_Name::GetID(), name)) return "";
  return TCollection_AsciiString(name->Get()).ToCString();
}

std::optional<SrgbColor> LabelColor(const Handle(TDocStd_Document)& doc, const TDF_Label& label) {
  if (label.IsNull()) return std::nullopt;
  Handle(XCAFDoc_ColorTool) colors = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  Quantity_Color color;
  for (XCAFDoc_ColorType type : {XCAFDoc_ColorSurf, XCAFDoc_ColorGen, XCAFDoc_ColorCurv}) {
    if (colors->GetColor(label, type, color)) {
      SrgbColor c;
      // STEP stores sRGB; Quantity_TOC_RGB would be linear (docs/stack.md, OCCT traps).
      color.Values(c.r, c.g, c.b, Quantity_TOC_sRGB);
      return c;
    }
  }
  return std::nullopt;
}

TDF_Label AddNamedShape(const Handle(TDocStd_Document)& doc, const TopoDS_Shape& shape,
                        const std::string& name, const std::optional<SrgbColor>& color) {
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const TDF_Label label = shapes->AddShape(shape, /*makeAssembly=*/false);
  const TCollection_ExtendedString text(name.c_str(), /*isMultiByte=*/true);
  TDataStd_Name::Set(label, text);
  // A located shape (a solid copied from an input assembly) is added as an instance of an
  // unnamed product, and readers take the product's name ("1", "2"...): name it too.
  TDF_Label product;
  if (XCAFDoc_ShapeTool::IsReference(label) && XCAFDoc_ShapeTool::GetReferredShape(label, product))
    TDataStd_Name::Set(product, text);
  if (color) {
    XCAFDoc_DocumentTool::ColorTool(doc->Main())
        ->SetColor(label, Quantity_Color(color->r, color->g, color->b, Quantity_TOC_sRGB),
                   XCAFDoc_ColorSurf);
  }
  return label;
}

void WriteStepAtomically(const Handle(TDocStd_Document)& doc, const std::string& path,
                         const std::string& schema) {
  InitOcctSession();
  AtomicFile file(path);
  const std::lock_guard<std::mutex> lock(OcctExchangeMutex());
  // The schema must be set before the writer is constructed (docs/stack.md, OCCT traps).
  Interface_Static::SetCVal("write.step.schema", schema.c_str());
  Interface_Static::SetCVal("write.step.unit", "MM");
  bool ok = false;
  try {
    STEPCAFControl_Writer writer;
    writer.SetNameMode(true);
    writer.SetColorMode(true);
    ok = writer.Transfer(doc, STEPControl_AsIs) &&
         writer.Write(file.temp_path().string().c_str()) == IFSelect_RetDone;
  } catch (const Standard_Failure& e) {
    throw FileError(path, std::string("STEP writer failed: ") + e.GetMessageString());
  }
  if (!ok) throw FileError(path, "could not write STEP (directory not writable?)");
  file.Commit();
}

}  // namespace cablefit
