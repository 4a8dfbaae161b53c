// Animated PNG: acTL announces the frame count before the first IDAT, every frame has an fcTL,
// frames after the first carry their data in fdAT, the sequence numbers of fcTL and fdAT count
// 0, 1, 2... without a gap, every chunk's CRC holds, and a plain PNG reader sees frame 0.
#include "cablefit/formats/apng_file.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <string>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/png_file.h"
#include "test_support.h"

namespace cablefit {
namespace {

struct Chunk {
  std::string type;
  std::vector<std::uint8_t> data;
  bool crc_ok = false;
};

std::uint32_t Be32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

std::vector<Chunk> Chunks(const std::vector<std::uint8_t>& b) {
  std::vector<Chunk> out;
  std::size_t at = 8;
  while (at + 12 <= b.size()) {
    const std::uint32_t length = Be32(&b[at]);
    if (at + 12 + length > b.size()) break;
    Chunk c;
    c.type.assign(reinterpret_cast<const char*>(&b[at + 4]), 4);
    c.data.assign(b.begin() + static_cast<long>(at + 8), b.begin() + static_cast<long>(at + 8 + length));
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), &b[at + 4], 4 + length);
    c.crc_ok = crc == Be32(&b[at + 8 + length]);
    out.push_back(std::move(c));
    at += 12 + length;
  }
  EXPECT_EQ(at, b.size());
  return out;
}

TEST(ApngFile, FramesAcTLAndConsecutiveSequenceNumbers) {
  const std::vector<Image> frames = {Image::Filled(64, 40, Rgb{200, 10, 10}),
                                     Image::Filled(64, 40, Rgb{10, 200, 10}),
                                     Image::Filled(64, 40, Rgb{10, 10, 200})};
  const std::vector<std::uint8_t> b = EncodeApng(frames, {150, 0});
  const std::vector<Chunk> chunks = Chunks(b);
  ASSERT_GE(chunks.size(), 8u);
  EXPECT_EQ(chunks[0].type, "IHDR");
  EXPECT_EQ(chunks[1].type, "acTL");
  EXPECT_EQ(Be32(chunks[1].data.data()), 3u);      // num_frames
  EXPECT_EQ(Be32(chunks[1].data.data() + 4), 0u);  // plays forever
  EXPECT_EQ(chunks.back().type, "IEND");
  std::uint32_t expected = 0;
  int fctl = 0, fdat = 0, idat = 0;
  bool seen_idat = false;
  for (const Chunk& c : chunks) {
    EXPECT_TRUE(c.crc_ok) << c.type;
    if (c.type == "IDAT") {
      EXPECT_EQ(fctl, 1) << "IDAT belongs to the first frame";
      seen_idat = true;
      ++idat;
    }
    if (c.type == "fcTL" || c.type == "fdAT") {
      EXPECT_EQ(Be32(c.data.data()), expected++) << c.type;
    }
    if (c.type == "fcTL") {
      ++fctl;
      ASSERT_EQ(c.data.size(), 26u);
      EXPECT_EQ(Be32(c.data.data() + 4), 64u);
      EXPECT_EQ(Be32(c.data.data() + 8), 40u);
      EXPECT_EQ((c.data[20] << 8) | c.data[21], 150);  // delay numerator [ms]
      EXPECT_EQ((c.data[22] << 8) | c.data[23], 1000);
    }
    if (c.type == "fdAT") {
      EXPECT_TRUE(seen_idat);
      ++fdat;
    }
  }
  EXPECT_EQ(fctl, 3);
  EXPECT_GE(idat, 1);
  EXPECT_GE(fdat, 2);
  // A viewer without APNG shows frame 0.
  const auto dir = testing::FreshTempDir("apng_file");
  const std::string path = (dir / "a.png").string();
  WriteApng(path, frames, {150, 0});
  const Image still = ReadPng(path);
  EXPECT_EQ(still.At(5, 5).r, 200);
  EXPECT_EQ(still.At(5, 5).g, 10);
}

TEST(ApngFile, FramesOfDifferentSizesAreRefused) {
  EXPECT_THROW(EncodeApng({Image::Filled(8, 8, Rgb{}), Image::Filled(9, 8, Rgb{})}, {}),
               UsageError);
  EXPECT_THROW(EncodeApng({}, {}), UsageError);
  // Pre-encoded frames: the same size and pixel format, and PNGs at all.
  const std::vector<std::uint8_t> a = EncodePng(Image::Filled(8, 8, Rgb{}));
  const std::vector<std::uint8_t> b = EncodePng(Image::Filled(8, 9, Rgb{}));
  EXPECT_THROW(AssembleApng({a, b}, {}), UsageError);
  EXPECT_THROW(AssembleApng({a, {1, 2, 3}}, {}), UsageError);
  std::vector<std::uint8_t> cut(a.begin(), a.end() - 20);
  EXPECT_THROW(AssembleApng({a, cut}, {}), UsageError);
  EXPECT_EQ(AssembleApng({a, a}, {}), EncodeApng({Image::Filled(8, 8, Rgb{}), Image::Filled(8, 8, Rgb{})}, {}));
}

}  // namespace
}  // namespace cablefit
