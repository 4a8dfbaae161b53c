#include "cablefit/app/output/output_files.h"

namespace cablefit::addin {

std::vector<std::string> EnvelopeFileNames(const std::string& stem) {
  std::vector<std::string> names;
  for (const char* kind : {"motion", "tolerance"})
    for (const char* ext : {".stl", ".glb", ".step"})
      names.push_back(stem + "-" + kind + "-envelope" + ext);
  return names;
}

json::Json EnvelopeFilesToJson(const std::vector<EnvelopeFiles>& files) {
  json::Json out = json::Json::array();
  for (const EnvelopeFiles& e : files) {
    json::Json cables = json::Json::array();
    for (const EnvelopeFiles::Cable& c : e.cables)
      cables.push_back({{"name", c.name},
                        {"shapes", c.shapes},
                        {"shapes_used", c.shapes_used},
                        {"triangles", c.triangles}});
    out.push_back(
        {{"kind", e.kind},
         {"stl", e.stl},
         {"glb", e.glb},
         {"step", e.step.empty() ? json::Json(nullptr) : json::Json(e.step)},
         {"step_problem", e.step_problem.empty() ? json::Json(nullptr) : json::Json(e.step_problem)},
         {"cables", cables},
         {"construction",
          e.kind == "motion"
              ? "union of the closed tube surfaces of every converged pose (a pose repeating an "
                "earlier one within 1e-6 m left out), overlapping shells in one mesh; nothing "
                "between poses"
              : "union of the closed tube surfaces of the nominal shape, every converged "
                "corner and any interior check that went further than the corners, overlapping "
                "shells in one mesh"}});
  }
  return out;
}

std::string MotionFramesFolder(const std::string& stem) { return stem + "-motion-frames"; }

}  // namespace cablefit::addin
