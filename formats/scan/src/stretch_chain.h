// Orders seen stretches into one cable from the first clamp to the last and gives them arc
// lengths, bridging gaps (and the unseen clamp regions) with cubic Hermite curves.
#pragma once

#include <optional>
#include <vector>

#include "cablefit/core/diagnosis/scan_centerline.h"
#include "cablefit/formats/scan_centerline_extractor.h"
#include "stretch.h"

namespace cablefit::scan {

/// Length [m] of the cubic Hermite curve from p0 to p1 (3 [m] each) with unit end tangents t0,
/// t1 scaled by the chord length (a "natural" bridge; exact for straight lines and close to a
/// circular arc for moderate turning).
double HermiteLength(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1,
                     const Eigen::Vector3d& t1);

/// Chains `stretches` greedily by the cheapest bridge (distance with penalties for turning),
/// starting at the guide's first clamp, or without a guide at the stretch end whose chain is
/// cheapest overall. Fills points, s, tangents, radius, support, stretch, coverage,
/// s_error_bound and estimated_length of `out`, and adds warnings. Throws InvalidInput when the
/// scan lies farther from a clamp than the cable is long.
void ChainStretches(const std::vector<Stretch>& stretches, const std::optional<ScanGuide>& guide,
                    double diameter, ScanCenterline* out);

}  // namespace cablefit::scan
