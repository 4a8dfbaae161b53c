// Animated PNG (APNG 1.0, Mozilla: https://wiki.mozilla.org/APNG_Specification): frames of
// one size encoded by the project's PNG writer (png_file.h), their image data re-wrapped as
// the animation's frames (acTL before the first IDAT; per frame an fcTL; the first frame's data
// stays IDAT, so viewers without APNG show it as a still; later frames' data in fdAT chunks;
// one sequence number counting fcTL and fdAT from 0). Writing is atomic.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cablefit/formats/image.h"

namespace cablefit {

struct ApngTiming {
  int delay_ms = 250;  ///< [ms] per frame, 1..65535
  int plays = 0;       ///< times the animation is played, 0 = endlessly
};

/// APNG bytes of `frames` (all the same size, at least one). UsageError otherwise.
std::vector<std::uint8_t> EncodeApng(const std::vector<Image>& frames, const ApngTiming& timing);

/// APNG bytes from frames already encoded as PNG (EncodePng: same size and pixel format, at
/// least one), so a caller that also writes the frames as stills encodes each once. UsageError
/// otherwise.
std::vector<std::uint8_t> AssembleApng(const std::vector<std::vector<std::uint8_t>>& pngs,
                                       const ApngTiming& timing);

/// Writes EncodeApng(frames, timing) to `path` atomically. FileError naming `path` on failure.
void WriteApng(const std::string& path, const std::vector<Image>& frames, const ApngTiming& timing);

}  // namespace cablefit
