#include "effect_combination.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "two_clamp_setup.h"

namespace cablefit {
namespace {

using testing::TwoClamps;

std::vector<EffectModel> Models(const RodSpec& nominal) {
  return testing::StraightRecordingModels(nominal, {0.01, 0.01});
}

int IndexOf(const std::vector<EffectModel>& models, ShapeEffect effect, int clamp = 0) {
  for (size_t i = 0; i < models.size(); ++i)
    if (models[i].effect == effect && (!models[i].clamp || *models[i].clamp == clamp))
      return static_cast<int>(i);
  throw std::logic_error(ToString(effect));
}

TEST(EffectCombinationTest, WhichPairsTheShapeCanTellApart) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> m = Models(nominal);
  auto can = [&](ShapeEffect a, int ca, ShapeEffect b, int cb) {
    return CanCombine(m[static_cast<size_t>(IndexOf(m, a, ca))],
                      m[static_cast<size_t>(IndexOf(m, b, cb))], nominal);
  };
  using E = ShapeEffect;
  EXPECT_TRUE(can(E::kIntrinsicCurvature, 0, E::kClampOrientation, 1));
  // One effect at two places.
  EXPECT_TRUE(can(E::kIntrinsicCurvature, 0, E::kIntrinsicCurvature, 0));
  EXPECT_TRUE(can(E::kSupportContact, 0, E::kSupportContact, 0));
  EXPECT_TRUE(can(E::kClampOrientation, 0, E::kClampOrientation, 1));
  EXPECT_TRUE(can(E::kClampCompliance, 0, E::kClampCompliance, 1));
  // Not: a clamp effect twice at one clamp, a whole-cable number twice, the nominal.
  EXPECT_FALSE(can(E::kClampOrientation, 1, E::kClampOrientation, 1));
  EXPECT_FALSE(can(E::kWeightStiffnessRatio, 0, E::kWeightStiffnessRatio, 0));
  EXPECT_FALSE(can(E::kAnisotropicBending, 0, E::kAnisotropicBending, 0));
  EXPECT_FALSE(can(E::kNone, 0, E::kClampOrientation, 0));
  // An isotropic cable between two clamps only feels the twist between them: a twist preload at
  // both is one effect. An anisotropic one tells them apart.
  EXPECT_FALSE(can(E::kTwistPreload, 0, E::kTwistPreload, 1));
  RodSpec flat = nominal;
  flat.material.bending_ratio = 2.0;
  const std::vector<EffectModel> mf = Models(flat);
  EXPECT_TRUE(CanCombine(mf[static_cast<size_t>(IndexOf(mf, E::kTwistPreload, 0))],
                         mf[static_cast<size_t>(IndexOf(mf, E::kTwistPreload, 1))], flat));
}

TEST(EffectCombinationTest, APairMakesBothChangesAndLeavingOnePartOutKeepsTheOther) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> m = Models(nominal);
  const int weight = IndexOf(m, ShapeEffect::kWeightStiffnessRatio);
  const int orientation = IndexOf(m, ShapeEffect::kClampOrientation, 1);
  const EffectModel pair = CombineEffects(m, weight, orientation);
  EXPECT_EQ(pair.physical_parameters, 3);
  ASSERT_EQ(pair.scale.size(), 3);
  Eigen::VectorXd x(3);
  x << std::log(1.5), 0.1, 0.0;  // density x 1.5; clamp 1 turned 0.1 rad about its d1
  const RodSpec both = pair.apply(x);
  EXPECT_NEAR(both.material.linear_density, 1.5 * nominal.material.linear_density, 1e-12);
  EXPECT_NEAR(std::acos(both.supports[1].tangent.normalized().dot(nominal.supports[1].tangent)),
              0.1, 1e-9);
  EXPECT_TRUE(both.supports[0].tangent.isApprox(nominal.supports[0].tangent));
  EXPECT_EQ(PartParameters(pair, m, 1, x), x.tail(2));

  const RodSpec no_weight = WithoutPart(pair, m, 0).apply(x);
  EXPECT_DOUBLE_EQ(no_weight.material.linear_density, nominal.material.linear_density);
  EXPECT_TRUE(no_weight.supports[1].tangent.isApprox(both.supports[1].tangent));
  const RodSpec no_orientation = WithoutPart(pair, m, 1).apply(x);
  EXPECT_NEAR(no_orientation.material.linear_density, both.material.linear_density, 1e-15);
  EXPECT_TRUE(no_orientation.supports[1].tangent.isApprox(nominal.supports[1].tangent));
}

TEST(EffectCombinationTest, TheSameEffectTwiceActsAtTwoPlaces) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> m = Models(nominal);
  const int curvature = IndexOf(m, ShapeEffect::kIntrinsicCurvature);
  const EffectModel pair = CombineEffects(m, curvature, curvature);
  Eigen::VectorXd x(8);
  x << 0.2, 0.1, 3.0, 0.0, 0.8, 0.1, 0.0, -2.0;
  const RodSpec spec = pair.apply(x);
  ASSERT_EQ(spec.natural_curvature.size(), 2u);
  EXPECT_NEAR(0.5 * (spec.natural_curvature[0].s_start + spec.natural_curvature[0].s_end), 0.2,
              1e-12);
  EXPECT_NEAR(0.5 * (spec.natural_curvature[1].s_start + spec.natural_curvature[1].s_end), 0.8,
              1e-12);
  EXPECT_DOUBLE_EQ(spec.natural_curvature[1].kappa.y(), -2.0);
}

}  // namespace
}  // namespace cablefit
