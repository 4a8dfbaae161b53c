#include "cablefit/formats/png_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cablefit/core/base/errors.h"
#include "test_support.h"

namespace cablefit {
namespace {

TEST(PngFile, RoundTripsPixelsAndLeavesNoTemporaryFile) {
  Image image = Image::Filled(7, 5, Rgb{10, 20, 30});
  image.Set(6, 4, Rgb{255, 0, 128});
  const auto dir = cablefit::testing::FreshTempDir("render");
  const std::string path = (dir / "sub" / "picture.png").string();
  WritePng(path, image);
  const Image back = ReadPng(path);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.pixels, image.pixels);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "sub")) files += entry.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(PngFile, ReportsBadFilesByName) {
  const auto dir = cablefit::testing::FreshTempDir("render");
  const std::string text = (dir / "not.png").string();
  std::ofstream(text) << "hello";
  EXPECT_THROW_WITH(ReadPng(text), FileError, "not.png: not a PNG file");
  EXPECT_THROW_WITH(ReadPng((dir / "missing.png").string()), FileError, "missing.png: cannot open");
  EXPECT_THROW_WITH(WritePng((dir / "not.png" / "x.png").string(), Image::Filled(2, 2, Rgb{})), FileError,
                    "x.png");
}

}  // namespace
}  // namespace cablefit
