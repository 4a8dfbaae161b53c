#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cablefit/formats/harness_drawing.h"

namespace cablefit::internal {

/// A tube recovered from a solid while reading, whether it became a cable or stayed a solid
/// part (too short to be a cable on its own).
struct DrawnTube {
  bool is_cable = false;     ///< index is into HarnessDrawing::cables, else into ::solids
  int index = 0;
  int skipped_note = -1;     ///< the HarnessDrawing::skipped line that said why it is a solid
  Eigen::Matrix3Xd centres;  ///< 3 x n [m], along the tube
  double radius = 0.0;       ///< [m] outer
  double inner_radius = 0.0; ///< [m] bore, 0 for a solid tube
  double fit_error = 0.0;    ///< [m] RMS residual of the cross-section circle fits
};

/// Tubes found to be part of another cable (a sweep around its route, a core in its flat
/// jacket): each marked with the line that says why, then all removed from the drawing at once
/// (indices stay valid while marking).
class AbsorbedTubes {
 public:
  explicit AbsorbedTubes(const HarnessDrawing& drawing)
      : cable_(drawing.cables.size(), 0),
        solid_(drawing.solids.size(), 0),
        solid_owner_(drawing.solids.size(), -1) {}
  bool CableMarked(size_t cable) const { return cable_[cable] != 0; }
  size_t CableCount() const { return cable_.size(); }
  bool Marked(const DrawnTube& tube) const {
    const std::vector<char>& marks = tube.is_cable ? cable_ : solid_;
    const size_t index = static_cast<size_t>(tube.index);
    return index < marks.size() && marks[index] != 0;
  }
  /// Replaces the tube's own skipped line (why it was a solid) by `why`, or adds one.
  /// `owner` is the index of the cable it became part of (-1: none).
  void Mark(const DrawnTube& tube, const std::string& why, HarnessDrawing* drawing,
            int owner = -1);
  /// Solid parts marked as part of cable `owner` stay in the drawing after all (that cable
  /// turned out to be no cable).
  void ReleaseSolidsOf(int owner);
  /// The solid part leaves the drawing without a line (it was taken as a cable after all); its
  /// own skipped line is emptied (RemoveFrom drops empty lines).
  void Drop(const DrawnTube& tube, HarnessDrawing* drawing);
  void RemoveFrom(HarnessDrawing* drawing) const;

 private:
  std::vector<char> cable_, solid_;
  std::vector<int> solid_owner_;
};

/// CAD tools that draw a cable as a route curve plus the solid swept along it (conductor,
/// insulation, sheath) leave the same cable twice: a curve without diameter and a tube around
/// it, which would otherwise be a second cable or an obstacle the curve lies inside. A tube
/// whose every centre lies on a bare curve is taken as that curve's body: the curve gets its
/// diameter (and colour when it has none) and the tube leaves the drawing, with a line in
/// `skipped` saying so. A hollow tube counts as body only when it sits on a matched core or
/// covers most of the curve (a hose); a short hollow tube alone is a duct or grommet and stays.
/// With `absorbed` the tubes are only marked there (the caller removes them after its other
/// merges, so that every merge sees the same indices); without, they are removed here.
void MergeSweepsIntoCurves(const std::vector<DrawnTube>& tubes, HarnessDrawing* drawing,
                           AbsorbedTubes* absorbed = nullptr);

}  // namespace cablefit::internal
