// The centreline recovered from a laser scan of a cable's outer surface: the neutral result of
// formats/scan (ExtractScanCenterline) that the diagnosis compares with simulated curves.
// Eigen only. Gaps are explicit (`coverage`) so nobody mistakes an unseen stretch for a deviation.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cablefit {

/// An arc-length interval [s_start, s_end] of the cable that the scan actually saw.
struct ScanCoverageInterval {
  double s_start = 0.0;  // [m]
  double s_end = 0.0;    // [m]
};

struct ScanCenterline {
  /// Centre points ordered from the first clamp to the last (seen stretches only).
  Eigen::Matrix3Xd points;    // 3 x n [m]
  /// Estimated arc length from the first clamp; gaps are bridged (see s_error_bound).
  Eigen::VectorXd s;          // n [m]
  /// Unit axis tangents, pointing towards increasing s.
  Eigen::Matrix3Xd tangents;  // 3 x n [-]
  /// Free-radius circle fit per sample (NaN where the visible arc is too short to tell).
  Eigen::VectorXd radius;     // n [m]
  /// Scan points that support each centre (inliers of its slice fit).
  Eigen::VectorXi support;    // n [-]
  /// Index of the seen stretch (coverage interval) each sample belongs to.
  Eigen::VectorXi stretch;    // n [-]
  /// Robust scan noise (1.4826 * MAD of the radial residuals of the local circle fits).
  double noise_sigma = 0.0;   // [m]
  /// Scan points used by no fit (statistical outliers, fit outliers, stray clusters).
  int outlier_count = 0;
  /// Scan points in total.
  int point_count = 0;
  /// Seen stretches in increasing s; everything between them is a gap.
  std::vector<ScanCoverageInterval> coverage;
  /// Bound on the error of `s` from bridging gaps and the clamp regions [m].
  double s_error_bound = 0.0;
  /// Estimated total cable length (seen + bridged, clamp to clamp when a guide was given) [m].
  double estimated_length = 0.0;
  /// Human-readable quality remarks (short lines); empty when nothing is suspicious.
  std::vector<std::string> warnings;

  int size() const { return static_cast<int>(points.cols()); }
};

}  // namespace cablefit
