#include "cablefit/core/rod/rod_spec.h"

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/recording_case.h"

namespace cablefit {

const char* ToString(SupportKind kind) {
  switch (kind) {
    case SupportKind::kClamp: return "clamp";
    case SupportKind::kClip: return "clip";
    case SupportKind::kPin: return "pin";
  }
  return "?";
}

SupportKind SupportKindFromString(const std::string& name) {
  if (name == "clamp") return SupportKind::kClamp;
  if (name == "clip") return SupportKind::kClip;
  if (name == "pin") return SupportKind::kPin;
  throw InvalidInput("unknown support kind '" + name + "' (expected clamp, clip or pin)");
}

const char* ToString(RecordingKind kind) {
  switch (kind) {
    case RecordingKind::kScan: return "scan";
    case RecordingKind::kCenterline: return "centerline";
    case RecordingKind::kForceCurve: return "force_curve";
  }
  return "?";
}

const char* ToString(ForceTestType type) {
  switch (type) {
    case ForceTestType::kPinnedBending: return "pinned_bending";
    case ForceTestType::kClampedTorsion: return "clamped_torsion";
  }
  return "?";
}

}  // namespace cablefit
