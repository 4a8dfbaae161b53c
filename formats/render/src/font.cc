#include "font.h"

#include "freetype_api.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "cablefit/core/base/errors.h"

namespace cablefit::render {
namespace {

constexpr const char* kRegularPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kBoldPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

}  // namespace

std::u32string DecodeUtf8(const std::string& text) {
  std::u32string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >= text.size()) {
      out.push_back(U'\uFFFD');
      ++i;
      continue;
    }
    char32_t code = extra == 0 ? c : c & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto d = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
      ok = ok && (d >> 6) == 2;
      code = (code << 6) | (d & 0x3F);
    }
    out.push_back(ok ? code : U'\uFFFD');
    i += ok ? static_cast<std::size_t>(extra) + 1 : 1;
  }
  return out;
}

Font& Font::Get(FontWeight weight) {
  // Function-local statics: thread-safe construction, loaded once per process.
  if (weight == FontWeight::kBold) {
    static Font bold(kBoldPath);
    return bold;
  }
  static Font regular(kRegularPath);
  return regular;
}

Font::Font(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw FileError(path, "font not found (install the Debian package fonts-dejavu-core)");
  const FreeTypeApi& ft = FreeType();
  FT_Library library = nullptr;
  if (ft.Init_FreeType(&library) != 0) throw std::runtime_error("FreeType initialisation failed");
  FT_Face face = nullptr;
  if (ft.New_Face(library, path.c_str(), 0, &face) != 0) {
    ft.Done_FreeType(library);
    throw FileError(path, "FreeType cannot read this font");
  }
  library_ = library;
  face_ = face;
}

Font::~Font() {
  // Only a constructed font has a library, and FreeType() was loaded to construct it.
  if (face_) FreeType().Done_Face(static_cast<FT_Face>(face_));
  if (library_) FreeType().Done_FreeType(static_cast<FT_Library>(library_));
}

const Font::Glyph& Font::GlyphFor(char32_t code, int size_px) {
  const auto key = std::make_pair(size_px, code);
  if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  auto face = static_cast<FT_Face>(face_);
  const FreeTypeApi& ft = FreeType();
  ft.Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size_px));
  Glyph glyph;
  // Light hinting keeps glyph shapes true while snapping stems vertically: crisp small labels.
  if (ft.Load_Char(face, code, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) == 0) {
    const FT_GlyphSlot slot = face->glyph;
    glyph.width = static_cast<int>(slot->bitmap.width);
    glyph.rows = static_cast<int>(slot->bitmap.rows);
    glyph.left = slot->bitmap_left;
    glyph.top = slot->bitmap_top;
    glyph.advance = slot->advance.x / 64.0;
    glyph.coverage.resize(static_cast<std::size_t>(glyph.width) * glyph.rows);
    for (int r = 0; r < glyph.rows; ++r)
      for (int c = 0; c < glyph.width; ++c)
        glyph.coverage[static_cast<std::size_t>(r) * glyph.width + c] =
            slot->bitmap.buffer[r * slot->bitmap.pitch + c];
  }
  return cache_.emplace(key, std::move(glyph)).first->second;
}

template <typename Plot>
void Font::Layout(const std::string& text, int size_px, Plot&& plot) {
  double pen = 0.0;
  for (char32_t code : DecodeUtf8(text)) {
    const Glyph& glyph = GlyphFor(code, size_px);
    plot(glyph, std::round(pen));
    pen += glyph.advance;
  }
}

double Font::Width(const std::string& text, int size_px) {
  std::lock_guard lock(mutex_);
  double width = 0.0;
  for (char32_t code : DecodeUtf8(text)) width += GlyphFor(code, size_px).advance;
  return width;
}

double Font::CapHeight(int size_px) {
  std::lock_guard lock(mutex_);
  return GlyphFor(U'H', size_px).top;
}

void Font::Draw(Image& image, double x, double baseline, const std::string& text, int size_px,
                Rgb colour, TextAlign align) {
  std::lock_guard lock(mutex_);
  const double width = Width(text, size_px);
  const double start = align == TextAlign::kLeft    ? x
                       : align == TextAlign::kCentre ? x - width / 2
                                                     : x - width;
  const int x0 = static_cast<int>(std::lround(start));
  const int y0 = static_cast<int>(std::lround(baseline));
  Layout(text, size_px, [&](const Glyph& g, double pen) {
    for (int r = 0; r < g.rows; ++r)
      for (int c = 0; c < g.width; ++c) {
        const int a = g.coverage[static_cast<std::size_t>(r) * g.width + c];
        if (a) image.Blend(x0 + static_cast<int>(pen) + g.left + c, y0 - g.top + r, colour, a / 255.0);
      }
  });
}

void Font::DrawVertical(Image& image, double baseline_x, double y, const std::string& text,
                        int size_px, Rgb colour, TextAlign align) {
  std::lock_guard lock(mutex_);
  const double width = Width(text, size_px);
  // Along-text coordinate u runs upwards (decreasing image y).
  const double start = align == TextAlign::kLeft    ? y
                       : align == TextAlign::kCentre ? y + width / 2
                                                     : y + width;
  const int y0 = static_cast<int>(std::lround(start));
  const int x0 = static_cast<int>(std::lround(baseline_x));
  Layout(text, size_px, [&](const Glyph& g, double pen) {
    for (int r = 0; r < g.rows; ++r)
      for (int c = 0; c < g.width; ++c) {
        const int a = g.coverage[static_cast<std::size_t>(r) * g.width + c];
        const int u = static_cast<int>(pen) + g.left + c;  // along the text
        const int v = r - g.top;                          // below the baseline
        if (a) image.Blend(x0 + v, y0 - u, colour, a / 255.0);
      }
  });
}

}  // namespace cablefit::render
