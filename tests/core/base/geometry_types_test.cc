#include "cablefit/core/base/geometry_types.h"

#include <gtest/gtest.h>

#include "cablefit/core/base/errors.h"
#include "test_support.h"

namespace cablefit {
namespace {

TEST(FrameTest, OrthonormalisesNonUnitNonPerpendicularInput) {
  const Frame f = Frame::FromTangentNormal(Vec3(2, 0, 0), Vec3(0.3, 0, 5));
  EXPECT_TRUE(testing::MatricesNear(f.d3, Vec3(1, 0, 0), 1e-15));
  EXPECT_TRUE(testing::MatricesNear(f.d1, Vec3(0, 0, 1), 1e-15));
  EXPECT_TRUE(testing::MatricesNear(f.d2, Vec3(0, -1, 0), 1e-15));
  EXPECT_NEAR((f.Matrix().transpose() * f.Matrix() - Mat3::Identity()).norm(), 0.0, 1e-14);
}

TEST(FrameTest, RejectsParallelNormalAndNaN) {
  EXPECT_THROW_WITH(Frame::FromTangentNormal(Vec3(1, 0, 0), Vec3(3, 0, 0)), InvalidInput,
                    "parallel");
  EXPECT_THROW_WITH(Frame::FromTangentNormal(Vec3(NAN, 0, 0), Vec3(0, 0, 1)), InvalidInput,
                    "finite");
  EXPECT_THROW_WITH(Frame::FromTangentNormal(Vec3(0, 0, 0), Vec3(0, 0, 1)), InvalidInput, "zero");
}

TEST(PolylineTest, ChordParameterisation) {
  Polyline p;
  p.points.resize(3, 3);
  p.points << 0, 3, 3, 0, 4, 4, 0, 0, 1;
  p.ParameteriseByChords(1.0);
  EXPECT_DOUBLE_EQ(p.s[2], 7.0);
  EXPECT_DOUBLE_EQ(p.ChordLength(), 6.0);
}

}  // namespace
}  // namespace cablefit
