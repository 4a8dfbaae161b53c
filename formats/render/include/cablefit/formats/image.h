// An 8-bit RGB raster: the common currency of the 3-D renderer, the plot renderer and PNG output.
#pragma once

#include <cstdint>
#include <vector>

namespace cablefit {

/// An sRGB colour, 8 bits per channel.
struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};


/// Row-major RGB pixels, row 0 at the top.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // 3 * width * height

  /// An image of the given size filled with `colour`.
  static Image Filled(int width, int height, Rgb colour);
  bool Contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  Rgb At(int x, int y) const;
  void Set(int x, int y, Rgb colour);
  /// Blends `colour` over pixel (x, y) with opacity `alpha` in [0, 1]; outside pixels are ignored.
  void Blend(int x, int y, Rgb colour, double alpha);
  /// Copies `source` with its top-left corner at (x, y), clipped to this image.
  void Paste(const Image& source, int x, int y);
};

/// Box-filters `image` down by an integer `factor` (anti-aliasing by supersampling).
Image Downsample(const Image& image, int factor);

}  // namespace cablefit
