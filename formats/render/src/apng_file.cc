#include "cablefit/formats/apng_file.h"

#include <png.h>
#include <zlib.h>

#include <cstring>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/png_file.h"

namespace cablefit {
namespace {

using Bytes = std::vector<std::uint8_t>;
constexpr std::size_t kSignature = 8;

struct Chunk {
  std::string type;
  Bytes data;
};

std::uint32_t Be32(const Bytes& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) |
         (std::uint32_t{b[at + 2]} << 8) | std::uint32_t{b[at + 3]};
}

void PutBe32(Bytes* out, std::uint32_t x) {
  for (int shift : {24, 16, 8, 0}) out->push_back(static_cast<std::uint8_t>(x >> shift));
}

void PutBe16(Bytes* out, std::uint16_t x) {
  out->push_back(static_cast<std::uint8_t>(x >> 8));
  out->push_back(static_cast<std::uint8_t>(x));
}

// The chunks of a PNG (UsageError when a chunk runs past the end).
std::vector<Chunk> Chunks(const Bytes& png) {
  std::vector<Chunk> chunks;
  std::size_t at = kSignature;
  while (at + 12 <= png.size()) {
    const std::uint32_t length = Be32(png, at);
    CABLEFIT_REQUIRE(at + 12 + length <= png.size(), "PNG chunk past the end of the file");
    Chunk c;
    c.type.assign(reinterpret_cast<const char*>(png.data() + at + 4), 4);
    c.data.assign(png.begin() + static_cast<std::ptrdiff_t>(at + 8),
                  png.begin() + static_cast<std::ptrdiff_t>(at + 8 + length));
    chunks.push_back(std::move(c));
    at += 12 + length;
  }
  return chunks;
}

void PutChunk(Bytes* out, const std::string& type, const Bytes& data) {
  PutBe32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out->size();
  out->insert(out->end(), type.begin(), type.end());
  out->insert(out->end(), data.begin(), data.end());
  // The CRC covers type and data (PNG spec, 5.3).
  const uLong crc = crc32(crc32(0L, Z_NULL, 0), out->data() + start,
                          static_cast<uInt>(out->size() - start));
  PutBe32(out, static_cast<std::uint32_t>(crc));
}

}  // namespace

std::vector<std::uint8_t> AssembleApng(const std::vector<std::vector<std::uint8_t>>& pngs,
                                       const ApngTiming& timing) {
  CABLEFIT_REQUIRE(!pngs.empty(), "an animation needs a frame");
  CABLEFIT_REQUIRE(timing.delay_ms >= 1 && timing.delay_ms <= 65535 && timing.plays >= 0,
                   "APNG delay must be 1..65535 ms and plays >= 0");
  Bytes out, header;
  std::uint32_t sequence = 0;
  for (std::size_t k = 0; k < pngs.size(); ++k) {
    const Bytes& png = pngs[k];
    CABLEFIT_REQUIRE(png.size() > kSignature + 12 && png_sig_cmp(png.data(), 0, kSignature) == 0,
                     "APNG frame " + std::to_string(k) + " is not a PNG");
    const std::vector<Chunk> chunks = Chunks(png);
    CABLEFIT_REQUIRE(!chunks.empty() && chunks[0].type == "IHDR" && chunks[0].data.size() == 13,
                     "APNG frame " + std::to_string(k) + " has no IHDR first");
    if (k == 0) {
      header = chunks[0].data;
      out.assign(png.begin(), png.begin() + kSignature);
      PutChunk(&out, "IHDR", header);
      Bytes actl;
      PutBe32(&actl, static_cast<std::uint32_t>(pngs.size()));
      PutBe32(&actl, static_cast<std::uint32_t>(timing.plays));
      PutChunk(&out, "acTL", actl);
    }
    // Same size, depth and colour type as frame 0 (fcTL cannot change them).
    CABLEFIT_REQUIRE(chunks[0].data == header,
                     "every APNG frame must have the first frame's size and pixel format");
    Bytes fctl;
    PutBe32(&fctl, sequence++);
    fctl.insert(fctl.end(), header.begin(), header.begin() + 8);  // width, height
    PutBe32(&fctl, 0);  // x offset
    PutBe32(&fctl, 0);  // y offset
    PutBe16(&fctl, static_cast<std::uint16_t>(timing.delay_ms));
    PutBe16(&fctl, 1000);  // delay in 1/1000 s
    fctl.push_back(0);     // dispose: none (the next frame covers it whole)
    fctl.push_back(0);     // blend: source (replace)
    PutChunk(&out, "fcTL", fctl);
    for (const Chunk& c : chunks) {
      if (c.type != "IDAT") continue;
      if (k == 0) {
        PutChunk(&out, "IDAT", c.data);
      } else {
        Bytes fdat;
        PutBe32(&fdat, sequence++);
        fdat.insert(fdat.end(), c.data.begin(), c.data.end());
        PutChunk(&out, "fdAT", fdat);
      }
    }
  }
  PutChunk(&out, "IEND", {});
  return out;
}

std::vector<std::uint8_t> EncodeApng(const std::vector<Image>& frames, const ApngTiming& timing) {
  CABLEFIT_REQUIRE(!frames.empty(), "an animation needs a frame");
  for (const Image& f : frames)
    CABLEFIT_REQUIRE(f.width == frames[0].width && f.height == frames[0].height,
                     "every APNG frame must have the first frame's size");
  std::vector<Bytes> pngs;
  pngs.reserve(frames.size());
  for (const Image& f : frames) pngs.push_back(EncodePng(f));
  return AssembleApng(pngs, timing);
}

void WriteApng(const std::string& path, const std::vector<Image>& frames, const ApngTiming& timing) {
  const Bytes bytes = EncodeApng(frames, timing);
  WriteFileAtomically(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace cablefit
