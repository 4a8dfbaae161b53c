// harness.json "motion": what it reads (a hinge in degrees, a rail in metres, there and back)
// and what it refuses with the field named (zero axis, NaN or equal angles, steps that are not a
// positive whole number, no moving support, a support that is neither an end nor an index).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/core/base/errors.h"
#include "test_support.h"

namespace cablefit::addin {
namespace {

HarnessConfig Read(const std::string& motion) {
  static const auto dir = testing::FreshTempDir("relax_motion_config");
  const std::string path = (dir / "harness.json").string();
  std::ofstream(path) << "{\"motion\": " << motion << "}";
  return ReadHarnessConfig(path);
}

std::string Error(const std::string& motion) {
  try {
    Read(motion);
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

TEST(RelaxMotionConfig, AHingeRotatesAboutItsAxisThroughItsPointThereAndBack) {
  const HarnessConfig h = Read(R"({"name": "door", "rotation": {"axis": [0, 0, 2],
      "point": [1, 0, 0], "angles": [0, 90]}, "steps": 3,
      "moving": [{"cable": "W1", "support": "end"}, {"cable": "W2", "support": 1}]})");
  ASSERT_TRUE(h.motion);
  const MotionConfig& m = *h.motion;
  EXPECT_EQ(m.name, "door");
  EXPECT_EQ(m.kind, MotionConfig::Kind::kRotation);
  EXPECT_NEAR(m.to, M_PI / 2, 1e-15);
  const std::vector<double> q = m.Poses();
  ASSERT_EQ(q.size(), 7u);  // 0, 30, 60, 90, 60, 30, 0 degrees
  EXPECT_EQ(q[2], q[4]);    // the way back passes the same poses exactly
  EXPECT_EQ(q.back(), q.front());
  // (2, 0, 5) turned by 90 degrees about z through (1, 0, 0) is (1, 1, 5).
  EXPECT_LT((m.At(M_PI / 2) * Vec3(2, 0, 5) - Vec3(1, 1, 5)).norm(), 1e-15);
  ASSERT_EQ(m.supports.size(), 2u);
  EXPECT_EQ(m.supports[0].at, "end");
  EXPECT_EQ(m.supports[1].index, 1);
}

TEST(RelaxMotionConfig, ARailTranslatesOneWayWhenReturnIsOff) {
  const HarnessConfig h = Read(R"({"translation": {"direction": [0, 3, 4], "distances": [0, 0.25]},
      "steps": 5, "return": false, "moving": [{"cable": "seat", "support": "start"}]})");
  const MotionConfig& m = *h.motion;
  EXPECT_EQ(m.Poses().size(), 6u);
  EXPECT_LT((m.At(0.25) * Vec3(1, 1, 1) - Vec3(1, 1.15, 1.2)).norm(), 1e-15);
}

TEST(RelaxMotionConfig, AListOfPosesIsVisitedInOrderAndInterpolatedBetween) {
  // Pose 1: turned 90 degrees about z through (1, 0, 0); pose 2: that, then shifted up 0.5 m.
  const HarnessConfig h = Read(R"({"poses": [
      {"rotation": {"axis": [0, 0, 1], "point": [1, 0, 0], "angle": 90}},
      {"rotation": {"axis": [0, 0, 1], "point": [1, 0, 0], "angle": 90}, "translation": [0, 0, 0.5]}],
      "steps": 2, "moving": [{"cable": "c", "support": "end"}]})");
  ASSERT_TRUE(h.motion);
  const MotionConfig& m = *h.motion;
  EXPECT_EQ(m.kind, MotionConfig::Kind::kPoses);
  EXPECT_STREQ(m.KindName(), "poses");
  const std::vector<double> q = m.Poses();
  ASSERT_EQ(q.size(), 9u);  // 0, 0.5, 1, 1.5, 2 and back
  EXPECT_EQ(q[4], 2.0);
  EXPECT_EQ(q[2], q[6]);
  const Vec3 p(2, 0, 5);
  EXPECT_LT((m.At(0) * p - p).norm(), 1e-15);  // the drawing
  EXPECT_LT((m.At(1) * p - Vec3(1, 1, 5)).norm(), 1e-15);
  EXPECT_LT((m.At(2) * p - Vec3(1, 1, 5.5)).norm(), 1e-15);
  // Halfway to pose 1: turned by 45 degrees; halfway between poses 1 and 2: shifted by half.
  EXPECT_LT((m.At(0.5) * p - Vec3(1 + std::sqrt(0.5), std::sqrt(0.5), 5)).norm(), 1e-12);
  EXPECT_LT((m.At(1.5) * p - Vec3(1, 1, 5.25)).norm(), 1e-12);
}

TEST(RelaxMotionConfig, BadMotionsAreRefusedNamingTheField) {
  const std::string moving = R"("moving": [{"cable": "c", "support": "end"}])";
  const std::string hinge =
      R"("rotation": {"axis": [0, 0, 1], "point": [0, 0, 0], "angles": [0, 45]})";
  EXPECT_NE(Error(R"({"rotation": {"axis": [0, 0, 0], "point": [0, 0, 0], "angles": [0, 45]}, )" +
                  moving + "}")
                .find("motion.rotation.axis"),
            std::string::npos);
  EXPECT_NE(Error(R"({"rotation": {"axis": [0, 0, 1], "point": [0, 0, 0], "angles": [10, 10]}, )" +
                  moving + "}")
                .find("angles"),
            std::string::npos);
  EXPECT_NE(
      Error(R"({"rotation": {"axis": [0, 0, 1], "point": [0, 0, 0], "angles": [0, "NaN"]}, )" +
            moving + "}")
          .find("angles"),
      std::string::npos);
  EXPECT_NE(Error(R"({"rotation": {"axis": [0, 0, 1], "point": [0, 0, 0], "angles": [0, 720]}, )" +
                  moving + "}")
                .find("angles"),
            std::string::npos);
  for (const char* steps : {"-3", "0", "2.5", "\"10\""})
    EXPECT_NE(
        Error("{" + hinge + ", \"steps\": " + steps + ", " + moving + "}").find("motion.steps"),
        std::string::npos)
        << steps;
  EXPECT_NE(Error("{" + hinge + ", \"moving\": []}").find("motion.moving"), std::string::npos);
  EXPECT_NE(
      Error("{" + hinge + R"(, "moving": [{"cable": "c", "support": "middle"}]})").find("support"),
      std::string::npos);
  EXPECT_NE(Error("{" + hinge + R"(, "moving": [{"cable": "c", "support": -1}]})").find("support"),
            std::string::npos);
  EXPECT_NE(Error("{" + moving + "}").find("exactly one"), std::string::npos);
  EXPECT_NE(
      Error("{" + hinge + R"(, "translation": {"direction": [1, 0, 0], "distances": [0, 1]}, )" +
            moving + "}")
          .find("exactly one"),
      std::string::npos);
  EXPECT_NE(Error("{" + hinge + ", \"speed\": 3, " + moving + "}").find("speed"),
            std::string::npos);
  // Solids that move: names (or patterns), and then no moving support is needed.
  EXPECT_NE(Error("{" + hinge + "}").find("\"moving\" supports or \"solids\""),
            std::string::npos);
  EXPECT_NE(Error("{" + hinge + R"(, "solids": [3]})").find("motion.solids[0]"), std::string::npos);
  EXPECT_NE(Error("{" + hinge + R"(, "solids": [""]})").find("motion.solids[0]"),
            std::string::npos);
  EXPECT_NE(Error("{" + hinge + R"(, "solids": "door"})").find("motion.solids"),
            std::string::npos);
  // Lists of poses.
  EXPECT_NE(Error("{\"poses\": [], " + moving + "}").find("motion.poses"), std::string::npos);
  EXPECT_NE(Error("{\"poses\": [{}], " + moving + "}").find("motion.poses[0]"),
            std::string::npos);
  EXPECT_NE(Error(R"({"poses": [{"rotation": {"axis": [0, 0, 1], "point": [0, 0, 0], "angle": 400}}], )" +
                  moving + "}")
                .find("motion.poses[0].rotation.angle"),
            std::string::npos);
  EXPECT_NE(Error(R"({"poses": [{"translation": [0, 0, "up"]}], )" + moving + "}")
                .find("motion.poses[0].translation"),
            std::string::npos);
  EXPECT_NE(Error("{" + hinge + R"(, "poses": [{"translation": [0, 0, 1]}], )" + moving + "}")
                .find("exactly one"),
            std::string::npos);
  // Tracked points: a cable and an arc length.
  EXPECT_NE(Error("{" + hinge + ", " + moving + R"(, "track": [{"cable": "c", "s": -1}]})")
                .find("motion.track[0].s"),
            std::string::npos);
  EXPECT_NE(Error("{" + hinge + ", " + moving + R"(, "track": [{"s": 0.1}]})")
                .find("motion.track[0].cable"),
            std::string::npos);
}

TEST(RelaxMotionConfig, SolidsThatMoveNeedNoMovingSupport) {
  const HarnessConfig h = Read(
      R"({"translation": {"direction": [0, 0, 1], "distances": [0, 0.1]}, "solids": ["seat*", "rail"]})");
  ASSERT_TRUE(h.motion);
  EXPECT_TRUE(h.motion->supports.empty());
  EXPECT_EQ(h.motion->solids, (std::vector<std::string>{"seat*", "rail"}));
}

TEST(RelaxToleranceConfig, FractionsAreReadAndImpossibleOnesRefused) {
  static const auto dir = testing::FreshTempDir("relax_tolerance_config");
  const std::string path = (dir / "harness.json").string();
  std::ofstream(path) << R"({"tolerances": {"length": 0.02, "bending_stiffness": 0.3}})";
  const HarnessConfig h = ReadHarnessConfig(path);
  ASSERT_TRUE(h.tolerances);
  EXPECT_DOUBLE_EQ(h.tolerances->length, 0.02);
  EXPECT_DOUBLE_EQ(h.tolerances->bending_stiffness, 0.3);
  EXPECT_DOUBLE_EQ(h.tolerances->linear_density, 0.0);
  EXPECT_DOUBLE_EQ(h.tolerances->clip_position, 0.0);
  std::ofstream(path) << R"({"tolerances": {"clip_position": 0.01}})";
  EXPECT_DOUBLE_EQ(ReadHarnessConfig(path).tolerances->clip_position, 0.01);
  for (const char* bad :
       {R"({"tolerances": {"length": -0.02}})", R"({"tolerances": {"length": 0.5}})",
        R"({"tolerances": {"clip_position": -0.01}})", R"({"tolerances": {"clip_position": 10}})",
        R"({"tolerances": {"bending_stiffness": 0.95}})", R"({"tolerances": {}})",
        R"({"tolerances": {"length": "2%"}})", R"({"tolerances": {"clips": 0.01}})"}) {
    std::ofstream(path) << bad;
    EXPECT_THROW(ReadHarnessConfig(path), FileError) << bad;
  }
}

}  // namespace
}  // namespace cablefit::addin
