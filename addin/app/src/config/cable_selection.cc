#include "cablefit/app/config/cable_selection.h"

#include <string>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/mesh_file.h"

namespace cablefit::addin {

void ApplyCableSelection(const HarnessConfig& config, HarnessDrawing* drawing) {
  if (config.rigid.empty() && config.only.empty()) return;
  std::vector<int> new_index(drawing->cables.size(), -1);
  std::vector<DrawnCable> kept;
  for (size_t i = 0; i < drawing->cables.size(); ++i) {
    DrawnCable& cable = drawing->cables[i];
    const std::string why = config.RigidReason(cable.name);
    if (why.empty()) {
      new_index[i] = static_cast<int>(kept.size());
      kept.push_back(std::move(cable));
      continue;
    }
    if (cable.diameter > 0 && cable.centreline.size() >= 2) {
      DrawnSolid solid;
      solid.name = cable.name;
      solid.has_color = cable.has_color;
      solid.color = cable.color;
      solid.mesh = SweepTubeMesh(cable.centreline, cable.diameter);
      solid.shape = cable.shape;
      drawing->solids.push_back(std::move(solid));
      drawing->skipped.push_back("'" + cable.name + "': " + why + ", kept as a solid");
    } else {
      drawing->skipped.push_back("'" + cable.name + "': " + why +
                                 ", a bare curve with no body: left out");
    }
  }
  if (kept.empty()) {
    throw FileError(drawing->source_path,
                    "no cable left to relax: harness.json's \"rigid\"/\"only\" make all " +
                        std::to_string(drawing->cables.size()) + " of them rigid parts");
  }
  drawing->cables = std::move(kept);
  std::vector<CableJunction> junctions;
  for (CableJunction j : drawing->junctions) {
    std::vector<CableJunction::End> ends;
    for (CableJunction::End e : j.ends) {
      e.cable = new_index[static_cast<size_t>(e.cable)];
      if (e.cable >= 0) ends.push_back(e);
    }
    if (ends.size() < 2) continue;
    j.ends = std::move(ends);
    junctions.push_back(std::move(j));
  }
  drawing->junctions = std::move(junctions);
}

}  // namespace cablefit::addin
