// The FreeType entry points the text renderer calls, loaded from libfreetype on the first
// label drawn. Linked, FreeType (and the brotli and PNG libraries it pulls in) would be loaded
// into every process, `cablefit simulate` too, which draws nothing and is meant to start in
// milliseconds.
#pragma once

#include <ft2build.h>
#include FT_FREETYPE_H

namespace cablefit::render {

struct FreeTypeApi {
  decltype(&::FT_Init_FreeType) Init_FreeType = nullptr;
  decltype(&::FT_Done_FreeType) Done_FreeType = nullptr;
  decltype(&::FT_New_Face) New_Face = nullptr;
  decltype(&::FT_Done_Face) Done_Face = nullptr;
  decltype(&::FT_Set_Pixel_Sizes) Set_Pixel_Sizes = nullptr;
  decltype(&::FT_Load_Char) Load_Char = nullptr;
};

/// The entry points, loaded once per process (thread-safe). Throws InvalidInput naming the
/// library and the missing function when FreeType is not available.
const FreeTypeApi& FreeType();

}  // namespace cablefit::render
