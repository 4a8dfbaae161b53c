// Every entry of the bad-input corpus (tests/bad-inputs/expected.tsv) through the built CLI: the
// expected exit code, a one-line "cablefit: <file>: <problem>" naming the file at fault, a
// bounded run time, and nothing half-written in the output folder.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

struct BadInput {
  std::string id;
  std::string setup;    // "-", "fifo:REL", "sparse:REL:BYTES" or "sparse-ply:REL:BYTES"
  int exit_code = 2;
  std::string named;    // path (relative to the corpus) the error line must name
  std::string message;  // substring of that line
  std::string args;     // cablefit arguments: paths relative to the corpus, {out}, {samples}
};

std::vector<std::string> SplitTabs(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, '\t')) cells.push_back(cell);
  return cells;
}

std::vector<BadInput> LoadManifest() {
  std::ifstream in(fs::path(CABLEFIT_BAD_INPUTS_DIR) / "expected.tsv");
  std::vector<BadInput> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> c = SplitTabs(line);
    if (c.size() != 6) continue;  // caught by ManifestIsWellFormed
    out.push_back({c[0], c[1], std::stoi(c[2]), c[3], c[4], c[5]});
  }
  return out;
}

std::vector<std::string> Split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, sep)) out.push_back(part);
  return out;
}

// Inputs git cannot hold, made in the copy of the corpus: a FIFO (would block a reader that
// opens it), a sparse file of some gigabytes (no disk, but its size is what a reader sees),
// the same with a PLY header claiming 10^12 points in front.
void MakeRuntimeInput(const fs::path& corpus, const std::string& setup) {
  if (setup == "-") return;
  const std::vector<std::string> p = Split(setup, ':');
  ASSERT_GE(p.size(), 2u) << setup;
  const fs::path file = corpus / p[1];
  fs::create_directories(file.parent_path());
  if (p[0] == "fifo") {
    ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0) << file;
    return;
  }
  ASSERT_EQ(p.size(), 3u) << setup;
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (p[0] == "sparse-ply")
      out << "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
             "property float x\nproperty float y\nproperty float z\nend_header\n";
  }
  fs::resize_file(file, std::stoull(p[2]));
}

std::string Substitute(std::string text, const std::string& key, const std::string& value) {
  for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
    text.replace(at, key.size(), value);
  return text;
}

// Relative path arguments become absolute paths into the corpus copy; options stay as they are.
std::string CommandLine(const BadInput& b, const fs::path& corpus, const fs::path& out) {
  std::string line;
  const std::vector<std::string> words = Split(b.args, ' ');
  for (std::size_t i = 0; i < words.size(); ++i) {
    std::string w = Substitute(words[i], "{out}", out.string());
    w = Substitute(w, "{samples}", (testing::SourceDir() / "samples").string());
    const bool path = i > 0 && w.rfind("--", 0) != 0 && !fs::path(w).is_absolute();
    if (path) w = (corpus / w).string();
    line += (i ? " '" : "") + (i ? w + "'" : w);
  }
  return line;
}

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, OneLineErrorNamingTheFileAndNothingHalfWritten) {
  const BadInput& b = GetParam();
  const fs::path root = testing::FreshTempDir(b.id);
  const fs::path corpus = root / "corpus";
  fs::copy(CABLEFIT_BAD_INPUTS_DIR, corpus,
           fs::copy_options::recursive | fs::copy_options::copy_symlinks);
  MakeRuntimeInput(corpus, b.setup);
  const fs::path out = root / "out";

  const auto t0 = std::chrono::steady_clock::now();
  const testing::CliRun run = testing::RunCablefit(CommandLine(b, corpus, out));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  EXPECT_EQ(run.exit_code, b.exit_code) << run.err;
  // The first line of stderr is the error itself, "cablefit: <file>: <problem>".
  const std::string first = run.err.substr(0, run.err.find('\n'));
  EXPECT_EQ(first.rfind("cablefit: ", 0), 0u) << run.err;
  const std::string named = (corpus / b.named).lexically_normal().string();
  EXPECT_NE(first.find(named + ": "), std::string::npos) << "expected " << named << " in\n"
                                                         << run.err;
  EXPECT_NE(first.find(b.message), std::string::npos) << "expected '" << b.message << "' in\n"
                                                      << run.err;
  // Bad input is refused up front: no solver runs, no input is read to its end when its size
  // or header already says no (the 2-3 GB sparse files).
  EXPECT_LT(seconds, 60.0);
  // Nothing half-written: no temporary file left behind, and nothing at all for the failed
  // input except the run's summary page.
  std::error_code ec;
  if (fs::exists(out, ec)) {
    for (const auto& e : fs::recursive_directory_iterator(out)) {
      const std::string name = e.path().filename().string();
      EXPECT_EQ(name.find(".tmp"), std::string::npos) << e.path();
      if (e.is_regular_file()) {
        EXPECT_EQ(name, "report.html") << e.path();
      }
    }
  }
  fs::remove_all(root, ec);
}

std::string TestName(const ::testing::TestParamInfo<BadInput>& info) {
  std::string name = info.param.id;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInputTest, ::testing::ValuesIn(LoadManifest()), TestName);

TEST(BadInputCorpus, ManifestIsWellFormedAndLargeEnough) {
  std::ifstream in(fs::path(CABLEFIT_BAD_INPUTS_DIR) / "expected.tsv");
  ASSERT_TRUE(in) << "no manifest";
  std::string line;
  int entries = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    EXPECT_EQ(SplitTabs(line).size(), 6u) << line;
    ++entries;
  }
  EXPECT_GE(entries, 50);
  EXPECT_EQ(static_cast<std::size_t>(entries), LoadManifest().size());
}

}  // namespace
}  // namespace cablefit
