#include "cablefit/app/output/relax_envelope.h"

#include <filesystem>

#include "cablefit/app/base/provenance.h"
#include "cablefit/app/output/relax_file.h"
#include "cablefit/app/output/swept_envelope.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/gltf_file.h"
#include "cablefit/formats/stl_file.h"

namespace cablefit::addin {
namespace {

// Tubes in an envelope STEP at most.
constexpr size_t kMaxEnvelopeStepTubes = 300;

struct Shapes {
  int cable = 0;
  std::vector<Polyline> shapes;
};

EnvelopeFiles Write(const std::string& dir, const RelaxedFile& f, const HarnessConfig& config,
                    const std::string& kind, const std::vector<Shapes>& cables) {
  EnvelopeFiles out;
  out.kind = kind;
  out.stl = f.stem + "-" + kind + "-envelope.stl";
  out.glb = f.stem + "-" + kind + "-envelope.glb";
  out.step = f.stem + "-" + kind + "-envelope.step";
  TriangleMesh all;
  std::vector<GltfMesh> meshes;
  std::vector<std::vector<Polyline>> used;  // per cable, the shapes in its envelope
  for (const Shapes& c : cables) {
    const double radius = 0.5 * OutputDiameter(f, c.cable, config);
    EnvelopeFiles::Cable row;
    row.name = f.drawing.cables[static_cast<size_t>(c.cable)].name;
    row.shapes = static_cast<int>(c.shapes.size());
    std::vector<size_t> picked;
    TriangleMesh mesh = SweptEnvelope(c.shapes, radius, EnvelopeOptions{}, &picked);
    row.shapes_used = static_cast<int>(picked.size());
    used.emplace_back();
    for (size_t i : picked) used.back().push_back(c.shapes[i]);
    row.triangles = static_cast<long>(mesh.faces.cols());
    AppendMesh(mesh, &all);
    meshes.push_back({row.name, std::move(mesh)});
    out.cables.push_back(row);
  }
  const std::filesystem::path folder(dir);
  // Binary STL headers must not start with "solid".
  WriteStl((folder / out.stl).string(), all, "cablefit " + kind + " envelope of " + f.stem);
  WriteGlb((folder / out.glb).string(), meshes, ToolVersion());
  // For CAD the envelope as exact solids: per cable the tube of every shape the mesh used,
  // swept along its centreline as the relaxed tubes are (a faceted copy of the mesh was ~2 kB
  // of STEP per triangle: 28 MB for the door sample).
  HarnessDrawing tubes_only;
  tubes_only.cables = f.drawing.cables;
  std::vector<RelaxedCable> tubes;
  for (size_t k = 0; k < cables.size(); ++k)
    for (const Polyline& shape : used[k])
      tubes.push_back({cables[k].cable, shape, OutputDiameter(f, cables[k].cable, config)});
  std::vector<std::string> skipped;
  if (tubes.size() > kMaxEnvelopeStepTubes) {
    // Each tube is an OCCT sweep (~0.1 s): a 183-segment harness's tolerance envelope took
    // minutes for a file nobody opens whole.
    out.step.clear();
    out.step_problem = "not written: " + std::to_string(tubes.size()) + " tubes, more than " +
                       std::to_string(kMaxEnvelopeStepTubes) +
                       " (the STL and GLB hold the envelope)";
    return out;
  }
  try {
    WriteRelaxedStep((folder / out.step).string(), tubes_only, tubes, &skipped);
  } catch (const InvalidInput& e) {
    skipped.push_back(e.what());
  }
  if (!skipped.empty()) {
    out.step_problem = skipped.front();
    if (!std::filesystem::exists(folder / out.step)) out.step.clear();
  }
  return out;
}

}  // namespace

std::vector<EnvelopeFiles> WriteEnvelopeFiles(const std::string& dir, const RelaxedFile& f,
                                              const HarnessConfig& config) {
  std::vector<EnvelopeFiles> written;
  if (f.motion && !f.motion->cables.empty()) {
    std::vector<Shapes> cables;
    for (const CableMotion& m : f.motion->cables) {
      Shapes s{m.cable, {}};
      for (const MotionPose& p : m.poses)
        if (p.converged) s.shapes.push_back(p.centreline);
      if (!s.shapes.empty()) cables.push_back(std::move(s));
    }
    if (!cables.empty()) written.push_back(Write(dir, f, config, "motion", cables));
  }
  if (f.tolerance && !f.tolerance->cables.empty()) {
    std::vector<Shapes> cables;
    for (const CableTolerance& t : f.tolerance->cables) {
      const auto& nominal = f.cables[static_cast<size_t>(t.cable)];
      if (!nominal) continue;
      Shapes s{t.cable, {nominal->relaxed}};
      // The corners bound it; an interior check only adds where it went beyond them (each shape
      // is a solid in the STEP: a 30-segment harness's 8 interior checks were 240 more tubes).
      const double worst = t.worst_corner >= 0
                               ? t.corners[static_cast<size_t>(t.worst_corner)].excursion
                               : 0.0;
      for (const ToleranceCase& c : t.corners)
        if (c.converged && c.centreline.size() > 1) s.shapes.push_back(c.centreline);
      for (const ToleranceCase& c : t.interior)
        if (c.converged && c.centreline.size() > 1 && c.excursion > worst)
          s.shapes.push_back(c.centreline);
      cables.push_back(std::move(s));
    }
    if (!cables.empty()) written.push_back(Write(dir, f, config, "tolerance", cables));
  }
  return written;
}

}  // namespace cablefit::addin
