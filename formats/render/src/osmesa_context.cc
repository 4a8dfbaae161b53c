#include "osmesa_context.h"

#include <algorithm>
#include <string>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "gl_api.h"

namespace cablefit::render {

OffscreenContext::OffscreenContext(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw InvalidInput("off-screen buffer size " + std::to_string(width) + " x " +
                       std::to_string(height) + " is not supported (1 .. 16384)");
  // The compatibility profile keeps client-side vertex arrays and GLSL 1.20 built-ins,
  // which is all this renderer needs.
  const int attributes[] = {OSMESA_FORMAT,      OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                            OSMESA_STENCIL_BITS, 0,          OSMESA_PROFILE,    OSMESA_COMPAT_PROFILE,
                            0};
  OSMesaContext context = Gl().CreateContextAttribs(attributes, nullptr);
  if (!context) throw InvalidInput("OSMesa could not create an off-screen GL context");
  // Not zeroed: every picture clears what it draws on, and a zeroed 10 MB buffer cost 13 ms.
  buffer_.reset(new std::uint8_t[static_cast<std::size_t>(width) * height * 4]);
  if (!Gl().MakeCurrent(context, buffer_.get(), GL_UNSIGNED_BYTE, width, height)) {
    Gl().DestroyContext(context);
    throw InvalidInput("OSMesa could not bind the off-screen buffer");
  }
  context_ = context;
}

void OffscreenContext::MakeCurrent() {
  if (!Gl().MakeCurrent(static_cast<OSMesaContext>(context_), buffer_.get(), GL_UNSIGNED_BYTE,
                        width_, height_))
    throw InvalidInput("OSMesa could not bind the off-screen buffer");
}

void OffscreenContext::Release() { Gl().MakeCurrent(nullptr, nullptr, 0, 0, 0); }

OffscreenContext::~OffscreenContext() {
  if (context_) Gl().DestroyContext(static_cast<OSMesaContext>(context_));
}

Image OffscreenContext::ReadPixels(int width, int height, int factor) const {
  CABLEFIT_REQUIRE(width >= 0 && height >= 0 && width <= width_ && height <= height_,
                   "read-back region larger than the off-screen buffer");
  CABLEFIT_REQUIRE(factor >= 1, "downsample factor must be positive");
  Gl().Finish();
  Image image;
  image.width = width / factor;
  image.height = height / factor;
  image.pixels.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  const int n = factor * factor;
  std::vector<int> sum(static_cast<std::size_t>(image.width) * 3);
  for (int y = 0; y < image.height; ++y) {
    std::fill(sum.begin(), sum.end(), 0);
    for (int dy = 0; dy < factor; ++dy) {
      const std::uint8_t* src =
          buffer_.get() + static_cast<std::size_t>(height_ - 1 - (y * factor + dy)) * width_ * 4;
      for (int x = 0; x < image.width; ++x) {
        for (int dx = 0; dx < factor; ++dx) {
          const std::uint8_t* p = src + 4 * static_cast<std::size_t>(x * factor + dx);
          sum[3 * x] += p[0];
          sum[3 * x + 1] += p[1];
          sum[3 * x + 2] += p[2];
        }
      }
    }
    std::uint8_t* dst = image.pixels.data() + static_cast<std::size_t>(y) * image.width * 3;
    for (std::size_t i = 0; i < sum.size(); ++i)
      dst[i] = static_cast<std::uint8_t>((sum[i] + n / 2) / n);
  }
  return image;
}

}  // namespace cablefit::render
