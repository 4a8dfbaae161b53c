// The helper executable the CAD reader's probe and the tube sweep run in.
#include "crash_probe.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace cablefit {
namespace {

TEST(CrashProbe, TheHelperIsFoundInTheBuildTree) {
  const std::string helper = OcctChildPath();
  ASSERT_FALSE(helper.empty());
  EXPECT_EQ(std::filesystem::path(helper).filename(), "cablefit-occt-child");
  // It refuses a call it does not know, and one whose parent is not the caller.
  auto outcome = RunOcctChild({"frobnicate"}, 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 64);
  outcome = RunChildProcess(helper, {"1", "sweep", "3", "0.01", "4"}, 60.0);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->exit_code, 64);
}

}  // namespace
}  // namespace cablefit
