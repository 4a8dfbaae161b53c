#include "osmesa_context.h"


#include <string>

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
  buffer_.assign(static_cast<std::size_t>(width) * height * 4, 0);
  if (!Gl().MakeCurrent(context, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    Gl().DestroyContext(context);
    throw InvalidInput("OSMesa could not bind the off-screen buffer");
  }
  context_ = context;
}

void OffscreenContext::MakeCurrent() {
  if (!Gl().MakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE,
                        width_, height_))
    throw InvalidInput("OSMesa could not bind the off-screen buffer");
}

void OffscreenContext::Release() { Gl().MakeCurrent(nullptr, nullptr, 0, 0, 0); }

OffscreenContext::~OffscreenContext() {
  if (context_) Gl().DestroyContext(static_cast<OSMesaContext>(context_));
}

Image OffscreenContext::ReadPixels(int width, int height) const {
  CABLEFIT_REQUIRE(width >= 0 && height >= 0 && width <= width_ && height <= height_,
                   "read-back region larger than the off-screen buffer");
  Gl().Finish();
  Image image = Image::Filled(width, height, Rgb{});
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* src = buffer_.data() + static_cast<std::size_t>(height_ - 1 - y) * width_ * 4;
    std::uint8_t* dst = image.pixels.data() + static_cast<std::size_t>(y) * width * 3;
    for (int x = 0; x < width; ++x) {
      dst[3 * x] = src[4 * x];
      dst[3 * x + 1] = src[4 * x + 1];
      dst[3 * x + 2] = src[4 * x + 2];
    }
  }
  return image;
}

}  // namespace cablefit::render
