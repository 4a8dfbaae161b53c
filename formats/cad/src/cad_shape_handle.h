// The definition behind the opaque CadShapeHandle of harness_drawing.h (CAD adapter only).
#pragma once

#include <TopoDS_Shape.hxx>

#include "cablefit/formats/harness_drawing.h"

namespace cablefit {

struct CadShapeHandle {
  TopoDS_Shape shape;  // located, in OCCT's working unit (millimetres)
};

}  // namespace cablefit
