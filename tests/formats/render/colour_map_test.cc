#include "cablefit/formats/colour_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/scene.h"

namespace cablefit {
namespace {

double Luminance(Rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

TEST(ColourMap, ViridisEndsAndMonotoneLightness) {
  // matplotlib's first and last entries.
  EXPECT_EQ(Viridis(0.0), (Rgb{68, 1, 84}));
  EXPECT_EQ(Viridis(1.0), (Rgb{253, 231, 37}));
  EXPECT_EQ(Viridis(-3.0), Viridis(0.0));
  EXPECT_EQ(Viridis(7.0), Viridis(1.0));
  EXPECT_EQ(Viridis(std::nan("")), Viridis(0.0));
  // Perceptual uniformity implies lightness rising steadily from dark to bright.
  double previous = -1.0;
  for (int i = 0; i <= 200; ++i) {
    const double l = Luminance(Viridis(i / 200.0));
    EXPECT_GE(l, previous - 0.5) << i;
    previous = l;
  }
}

TEST(ColourMap, ScaleNormalisesAndSceneRangesCombine) {
  const ColourScale scale{2.0, 6.0, "deviation [mm]"};
  EXPECT_DOUBLE_EQ(scale.Normalised(4.0), 0.5);
  EXPECT_DOUBLE_EQ(scale.Normalised(10.0), 1.0);
  EXPECT_FALSE((ColourScale{1.0, 1.0, ""}).IsValid(nullptr));
  Scene a, b;
  a.tubes.resize(1);
  a.tubes[0].deviation = Eigen::Vector3d(0.001, 0.002, 0.003);
  b.tubes.resize(1);
  b.tubes[0].deviation = Eigen::Vector2d(0.0005, 0.009);
  EXPECT_DOUBLE_EQ(EffectiveColourScale(a).min, 0.0);
  EXPECT_DOUBLE_EQ(EffectiveColourScale(a).max, 3.0);
  EXPECT_DOUBLE_EQ(CommonColourScale(a, b).max, 9.0);
}

}  // namespace
}  // namespace cablefit
