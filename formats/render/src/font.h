// Text rendering with FreeType and DejaVu Sans (Debian fonts-dejavu-core): hinted, anti-aliased
// glyphs, readable at 100 % zoom. Glyph bitmaps are cached per (size, code point).
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "cablefit/formats/image.h"

namespace cablefit::render {

enum class FontWeight { kRegular, kBold };
enum class TextAlign { kLeft, kCentre, kRight };

class Font {
 public:
  /// The process-wide font of that weight; throws FileError when the font file is missing.
  static Font& Get(FontWeight weight);

  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;
  ~Font();

  /// Advance width of `text` [px] at `size_px`.
  double Width(const std::string& text, int size_px);
  /// Height of capital letters above the baseline [px].
  double CapHeight(int size_px);
  /// Draws UTF-8 `text` with its baseline at y = `baseline`, aligned horizontally on `x`.
  void Draw(Image& image, double x, double baseline, const std::string& text, int size_px,
            Rgb colour, TextAlign align = TextAlign::kLeft);
  /// Draws `text` rotated 90 degrees counter-clockwise (reading upwards); the baseline is the
  /// vertical line x = `baseline_x`, aligned on `y` along the text direction.
  void DrawVertical(Image& image, double baseline_x, double y, const std::string& text,
                    int size_px, Rgb colour, TextAlign align = TextAlign::kCentre);

 private:
  struct Glyph {
    int width = 0, rows = 0, left = 0, top = 0;  // bitmap size and offset from the pen [px]
    double advance = 0.0;                          // [px]
    std::vector<std::uint8_t> coverage;            // rows x width
  };
  explicit Font(const std::string& path);
  const Glyph& GlyphFor(char32_t code, int size_px);
  template <typename Plot>
  void Layout(const std::string& text, int size_px, Plot&& plot);

  void* library_ = nullptr;  // FT_Library, kept opaque so FreeType headers stay in font.cc
  void* face_ = nullptr;     // FT_Face
  std::map<std::pair<int, char32_t>, Glyph> cache_;
  std::recursive_mutex mutex_;
};

/// Decodes UTF-8; invalid bytes become U+FFFD.
std::u32string DecodeUtf8(const std::string& text);

}  // namespace cablefit::render
