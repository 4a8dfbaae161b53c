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

struct KblSizedHarnessSize {
  int segments = 183;  // nodes = segments + 1 (a tree, as a KBL harness is)
  int fixings = 16;    // one clip in the middle of every (segments / fixings)-th segment
  double min_length = 0.03, max_length = 0.35;  // [m] segment lengths, uniform
  /// Per cent of nodes that continue the previous one (a splice); the others branch off an
  /// earlier node with fewer than four segments (a breakout).
  int chain_percent = 10;
  /// Every segment built this fraction longer (+) or shorter (-) than drawn, as harness.json's
  /// "length": "+2%": the supports keep their drawn positions, their arc lengths scale.
  double length_change = 0.0;
};

/// A harness the size of the largest real KBL harness in use (183 segments, 184 nodes,
/// 16 fixings), generated deterministically: a tree whose every node of two or more segments
/// is a junction (splice or breakout) and whose every end node is clamped (a connector), with
/// bundle diameters of 3-12 mm. Built for `cablefit bench`.
NetworkSpec KblSizedHarness(const KblSizedHarnessSize& size = {});

/// A flat panel at height z under the x-y rectangle [lo, hi], tessellated into nx x ny cells of
/// two triangles each facing +z (an open sheet, like a body panel exported as a surface).
TriangleMesh FlatPanel(const Vec3& lo, const Vec3& hi, int nx, int ny);

/// Total drawn length [m].
double NetworkLength(const NetworkSpec& spec);

}  // namespace cablefit::addin
