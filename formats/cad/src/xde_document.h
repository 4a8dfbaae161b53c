// Small helpers around OCCT's XDE (XCAF) documents: names and sRGB colours on labels, writing a
// document as STEP atomically. Shared by the writer and the sample tool.
#pragma once

#include <TDF_Label.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Shape.hxx>
#include <optional>
#include <string>

#include "cablefit/formats/harness_drawing.h"

namespace cablefit {

Handle(TDocStd_Document) NewXcafDocument();

/// The TDataStd_Name of `label`, or "" when it has none.
std::string LabelName(const TDF_Label& label);

/// The surface, generic or curve colour of `label` (first found) as sRGB.
std::optional<SrgbColor> LabelColor(const Handle(TDocStd_Document)& doc, const TDF_Label& label);

/// Adds `shape` as a top-level part with a name and (optional) sRGB surface colour.
TDF_Label AddNamedShape(const Handle(TDocStd_Document)& doc, const TopoDS_Shape& shape,
                        const std::string& name, const std::optional<SrgbColor>& color);

/// Writes `doc` as STEP with the given schema ("AP242DIS", "AP214IS", "AP203") in millimetres,
/// to a temporary file next to `path` that is then renamed over it. Throws FileError.
void WriteStepAtomically(const Handle(TDocStd_Document)& doc, const std::string& path,
                         const std::string& schema);

}  // namespace cablefit
