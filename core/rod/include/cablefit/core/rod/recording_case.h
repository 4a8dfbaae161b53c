// A test-bench recording case (recording-v1.md): the nominal set-up plus what was recorded.
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/rod/rod_spec.h"

namespace cablefit {

enum class RecordingKind { kScan, kCenterline, kForceCurve };
const char* ToString(RecordingKind kind);

enum class ForceTestType { kPinnedBending, kClampedTorsion };
const char* ToString(ForceTestType type);

struct ForceTestSpec {
  ForceTestType type = ForceTestType::kPinnedBending;
  double prebend = 0.0;           // [m] pinned_bending: end shortening where recording starts
  double max_displacement = 0.0;  // [m] pinned_bending
  double max_angle = 0.0;         // [rad] clamped_torsion
};

/// A recorded quasi-static force curve (recording-v1: `step,displacement,force` for bending or
/// `step,angle,moment` for torsion), rows in recorded order (loading, then unloading).
struct ForceCurve {
  std::string x_name;       // "displacement" [m] or "angle" [rad]
  std::string y_name;       // "force" [N] or "moment" [N m]
  std::vector<long> step;   // n, as recorded
  Eigen::VectorXd x;        // n
  Eigen::VectorXd y;        // n
  int size() const { return static_cast<int>(x.size()); }
};

struct RecordingRef {
  RecordingKind kind = RecordingKind::kScan;
  std::string file;       // as written in case.json (relative to the case file)
  std::string path;       // resolved path
  ForceTestSpec test;     // force_curve only
};

struct RecordingCase {
  std::string name;
  std::string case_file;  // path of case.json
  RodSpec nominal;        // cable, gravity, clamps (as supports)
  std::vector<RecordingRef> recordings;
};

}  // namespace cablefit
