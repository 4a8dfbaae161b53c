#include "cablefit/core/diagnosis/shape_effect.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace cablefit {
namespace {

// The names are the contract of diagnosis.json (recording-v1.md, the catalogue of effects).
TEST(ShapeEffectTest, NamesAreTheCatalogues) {
  const std::set<std::string> catalogue = {"none",
                                           "intrinsic_curvature",
                                           "clamp_orientation",
                                           "twist_preload",
                                           "weight_stiffness_ratio",
                                           "anisotropic_bending",
                                           "support_contact",
                                           "clamp_compliance"};
  std::set<std::string> names;
  for (ShapeEffect e : kAllShapeEffects) names.insert(ToString(e));
  EXPECT_EQ(names, catalogue);
}

TEST(ShapeEffectTest, NameRoundTrips) {
  for (ShapeEffect e : kAllShapeEffects) {
    const std::optional<ShapeEffect> back = ShapeEffectFromString(ToString(e));
    ASSERT_TRUE(back.has_value()) << ToString(e);
    EXPECT_EQ(*back, e);
  }
}

TEST(ShapeEffectTest, ForceEffectsAndUnknownNamesAreNotShapeEffects) {
  EXPECT_FALSE(ShapeEffectFromString("stiffness").has_value());
  EXPECT_FALSE(ShapeEffectFromString("hysteresis").has_value());
  EXPECT_FALSE(ShapeEffectFromString("").has_value());
  EXPECT_FALSE(ShapeEffectFromString("None").has_value());
}

}  // namespace
}  // namespace cablefit
