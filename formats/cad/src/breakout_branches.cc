#include "breakout_branches.h"

#include <algorithm>

namespace cablefit::internal {
namespace {

bool EndNear(const Eigen::Matrix3Xd& q, const Vec3& p, double tolerance) {
  return q.cols() >= 2 &&
         ((q.col(0) - p).norm() <= tolerance || (q.col(q.cols() - 1) - p).norm() <= tolerance);
}

}  // namespace

void KeepBreakoutBranches(const std::vector<DrawnTube>& tubes, double tolerance,
                          AbsorbedTubes* absorbed, HarnessDrawing* drawing) {
  // Tubes kept as parts for their slenderness alone (they carry that line).
  std::vector<const DrawnTube*> stout;
  for (const DrawnTube& tube : tubes)
    if (!tube.is_cable && tube.skipped_note >= 0 && tube.centres.cols() >= 2 && !absorbed->Marked(tube))
      stout.push_back(&tube);
  std::vector<DrawnCable> branches;
  std::vector<const DrawnTube*> promoted;
  for (const DrawnTube* tube : stout) {
    const double reach = std::max(tolerance, 0.05 * tube->radius);
    // Its neighbours: cables, and other stout segments (a node where every segment is short).
    bool joined = false;
    const Vec3 ends[] = {tube->centres.col(0), tube->centres.col(tube->centres.cols() - 1)};
    for (const Vec3& end : ends) {
      for (size_t c = 0; c < drawing->cables.size() && !joined; ++c)
        joined = !(c < absorbed->CableCount() && absorbed->CableMarked(c)) &&
                 EndNear(drawing->cables[c].centreline.points, end, reach);
      for (const DrawnTube* other : stout)
        joined = joined || (other != tube && EndNear(other->centres, end, reach));
    }
    if (!joined) continue;
    const DrawnSolid& solid = drawing->solids[static_cast<size_t>(tube->index)];
    DrawnCable cable;
    cable.name = solid.name;
    cable.has_color = solid.has_color;
    cable.color = solid.color;
    cable.centreline.points = tube->centres;
    cable.centreline.ParameteriseByChords(0.0);
    cable.diameter = 2 * tube->radius;
    cable.inner_diameter = 2 * tube->inner_radius;
    cable.source = CableSourceKind::kTube;
    cable.fit_error = tube->fit_error;
    cable.shape = solid.shape;
    branches.push_back(std::move(cable));
    promoted.push_back(tube);
  }
  // Dropped after the loop: every stout tube is judged against the same neighbours.
  for (const DrawnTube* tube : promoted) absorbed->Drop(*tube, drawing);
  for (DrawnCable& c : branches) drawing->cables.push_back(std::move(c));
}

}  // namespace cablefit::internal
