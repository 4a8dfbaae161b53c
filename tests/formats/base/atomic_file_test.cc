#include "cablefit/formats/atomic_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <thread>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::FreshTempDir;
using testing::ListDir;
using testing::ReadText;
using testing::WriteText;

TEST(AtomicFile, WritesContentsAndCreatesParentFolders) {
  const auto dir = FreshTempDir("io");
  const auto path = dir / "a" / "b" / "out.txt";
  WriteFileAtomically(path.string(), [](std::ostream& out) { out << "hello\n" << 42; });
  EXPECT_EQ(ReadText(path), "hello\n42");
  EXPECT_EQ(ListDir(path.parent_path()), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, StringOverloadReplacesExistingFile) {
  const auto dir = FreshTempDir("io");
  const auto path = dir / "out.txt";
  WriteText(path, "old contents that are longer");
  WriteFileAtomically(path.string(), std::string("new"));
  EXPECT_EQ(ReadText(path), "new");
  EXPECT_EQ(ListDir(dir).size(), 1u);
}

TEST(AtomicFile, ThrowingWriterLeavesNoFileAndNoTemp) {
  const auto dir = FreshTempDir("io");
  const auto path = dir / "out.txt";
  EXPECT_THROW(WriteFileAtomically(path.string(),
                                   [](std::ostream& out) {
                                     out << std::string(100000, 'x');  // past any buffer
                                     throw std::runtime_error("midway");
                                   }),
               std::runtime_error);
  EXPECT_TRUE(ListDir(dir).empty());
}

TEST(AtomicFile, ThrowingWriterKeepsExistingFileIntact) {
  const auto dir = FreshTempDir("io");
  const auto path = dir / "out.txt";
  WriteText(path, "precious");
  EXPECT_THROW_WITH(WriteFileAtomically(path.string(),
                                        [](std::ostream& out) {
                                          out << "partial";
                                          throw std::logic_error("writer failed");
                                        }),
                    std::logic_error, "writer failed");
  EXPECT_EQ(ReadText(path), "precious");
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, UnwritableLocationIsAFileError) {
  const auto dir = FreshTempDir("io");
  WriteText(dir / "plain", "a file, not a folder");
  EXPECT_THROW_WITH(WriteFileAtomically((dir / "plain" / "out.txt").string(), std::string("x")),
                    FileError, "plain");
}

TEST(AtomicFile, TargetThatIsAFolderIsAFileErrorAndLeavesNoTemp) {
  const auto dir = FreshTempDir("io");
  std::filesystem::create_directories(dir / "target" / "inside");
  EXPECT_THROW_WITH(WriteFileAtomically((dir / "target").string(), std::string("x")), FileError,
                    "cannot replace");
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"target"});
}

// Writes without sync (simulate's) move an old file aside instead of renaming over it: the
// same outcome, the new contents alone under the name and nothing else left in the folder; a
// folder in the way is still an error and still there.
TEST(AtomicFile, UnsyncedReplacementLeavesOnlyTheNewFile) {
  SetDurableWrites(false);
  const auto dir = FreshTempDir("io");
  const auto path = dir / "out.txt";
  WriteText(path, "old contents that are longer");
  WriteFileAtomically(path.string(), std::string("new"));
  WriteFileAtomically(path.string(), std::string("newer"));
  EXPECT_EQ(ReadText(path), "newer");
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"out.txt"});
  std::filesystem::create_directories(dir / "target" / "inside");
  EXPECT_THROW_WITH(WriteFileAtomically((dir / "target").string(), std::string("x")), FileError,
                    "cannot replace");
  EXPECT_TRUE(std::filesystem::is_directory(dir / "target" / "inside"));
  std::vector<std::string> left = ListDir(dir);
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"out.txt", "target"}));
  SetDurableWrites(true);
}

// Threads replacing the same file at once each get their own temporary name: every write
// succeeds, the file holds one complete version and no temporary file is left behind.
TEST(AtomicFile, ConcurrentWritersOfOneFileNeverShareATemporaryFile) {
  const auto dir = FreshTempDir("io");
  const auto path = dir / "out.txt";
  std::vector<std::thread> threads;
  std::vector<int> failures(8, 0);
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < 20; ++i) {
        try {
          WriteFileAtomically(path.string(), std::string(10000, static_cast<char>('a' + t)));
        } catch (const std::exception&) {
          ++failures[static_cast<std::size_t>(t)];
        }
      }
    });
  }
  for (std::thread& t : threads) t.join();
  for (int f : failures) EXPECT_EQ(f, 0);
  const std::string text = ReadText(path);
  ASSERT_EQ(text.size(), 10000u);
  EXPECT_EQ(text, std::string(10000, text[0]));
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, ForWritersThatWantAFileName) {
  const auto dir = FreshTempDir("io");
  const auto path = dir / "sub" / "mesh.stl";
  {
    AtomicFile file(path.string());
    EXPECT_EQ(file.temp_path().parent_path(), path.parent_path());  // same file system
    EXPECT_EQ(file.temp_path().filename().string().rfind(".mesh.stl.tmp.", 0), 0u);
    WriteText(file.temp_path(), "uncommitted");
  }
  EXPECT_TRUE(ListDir(dir / "sub").empty());  // not committed: removed, target untouched
  {
    AtomicFile file(path.string());
    WriteText(file.temp_path(), "solid");
    file.Commit();
  }
  EXPECT_EQ(ReadText(path), "solid");
  EXPECT_EQ(ListDir(dir / "sub"), std::vector<std::string>{"mesh.stl"});
}

}  // namespace
}  // namespace cablefit
