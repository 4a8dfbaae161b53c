// A synthetic branched harness for benchmarks and tests: a trunk with breakouts, side branches
// (some splitting again) ending at clamped connectors, clips along every branch, drawn with a
// small droop between clips so it has slack to settle under gravity.
#pragma once

#include "cablefit/core/network/network_spec.h"

namespace cablefit::addin {

struct SyntheticHarnessSize {
  int trunk_segments = 10;  // breakouts on the trunk: trunk_segments - 1
  double clip_spacing = 0.29;  // [m] about one clip per this length of branch
};

/// 30 branches, 14 junctions and about 60 clips with the default size (17.6 m of cable).
NetworkSpec SyntheticHarness(const SyntheticHarnessSize& size = {});

/// A flat panel at height z under the x-y rectangle [lo, hi], tessellated into nx x ny cells of
/// two triangles each facing +z (an open sheet, like a body panel exported as a surface).
TriangleMesh FlatPanel(const Vec3& lo, const Vec3& hi, int nx, int ny);

/// Total drawn length [m].
double NetworkLength(const NetworkSpec& spec);

}  // namespace cablefit::addin
