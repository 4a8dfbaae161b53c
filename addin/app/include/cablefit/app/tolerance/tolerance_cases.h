// What a tolerance envelope found: the varied set-ups of each cable and how far each one's shape
// went (relax_tolerance.h runs them; tolerance_search decides which to solve).
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/core/base/geometry_types.h"

namespace cablefit::addin {

/// One varied set-up of a cable, and how far its shape went.
struct ToleranceCase {
  double length = 0.0, bending_stiffness = 0.0, linear_density = 0.0;  ///< signed fractions
  std::vector<double> clip_shift;  ///< [m] per CableTolerance::clip_s, + = further along
  bool converged = false;
  /// False when the set-up cannot exist (a stretch shorter than its supports' distance): a
  /// harness that cannot be built, outside the envelope rather than missing from it.
  bool buildable = true;
  std::string why;  ///< why it was not solved (cannot be built, or the solver's failure)
  /// [m] the farthest any point of the varied cable is from the nominal cable (as a curve:
  /// how far outside the nominal place it can be, whatever slides along it)
  double excursion = 0.0;
  double s = 0.0;             ///< [m] arc length of the nominal cable's point nearest to it
  Vec3 point = Vec3::Zero();  ///< [m] the varied cable's point farthest out
  Polyline centreline;        ///< the varied relaxed shape (s [m], 3 x n [m]); empty if not converged
};

struct CableTolerance {
  int cable = 0;
  std::string name;
  /// The supports between the cable's ends whose place on it is varied: nominal arc length
  /// [m], the shifts at the box's corners [m] (-back, +ahead: the tolerance asked, less where
  /// the cable to a neighbouring support is short (45 % of it at most) or nearly taut (90 % of
  /// its slack at the shortest length, shared with a neighbour that moves too)), and where the
  /// support comes from.
  std::vector<double> clip_s;
  std::vector<std::array<double, 2>> clip_range;
  std::vector<std::string> clip_origin;
  std::vector<ToleranceCase> corners, interior;
  int worst_corner = -1;        ///< index into corners, -1 when none converged
  bool interior_within = true;  ///< no interior case went further than the worst corner
  int quantities = 0;           ///< varied quantities of the solve (the network's for a network)
  bool all_corners = true;      ///< every corner solved, else chosen by sensitivity
  int sensitivity_solves = 0;   ///< solves spent on sensitivities (0 with all corners)
  std::string network;          ///< the network's cables when solved as one, else empty
  int elements = 0;             ///< a network's elements (solved at one level, not refined)
  /// [m] a network's: the nominal at that level against the refined relax (NaN otherwise)
  double resolution_error = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;
};

struct FileTolerance {
  ToleranceConfig config;
  std::vector<CableTolerance> cables;
  std::vector<std::string> problems;  ///< cables not varied, and why; tolerances cut short
};

/// Varied quantities beyond which corners are chosen by sensitivity (2^6 = 64 solves).
inline constexpr int kExhaustiveQuantities = 6;
/// Corners solved at most when chosen by sensitivity (pairs of opposites).
inline constexpr int kChosenCorners = 32;
/// Pseudo-random interior points of the box solved to check the corners cover it.
inline constexpr int kInteriorChecks = 8;

}  // namespace cablefit::addin
