// The relax pictures never show a cable that failed as if it had been relaxed: it is drawn as
// drawn, in a colour outside the deviation colour map.
#include <gtest/gtest.h>

#include <filesystem>

#include "cablefit/app/report/relax_report.h"
#include "cablefit/formats/png_file.h"
#include "colour_distance.h"
#include "test_support.h"

namespace cablefit::addin {
namespace {

using cablefit::testing::ColourDistance;

int PixelsNear(const Image& image, const Rgb& colour, double tolerance) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += ColourDistance(image.At(x, y), colour) < tolerance;
  return n;
}

TEST(RelaxPictures, AFailedCableIsDrawnRedAsDrawn) {
  RelaxedFile f;
  f.input = "failed.step";
  f.stem = "failed";
  f.read_ok = true;
  DrawnCable cable;
  cable.name = "w1";
  cable.diameter = 0.01;
  cable.centreline.points.resize(3, 3);
  cable.centreline.points << 0, 0.2, 0.4, 0, 0.05, 0, 0, 0, 0;
  cable.centreline.ParameteriseByChords();
  f.drawing.cables.push_back(cable);
  f.cables.resize(1);  // no relaxation: the cable failed
  f.cable_errors = {"the solver did not converge"};
  const auto dir = cablefit::testing::FreshTempDir("relax_failed_picture");
  const std::vector<std::string> names = WriteCloseUpPictures(dir.string(), f, HarnessConfig{});
  ASSERT_EQ(names.size(), 1u);
  const Image image = ReadPng((dir / names[0]).string());
  // Red (214, 39, 40) is far from every viridis colour and from the grey of a drawn route.
  EXPECT_GT(PixelsNear(image, Rgb{214, 39, 40}, 60), 500);
}

}  // namespace
}  // namespace cablefit::addin
