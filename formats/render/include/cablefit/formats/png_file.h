// PNG encode/decode of an Image (libpng). Writing is atomic: temp file next to the target, then
// rename, so a viewer or the HTML report never sees half a picture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cablefit/formats/image.h"

namespace cablefit {

/// PNG bytes of `image` (8-bit RGB).
std::vector<std::uint8_t> EncodePng(const Image& image);

/// Writes `image` to `path` (parent directories created). Throws FileError naming `path`.
void WritePng(const std::string& path, const Image& image);

/// Reads an 8-bit or 16-bit PNG (grey, RGB, palette; alpha dropped) into RGB. Throws FileError.
Image ReadPng(const std::string& path);

}  // namespace cablefit
