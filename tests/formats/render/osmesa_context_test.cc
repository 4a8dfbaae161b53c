// The off-screen buffer's read-back: the downsampled read equals Downsample of the full read.
#include "osmesa_context.h"

#include <gtest/gtest.h>

#include "gl_api.h"

namespace cablefit::render {
namespace {

TEST(OffscreenContext, ADownsampledReadIsTheBoxAverageOfTheFullRead) {
  OffscreenContext context(50, 40);
  // Rectangles of four colours, with edges that do not fall on 3-pixel blocks, so blocks mix.
  Gl().Enable(GL_SCISSOR_TEST);
  const struct {
    int x, y, w, h;
    float r, g, b;
  } boxes[] = {{0, 0, 50, 40, 0.1f, 0.2f, 0.3f},
               {4, 5, 20, 17, 0.9f, 0.1f, 0.0f},
               {17, 11, 31, 22, 0.0f, 0.8f, 0.4f},
               {1, 30, 7, 10, 1.0f, 1.0f, 1.0f}};
  for (const auto& b : boxes) {
    Gl().Scissor(b.x, b.y, b.w, b.h);
    Gl().ClearColor(b.r, b.g, b.b, 1.0f);
    Gl().Clear(GL_COLOR_BUFFER_BIT);
  }
  for (const int factor : {1, 2, 3}) {
    const Image fused = context.ReadPixels(47, 38, factor);
    const Image reference = Downsample(context.ReadPixels(47, 38), factor);
    ASSERT_EQ(fused.width, 47 / factor);
    ASSERT_EQ(fused.height, 38 / factor);
    EXPECT_EQ(fused.pixels, reference.pixels) << "factor " << factor;
  }
  // Not one colour: the rectangles are there (row 0 is the top, GL's y = 39).
  const Image full = context.ReadPixels();
  EXPECT_NE(full.At(0, 0).g, full.At(10, 25).g);
  OffscreenContext::Release();
}

}  // namespace
}  // namespace cablefit::render
