// Clearance: how far the surface of a relaxed cable (a tube of radius r around its centreline)
// stays from a solid and from another cable. A harness must keep its distance from hot,
// sharp or moving parts; the relax output flags the cables that come closer than asked.
// Cable to solid: the signed distance of every centreline sample to the solid's triangles
// (obstacle_distance.h; negative inside) minus r. The minimum of a polyline's distance to a
// plane is at a vertex, so against a flat face this is exact; against curved faces the samples
// (about one per millimetre in the relax output) bound the error by the sample spacing.
// Cable to cable: the exact distance between the two polylines (closest points of segments:
// Ericson, "Real-Time Collision Detection" (2005), sec. 5.1.9) minus both radii.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "cablefit/core/base/box_tree.h"
#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/network/network_spec.h"

namespace cablefit {

/// Where a cable comes closest to something.
struct ClearanceHit {
  /// [m] surface-to-surface distance; < 0 when they overlap; +infinity when nothing was measured.
  double clearance = std::numeric_limits<double>::infinity();
  double s = 0.0;             ///< [m] arc length on the cable
  Vec3 point = Vec3::Zero();  ///< [m] the centreline point there
  Vec3 other = Vec3::Zero();  ///< [m] the nearest point of the solid, or the other centreline
  double other_s = 0.0;       ///< [m] arc length on the other cable (cable pairs only)
  bool found() const { return clearance < std::numeric_limits<double>::infinity(); }
};

/// A solid prepared for many clearance queries (its triangles in a bounding-volume tree).
class SolidClearance {
 public:
  explicit SolidClearance(const TriangleMesh& mesh);
  ~SolidClearance();
  SolidClearance(SolidClearance&&) noexcept;
  SolidClearance& operator=(SolidClearance&&) noexcept;
  SolidClearance(const SolidClearance&) = delete;
  SolidClearance& operator=(const SolidClearance&) = delete;

  bool empty() const;
  /// Smallest clearance of the tube of `radius` [m] around `centreline` (s [m], points 3 x n
  /// [m]), checking the samples whose arc length is in [s_from, s_to].
  ClearanceHit ToTube(const Polyline& centreline, double radius, double s_from = 0.0,
                      double s_to = std::numeric_limits<double>::infinity()) const;

 private:
  struct Impl;
  Impl* impl_;
};

/// Smallest surface distance of tube a (radius ra [m]) to tube b (radius rb [m]), leaving out
/// the parts of a within `skip_a` [m] of arc length from a's start/end (the pairs {start, end}
/// skip nothing when 0): two cables joined at a breakout touch there by construction.
/// Result's s/point are on a, other_s/other on b.
struct TubeSkip {
  double start = 0.0, end = 0.0;  ///< [m] arc length left out at each end
};
ClearanceHit TubeToTubeClearance(const Polyline& a, double ra, const TubeSkip& skip_a,
                                 const Polyline& b, double rb, const TubeSkip& skip_b);

/// Many tubes indexed for clearance between them: runs of segments of every tube in one BoxTree,
/// so that the nearest other tube of each is found by
/// measuring only the segment pairs that could come closer than the best found so far, never
/// the pairs far apart. Answers as TubeToTubeClearance gives them pair by pair.
class TubeClearanceIndex {
 public:
  struct Tube {
    const Polyline* centreline = nullptr;  ///< s [m], points 3 x n [m]; must outlive the index
    double radius = 0.0;                   ///< [m]
  };
  /// What TubeToTubeClearance leaves out of tube `a` in its pair with tube `b`.
  using PairSkip = std::function<TubeSkip(int a, int b)>;

  explicit TubeClearanceIndex(std::vector<Tube> tubes);

  /// The other tube whose surface comes closest to tube `i`'s, -1 when none can be measured;
  /// `clearance` [m] (optional) receives the pair's TubeToTubeClearance. Ties go to the lower
  /// index.
  int Nearest(int i, const PairSkip& skip, double* clearance = nullptr) const;
  /// The other tubes whose surfaces may come within `reach` [m] of tube `i`'s (a superset:
  /// their boxes do), in increasing order.
  std::vector<int> Within(int i, double reach) const;

 private:
  struct IndexedRun {
    int tube = 0, begin = 0, end = 0;  // segments [begin, end) of that tube's centreline
  };
  std::vector<Tube> tubes_;
  std::vector<IndexedRun> runs_;            // the BoxTree's primitives
  std::vector<Eigen::AlignedBox3d> boxes_;  // each run's box, grown by its tube's radius
  double widest_ = 0.0;                        // [m] the largest radius
  BoxTree tree_;
};

/// Closest points of segments [p0, p1] and [q0, q1]: parameters (s, t) in [0, 1]^2.
void ClosestSegmentParameters(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1,
                              double* s, double* t);

}  // namespace cablefit
