// WriteRelaxedStep: relaxed centrelines as swept tubes, input solids copied, STEP AP242.
#include <BRepBuilderAPI_MakeWire.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>

#include "cablefit/core/errors.h"
#include "cablefit/formats/cad_file.h"
#include "cad_shape_handle.h"
#include "occt_session.h"
#include "occt_tube.h"
#include "xde_document.h"

namespace cablefit {

void WriteRelaxedStep(const std::string& path, const HarnessDrawing& input,
                      const std::vector<RelaxedCable>& cables) {
  Handle(TDocStd_Document) doc = NewXcafDocument();
  for (const RelaxedCable& relaxed : cables) {
    if (relaxed.source_cable < 0 || relaxed.source_cable >= static_cast<int>(input.cables.size())) {
      throw InvalidInput("relaxed cable refers to input cable " +
                         std::to_string(relaxed.source_cable) + " of " +
                         std::to_string(input.cables.size()));
    }
    const DrawnCable& drawn = input.cables[relaxed.source_cable];
    const double diameter = relaxed.diameter > 0 ? relaxed.diameter : drawn.diameter;  // [m]
    if (!(diameter > 0)) {
      throw InvalidInput("cable '" + drawn.name + "': no diameter (drawn as a curve; set one)");
    }
    try {
      const Eigen::Matrix3Xd points = relaxed.centreline.points / kMetresPerOcctUnit;  // 3 x n [mm]
      // Approximation tolerance well below the 1 %-of-diameter accuracy promised for read-back.
      const double tolerance = std::min(0.01, 1e-3 * diameter / kMetresPerOcctUnit);  // [mm]
      const TopoDS_Wire spine =
          BRepBuilderAPI_MakeWire(MakeSplineEdge(points, tolerance)).Wire();
      const TopoDS_Shape tube = MakeTubeSolid(spine, diameter / kMetresPerOcctUnit);
      AddNamedShape(doc, tube, drawn.name,
                    drawn.has_color ? std::optional<SrgbColor>(drawn.color) : std::nullopt);
    } catch (const InvalidInput& e) {
      throw InvalidInput("cable '" + drawn.name + "': " + e.what());
    } catch (const Standard_Failure& e) {
      throw InvalidInput("cable '" + drawn.name + "': " + e.GetMessageString());
    }
  }
  for (const DrawnSolid& solid : input.solids) {
    if (!solid.shape) continue;  // not from CAD (e.g. a mesh input): nothing to copy
    AddNamedShape(doc, solid.shape->shape, solid.name,
                  solid.has_color ? std::optional<SrgbColor>(solid.color) : std::nullopt);
  }
  WriteStepAtomically(doc, path, "AP242DIS");
}

}  // namespace cablefit
