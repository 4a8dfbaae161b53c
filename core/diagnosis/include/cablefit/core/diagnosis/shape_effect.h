// The catalogue of shape effects (recording-v1.md, "The catalogue of effects") as a type. The
// catalogue names are the contract of diagnosis.json and the command line; they are spelled in
// one place, ToString / ShapeEffectFromString.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace cablefit {

enum class ShapeEffect {
  kNone,
  kIntrinsicCurvature,
  kClampOrientation,
  kWeightStiffnessRatio,
  kAnisotropicBending,
  kSupportContact,
  kTwistPreload,
  kClampCompliance,
};

inline constexpr std::array<ShapeEffect, 8> kAllShapeEffects = {
    ShapeEffect::kNone,           ShapeEffect::kIntrinsicCurvature,
    ShapeEffect::kClampOrientation, ShapeEffect::kWeightStiffnessRatio,
    ShapeEffect::kAnisotropicBending, ShapeEffect::kSupportContact,
    ShapeEffect::kTwistPreload,   ShapeEffect::kClampCompliance};

/// The catalogue name ("none", "intrinsic_curvature", ...).
const char* ToString(ShapeEffect effect);

/// The effect of a catalogue name; nullopt for a name the shape catalogue does not have.
std::optional<ShapeEffect> ShapeEffectFromString(std::string_view name);

}  // namespace cablefit
