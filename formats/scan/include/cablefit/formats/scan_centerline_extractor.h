// Laser scan of a cable's outer surface -> ordered centreline with arc length, coverage and noise.
//
// Method (see scan_centerline_extractor.cc): statistical k-NN outlier removal; the tube is traced
// slice by slice (local PCA seed axis, then a robust known-radius circle fit to the visible arc
// in each slice perpendicular to the current axis, predicting the next slice along the tangent);
// traced stretches are chained from the first clamp (or the most plausible end) with Hermite
// bridges across gaps, and s is the chord length of the lightly smoothed centres plus bridges.
#pragma once

#include <optional>
#include <string>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/rod/rod_spec.h"
#include "cablefit/core/diagnosis/scan_centerline.h"

namespace cablefit {

/// Nominal clamp poses at both ends and the cable length: orients the result and anchors s.
struct ScanGuide {
  Vec3 start_position = Vec3::Zero();  // [m] first clamp (s = 0)
  Vec3 start_tangent = Vec3::UnitX();  // [-] direction of increasing s, need not be unit
  Vec3 end_position = Vec3::Zero();    // [m] last clamp (s = length)
  Vec3 end_tangent = Vec3::UnitX();    // [-] direction of increasing s, need not be unit
  double length = 0.0;                 // [m] nominal cable length, 0 = unknown

  /// The supports with the smallest and largest s. Throws InvalidInput with fewer than two.
  static ScanGuide FromRodSpec(const RodSpec& spec);
};

struct ScanCenterlineOptions {
  /// Cable diameter [m] (case.json), required: a partial arc fixes the centre only when the
  /// radius is known. The per-sample free radius is reported to check it.
  double diameter = 0.0;
  /// Distance between centre samples [m]; 0 = automatic (from diameter and point spacing).
  double step = 0.0;
  /// Neighbours for the statistical outlier test.
  int outlier_neighbours = 12;
  /// A point is a statistical outlier when its mean k-NN distance exceeds this many robust
  /// standard deviations above the median.
  double outlier_threshold = 6.0;
  /// Slice fit residuals beyond this many noise sigmas are outliers of that fit.
  double residual_cutoff = 3.5;
  /// Traced stretches shorter than this many diameters are treated as stray clusters.
  double min_stretch_diameters = 2.0;

  /// True when usable; otherwise `why` (if given) says which field is wrong.
  bool IsValid(std::string* why) const;
};

/// Extracts the centreline of the scanned cable. `guide` (optional) orders the result from the
/// first clamp and offsets s; without it s starts at the first seen centre of the most
/// plausible end. Throws InvalidInput for unusable scans (empty, too few points, nothing
/// tube-like, or a scan nowhere near the guide's clamps).
ScanCenterline ExtractScanCenterline(const PointCloud& scan, const ScanCenterlineOptions& options,
                                     const std::optional<ScanGuide>& guide = std::nullopt);

}  // namespace cablefit
