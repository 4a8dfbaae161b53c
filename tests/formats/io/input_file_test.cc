// Why a named input cannot be read is said as the system knows it: a loop of symbolic links or a
// dangling link is not "no such file" (the user would look for a typo), and size limits hold.
#include "cablefit/formats/input_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cablefit/core/base/errors.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

TEST(InputFile, MissingFileIsNoSuchFile) {
  const fs::path dir = testing::FreshTempDir("input_missing");
  EXPECT_EQ(UnreachablePathProblem((dir / "none.csv").string()), "no such file or folder");
}

TEST(InputFile, SymbolicLinkLoopIsNamedAsSuch) {
  const fs::path dir = testing::FreshTempDir("input_link_loop");
  fs::create_symlink(dir / "b", dir / "a");
  fs::create_symlink(dir / "a", dir / "b");
  const std::string problem = UnreachablePathProblem((dir / "a").string());
  EXPECT_NE(problem.find("symbolic link"), std::string::npos) << problem;
  EXPECT_THROW_WITH(CheckInputFile((dir / "a").string(), 100, "a test file"), FileError, "symbolic link");
}

TEST(InputFile, DanglingLinkIsNamedAsSuch) {
  const fs::path dir = testing::FreshTempDir("input_dangling");
  fs::create_symlink(dir / "gone.json", dir / "link.json");
  EXPECT_NE(UnreachablePathProblem((dir / "link.json").string()).find("symbolic link"), std::string::npos);
}

TEST(InputFile, SizeLimitIsChecked) {
  const fs::path dir = testing::FreshTempDir("input_size");
  std::ofstream(dir / "big.txt") << std::string(200, 'x');
  EXPECT_THROW_WITH(CheckInputFile((dir / "big.txt").string(), 100, "a test file"), FileError,
                    "more than the limit of 100 bytes for a test file");
  EXPECT_EQ(CheckInputFile((dir / "big.txt").string(), 1000, "a test file"), 200u);
}

}  // namespace
}  // namespace cablefit
