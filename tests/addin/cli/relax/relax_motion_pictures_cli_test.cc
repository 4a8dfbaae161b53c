// `cablefit relax` with pictures on the door-hinge sample writes the motion as an animated PNG
// with one frame per pose (acTL), consecutive sequence numbers, the still frames for the
// report's slider, and a report that shows both.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "cablefit/formats/json_util.h"
#include "cablefit/formats/png_file.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using testing::Q;

std::uint32_t Be32(const std::string& b, std::size_t at) {
  const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

TEST(RelaxMotionPicturesCli, TheDoorMotionIsAnAnimationWithOneFramePerPose) {
  const fs::path dir = testing::FreshTempDir("relax_motion_pictures");
  const fs::path samples = testing::SourceDir() / "samples/harness";
  const fs::path out = dir / "out";
  const auto run = testing::RunCablefit("relax " + Q(samples / "door_hinge.stl") + " --config " +
                                        Q(samples / "door_hinge.json") + " --out " + Q(out));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const auto j = json::ReadJsonFile((out / "door_hinge.json").string());
  const std::size_t poses = j["cables"][0]["motion"]["poses"].size();
  ASSERT_EQ(poses, 31u);

  std::ifstream in(out / "door_hinge-motion.png", std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(b.size(), 8u);
  std::size_t at = 8;
  std::uint32_t frames = 0, next = 0, fctl = 0;
  bool sequence_ok = true;
  std::vector<std::string> order;
  while (at + 12 <= b.size()) {
    const std::uint32_t length = Be32(b, at);
    const std::string type = b.substr(at + 4, 4);
    order.push_back(type);
    if (type == "acTL") frames = Be32(b, at + 8);
    if (type == "fcTL" || type == "fdAT") sequence_ok = sequence_ok && Be32(b, at + 8) == next++;
    if (type == "fcTL") ++fctl;
    at += 12 + length;
  }
  EXPECT_EQ(at, b.size());
  EXPECT_EQ(frames, poses);
  EXPECT_EQ(fctl, poses);
  EXPECT_TRUE(sequence_ok);
  ASSERT_GE(order.size(), 2u);
  EXPECT_EQ(order[1], "acTL");
  EXPECT_EQ(order.back(), "IEND");

  // Still frames: one per pose, the size of the animation.
  const Image first = ReadPng((out / "door_hinge-motion.png").string());
  std::size_t stills = 0;
  for (const auto& e : fs::directory_iterator(out / "door_hinge-motion-frames")) {
    ++stills;
    const Image still = ReadPng(e.path().string());
    EXPECT_EQ(still.width, first.width);
    EXPECT_EQ(still.height, first.height);
  }
  EXPECT_EQ(stills, poses);
  const std::string report = testing::ReadTextFile(out / "report.html");
  EXPECT_NE(report.find("<img src=\"door_hinge-motion.png\""), std::string::npos);
  EXPECT_NE(report.find("max=\"30\""), std::string::npos);
  EXPECT_NE(report.find("door_hinge-motion-frames/pose-030.png"), std::string::npos);
}

}  // namespace
}  // namespace cablefit
