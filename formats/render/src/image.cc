#include "cablefit/formats/image.h"

#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"

namespace cablefit {

Image Image::Filled(int width, int height, Rgb colour) {
  CABLEFIT_REQUIRE(width >= 0 && height >= 0, "negative image size");
  Image image;
  image.width = width;
  image.height = height;
  image.pixels.resize(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    image.pixels[i] = colour.r;
    image.pixels[i + 1] = colour.g;
    image.pixels[i + 2] = colour.b;
  }
  return image;
}

Rgb Image::At(int x, int y) const {
  CABLEFIT_REQUIRE(Contains(x, y), "pixel outside the image");
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  return {pixels[i], pixels[i + 1], pixels[i + 2]};
}

void Image::Set(int x, int y, Rgb colour) {
  if (!Contains(x, y)) return;
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  pixels[i] = colour.r;
  pixels[i + 1] = colour.g;
  pixels[i + 2] = colour.b;
}

void Image::Blend(int x, int y, Rgb colour, double alpha) {
  if (!Contains(x, y) || !(alpha > 0.0)) return;
  alpha = std::min(alpha, 1.0);
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  const std::uint8_t src[3] = {colour.r, colour.g, colour.b};
  for (int c = 0; c < 3; ++c) {
    const double v = pixels[i + c] * (1.0 - alpha) + src[c] * alpha;
    pixels[i + c] = static_cast<std::uint8_t>(std::lround(v));
  }
}

void Image::Paste(const Image& source, int x, int y) {
  const int x0 = std::max(0, x), x1 = std::min(width, x + source.width);
  if (x1 <= x0) return;
  for (int row = std::max(0, y); row < std::min(height, y + source.height); ++row) {
    const std::size_t dst = (static_cast<std::size_t>(row) * width + x0) * 3;
    const std::size_t src = (static_cast<std::size_t>(row - y) * source.width + (x0 - x)) * 3;
    std::copy_n(source.pixels.begin() + static_cast<long>(src), (x1 - x0) * 3,
                pixels.begin() + static_cast<long>(dst));
  }
}

Image Downsample(const Image& image, int factor) {
  CABLEFIT_REQUIRE(factor >= 1, "downsample factor must be positive");
  if (factor == 1) return image;
  Image out = Image::Filled(image.width / factor, image.height / factor, Rgb{});
  const int n = factor * factor;
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      int sum[3] = {0, 0, 0};
      for (int dy = 0; dy < factor; ++dy) {
        const std::size_t row = (static_cast<std::size_t>(y * factor + dy) * image.width) * 3;
        for (int dx = 0; dx < factor; ++dx) {
          const std::size_t i = row + static_cast<std::size_t>(x * factor + dx) * 3;
          sum[0] += image.pixels[i];
          sum[1] += image.pixels[i + 1];
          sum[2] += image.pixels[i + 2];
        }
      }
      const std::size_t o = (static_cast<std::size_t>(y) * out.width + x) * 3;
      for (int c = 0; c < 3; ++c) out.pixels[o + c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
    }
  }
  return out;
}

}  // namespace cablefit
