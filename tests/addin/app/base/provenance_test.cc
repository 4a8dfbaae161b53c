// Provenance of every output: the command line as it can be pasted back into a shell, the UTC
// date, the tool version and each input's SHA-256.
#include "cablefit/app/base/provenance.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <regex>

#include "cablefit/formats/file_digest.h"
#include "test_support.h"

namespace cablefit::addin {
namespace {

TEST(Provenance, CommandLineIsQuotedForTheShellAndNamesTheToolNotItsPath) {
  const char* argv[] = {"/opt/build/addin/cablefit", "relax", "my harness.step", "--out",
                        "it's", "--jobs=2", ""};
  SetCommandLine(7, argv);
  EXPECT_EQ(CommandLine(), "cablefit relax 'my harness.step' --out 'it'\\''s' --jobs=2 ''");
  SetCommandLine(0, nullptr);
  EXPECT_EQ(CommandLine(), "");
}

TEST(Provenance, JsonHasToolDateCommandLineAndEachInputsSha256) {
  const auto dir = testing::FreshTempDir("provenance");
  const std::string file = (dir / "in.txt").string();
  std::ofstream(file) << "abc";
  const char* argv[] = {"cablefit", "section", "in.txt"};
  SetCommandLine(3, argv);
  const nlohmann::json j =
      ProvenanceJson({{"input", file}, {"config", ""}, {"gone", (dir / "gone").string()}});
  EXPECT_EQ(j.at("tool"), ToolVersion());
  EXPECT_TRUE(std::regex_match(j.at("date").get<std::string>(),
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")))
      << j.at("date");
  EXPECT_EQ(j.at("command_line"), "cablefit section in.txt");
  ASSERT_EQ(j.at("inputs").size(), 2u);  // the empty path is left out
  // SHA-256("abc"), FIPS 180-2 appendix B.1.
  EXPECT_EQ(j.at("inputs")[0].at("sha256"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_TRUE(j.at("inputs")[1].at("sha256").is_null());
  const std::string html = ProvenanceHtml(j);
  EXPECT_NE(html.find("sha256 ba7816bf"), std::string::npos) << html;
  EXPECT_NE(html.find("sha256 unreadable"), std::string::npos) << html;
  EXPECT_NE(html.find("<code>cablefit section in.txt</code>"), std::string::npos) << html;
  SetCommandLine(0, nullptr);
}

// A failed input of a batch may be a FIFO: hashing it would wait for a writer forever.
TEST(Provenance, AFifoIsNotReadAndHasNoSha256) {
  const auto dir = testing::FreshTempDir("provenance_fifo");
  const std::string fifo = (dir / "case.json").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const nlohmann::json j = ProvenanceJson({{"case", fifo}});
  ASSERT_EQ(j.at("inputs").size(), 1u);
  EXPECT_TRUE(j.at("inputs")[0].at("sha256").is_null());
}

}  // namespace
}  // namespace cablefit::addin
