#include "cablefit/core/diagnosis/shape_effect.h"

namespace cablefit {

const char* ToString(ShapeEffect effect) {
  switch (effect) {
    case ShapeEffect::kNone:
      return "none";
    case ShapeEffect::kIntrinsicCurvature:
      return "intrinsic_curvature";
    case ShapeEffect::kClampOrientation:
      return "clamp_orientation";
    case ShapeEffect::kWeightStiffnessRatio:
      return "weight_stiffness_ratio";
    case ShapeEffect::kAnisotropicBending:
      return "anisotropic_bending";
    case ShapeEffect::kSupportContact:
      return "support_contact";
    case ShapeEffect::kTwistPreload:
      return "twist_preload";
    case ShapeEffect::kClampCompliance:
      return "clamp_compliance";
  }
  return "none";
}

std::optional<ShapeEffect> ShapeEffectFromString(std::string_view name) {
  for (ShapeEffect e : kAllShapeEffects)
    if (name == ToString(e)) return e;
  return std::nullopt;
}

}  // namespace cablefit
