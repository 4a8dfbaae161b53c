// Clearance of relaxed cables (core/network/clearance.h) to the drawing's solids and to each
// other, checked against the min_clearance harness.json asks of the cables and the solids.
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/relax/relax_cable.h"
#include "cablefit/app/relax/relax_clips.h"
#include "cablefit/app/relax/relaxed_harness.h"
#include "cablefit/core/network/clearance.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

/// A cable as clearance sees it.
struct ClearanceCable {
  std::string name;
  const Polyline* centreline = nullptr;  ///< s [m], points 3 x n [m]; must outlive the call
  double radius = 0.0;                   ///< [m]
  double min_clearance = 0.0;            ///< [m] asked of this cable, 0 = none
  /// Solids holding one of its supports (a clip on them, an end in a ring): it rests on them.
  std::vector<std::string> clipped_to;
};

/// A solid as clearance sees it.
struct ClearanceSolid {
  std::string name;
  const SolidClearance* geometry = nullptr;  ///< must outlive the call
  double min_clearance = 0.0;                ///< [m] asked of this solid, 0 = none
};

/// One measured pair: a cable and a solid or another cable.
struct ClearancePair {
  std::string cable, other;
  bool other_is_solid = true;
  ClearanceHit hit;       ///< s and point on `cable`; other_s on `other` for cable pairs
  double required = 0.0;  ///< [m] the larger min_clearance of the two
  /// The cable rests on the solid (one of its supports lies in the solid's bounding box, or it
  /// touches it: clearance within kRestingFraction of its radius): contact there is intended.
  bool rests_on = false;
  bool violation() const { return !rests_on && required > 0 && hit.clearance < required; }
};

/// A clearance within this fraction of the cable's radius is contact (the contact solver holds
/// the surface at the solid to its accuracy, well inside this).
inline constexpr double kRestingFraction = 0.01;
/// Two cables whose ends meet (a breakout or splice: ends closer than the sum of their radii)
/// touch there by construction: this many times the sum of their radii of arc length from such
/// an end is left out of their clearance (two branches leaving at 30 degrees are apart by then).
inline constexpr double kJunctionSkipFactor = 4.0;

/// Every cable against every solid (with a surface); against the other cables, the pair with
/// its nearest other cable and every pair close enough to break the min_clearance asked of it
/// (a cable's least clearance is therefore always among the pairs). Pairs far apart are never
/// measured. Cables in the given order, each with its solids, then its pairs with later
/// cables. Deterministic.
std::vector<ClearancePair> MeasureClearances(const std::vector<ClearanceCable>& cables,
                                             const std::vector<ClearanceSolid>& solids);

/// Cable `r` with `centreline` (its relaxed one, or a moved pose's) as clearance sees it: its
/// radius, the min_clearance `config` asks, and the solids of `drawing` (boxes `boxes`, same
/// order) holding one of its supports at their drawn places.
ClearanceCable ClearanceCableOf(const CableRelaxation& r, const Polyline* centreline,
                                const HarnessDrawing& drawing,
                                const std::vector<OrientedBox>& boxes, const HarnessConfig& config);
/// One box per solid (empty for a solid without vertices), as ClearanceCableOf takes.
std::vector<OrientedBox> ClearanceBoxes(const HarnessDrawing& drawing);

/// Every relaxed cable of `h` (failed ones are left out) against its solids and the other
/// cables, with the min_clearance `config` asks of them.
std::vector<ClearancePair> MeasureHarnessClearances(const HarnessConfig& config,
                                                    const RelaxedHarness& h);

/// The JSON of one pair.
json::Json ClearancePairToJson(const ClearancePair& p);

/// "<cable> to solid '<other>': 8.2 mm, less than the 20 mm asked, at s=0.312 m (x, y, z) m".
std::string ClearanceViolationText(const ClearancePair& p);

}  // namespace cablefit::addin
