// One scan of a whole harness split onto its branches: each point goes to the branch whose
// surface (the current shape of its centreline, a tube of its radius) is nearest; points close
// to a junction, where branches meet and a point tells no branch, are left out. Each branch's
// points are then traced into its recorded centre line. Splitting along the nominal shape first
// and along the fitted one after is how the tool refines it.
#pragma once

#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/diagnosis/harness_diagnosis.h"
#include "cablefit/core/network/network_spec.h"

namespace cablefit::addin {

struct HarnessScanSplit {
  std::vector<PointCloud> branches;  // per branch: its points
  int left_out = 0;                  // points near junctions
};

/// Splits `scan` along `shapes` (per branch of `spec`: the centreline s [m], points 3 x n [m]).
HarnessScanSplit SplitHarnessScan(const PointCloud& scan, const NetworkSpec& spec,
                                  const std::vector<Polyline>& shapes);

/// The recorded centre points of each branch from its split points (a branch whose points
/// cannot be traced is left unseen and named in `problems`), their arc lengths along `shapes`.
HarnessObservation ObserveHarnessScan(const HarnessScanSplit& split, const NetworkSpec& spec,
                                      const std::vector<Polyline>& shapes,
                                      std::vector<std::string>* problems);

}  // namespace cablefit::addin
