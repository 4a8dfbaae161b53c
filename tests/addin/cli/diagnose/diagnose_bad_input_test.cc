// Bad inputs to `cablefit diagnose`: each broken case gives one line `cablefit: <file>: <problem>`
// naming the file at fault, the good case in the same run is still diagnosed, the failures are
// listed again at the end, and the exit status is 1 (2 when nothing could be read at all).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cablefit/formats/json_util.h"
#include "cablefit/formats/ply_reader.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

fs::path Public(const std::string& name) {
  return testing::PublicCasesDir() / name;
}

/// Copies public case `from` to `root/to` under the name `to`, keeping only the recordings of
/// `kind` (all when empty).
fs::path CopyCase(const std::string& from, const fs::path& root, const std::string& to,
                  const std::string& kind = "") {
  const fs::path dir = root / to;
  fs::create_directories(dir);
  json::Json c = json::ReadJsonFile((Public(from) / "case.json").string());
  c["name"] = to;
  json::Json kept = json::Json::array();
  for (const auto& r : c["recordings"]) {
    if (!kind.empty() && r["kind"] != kind) continue;
    fs::copy_file(Public(from) / r["file"].get<std::string>(), dir / r["file"].get<std::string>());
    kept.push_back(r);
  }
  c["recordings"] = kept;
  json::WriteJsonFile((dir / "case.json").string(), c);
  return dir;
}

std::string Slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

void Spit(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary | std::ios::trunc);
  f << text;
}

int CountLinesContaining(const std::string& text, const std::string& what) {
  int n = 0;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);)
    if (line.find(what) != std::string::npos) ++n;
  return n;
}

TEST(DiagnoseBadInput, EachBrokenCaseIsOneLineNamingItsFileAndTheOthersRun) {
  const fs::path root = testing::FreshTempDir("diagnose-bad");
  const fs::path in = root / "in";
  const fs::path out = root / "out";
  CopyCase("sample-force-stiffness", in, "good-force");

  const fs::path truncated = CopyCase("sample-clamp_orientation", in, "truncated-ply");
  const std::string ply = Slurp(truncated / "scan.ply");
  Spit(truncated / "scan.ply", ply.substr(0, ply.size() / 2));

  const fs::path tiny = CopyCase("sample-clamp_orientation", in, "three-point-scan");
  PointCloud three;
  three.points = Eigen::Matrix3Xd::Random(3, 3) * 0.01;
  WritePly((tiny / "scan.ply").string(), three);

  const fs::path nan = CopyCase("sample-none", in, "nan-centerline", "centerline");
  std::string csv = Slurp(nan / "centerline.csv");
  const std::size_t row = csv.find('\n', csv.find('\n', csv.size() / 2) + 1);
  csv.insert(row + 1, "0.4,nan,0.1,0.2\n");
  Spit(nan / "centerline.csv", csv);

  const fs::path column = CopyCase("sample-force-none", in, "missing-column");
  std::string torsion = Slurp(column / "torsion.csv");
  std::stringstream rows(torsion);
  std::string fixed, line;
  while (std::getline(rows, line)) fixed += line.substr(0, line.rfind(',')) + "\n";
  Spit(column / "torsion.csv", fixed);

  const fs::path missing = CopyCase("sample-force-none", in, "missing-file");
  fs::remove(missing / "torsion.csv");

  const testing::CliRun run =
      testing::RunCablefit("diagnose '" + in.string() + "' --out '" + out.string() + "' --jobs 2");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  // The good case is diagnosed completely.
  EXPECT_TRUE(fs::exists(out / "good-force" / "diagnosis.json")) << run.err;
  EXPECT_TRUE(fs::exists(out / "good-force" / "report.html"));
  EXPECT_EQ(CountLinesContaining(run.out, "good-force: stiffness"), 1) << run.out;
  // Each failure: one line naming the file at fault, repeated in the list at the end.
  const std::vector<std::pair<fs::path, std::string>> expected = {
      {truncated / "scan.ply", "truncated"},
      {tiny / "scan.ply", ""},
      {nan / "centerline.csv", "NaN"},
      {column / "torsion.csv", "column"},
      {missing / "case.json", "torsion.csv"},
  };
  for (const auto& [file, word] : expected) {
    SCOPED_TRACE(file.string());
    EXPECT_EQ(CountLinesContaining(run.err, "cablefit: " + file.string() + ": "), 2) << run.err;
    if (!word.empty()) {
      EXPECT_GE(CountLinesContaining(run.err, word), 1) << run.err;
    }
    EXPECT_FALSE(fs::exists(out / file.parent_path().filename() / "diagnosis.json"));
  }
  EXPECT_EQ(CountLinesContaining(run.err, "diagnose: 5 failure(s):"), 1) << run.err;
  // The run summary lists the good case and the failures.
  const std::string summary = Slurp(out / "report.html");
  EXPECT_NE(summary.find("good-force/report.html"), std::string::npos);
  EXPECT_NE(summary.find("failed"), std::string::npos);
}

TEST(DiagnoseBadInput, NothingReadableIsExitTwo) {
  const fs::path root = testing::FreshTempDir("diagnose-nothing");
  const testing::CliRun run = testing::RunCablefit("diagnose '" + (root / "nowhere").string() +
                                                   "' --out '" + (root / "out").string() + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find((root / "nowhere").string()), std::string::npos) << run.err;

  const fs::path bad = CopyCase("sample-force-none", root / "in", "only-bad");
  fs::remove(bad / "torsion.csv");
  const testing::CliRun only_bad = testing::RunCablefit(
      "diagnose '" + (root / "in").string() + "' --out '" + (root / "out").string() + "'");
  EXPECT_EQ(only_bad.exit_code, 2) << only_bad.err;
}

TEST(DiagnoseBadInput, UsageErrorsAreExitTwo) {
  EXPECT_EQ(testing::RunCablefit("diagnose").exit_code, 2);
  EXPECT_EQ(testing::RunCablefit("diagnose '" + Public("sample-none").string() + "'").exit_code, 2);
  EXPECT_EQ(testing::RunCablefit("diagnose x --out y --jobs -3").exit_code, 2);
}

// A case name is input: printed raw, a newline in it could forge a result line and an escape
// sequence could recolour the terminal. Control characters come out as \xNN.
TEST(DiagnoseBadInput, ControlCharactersInNamesCannotForgeOutput) {
  const fs::path root = testing::FreshTempDir("diag_ctrl");
  const fs::path dir = CopyCase("sample-force-none", root, "ctrl");
  json::Json c = json::ReadJsonFile((dir / "case.json").string());
  c["name"] = "ctrl\nFAKE: none, confidence 1.00\x1b[31m\x07";
  json::WriteJsonFile((dir / "case.json").string(), c);
  const auto run = testing::RunCablefit("diagnose '" + dir.string() + "' --out '" +
                                        (root / "out").string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  for (const std::string& text : {run.out, run.err}) {
    std::stringstream lines(text);
    for (std::string line; std::getline(lines, line);) EXPECT_NE(line.rfind("FAKE", 0), 0u) << line;
    EXPECT_EQ(text.find('\x1b'), std::string::npos);
    EXPECT_EQ(text.find('\x07'), std::string::npos);
  }
  EXPECT_NE(run.out.find("ctrl\\x0aFAKE"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

// --out naming an existing file is refused before any case runs: nothing is written and no
// summary is announced.
TEST(DiagnoseBadInput, OutNamingAFileIsRefusedBeforeAnyWork) {
  const fs::path root = testing::FreshTempDir("diagnose-out-file");
  Spit(root / "taken", "not a folder");
  const testing::CliRun run = testing::RunCablefit("diagnose '" + Public("sample-none").string() +
                                                   "' --out '" + (root / "taken").string() + "'");
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("exists and is not a folder"), std::string::npos) << run.err;
  EXPECT_EQ(run.out.find("summary:"), std::string::npos) << run.out;
  EXPECT_EQ(Slurp(root / "taken"), "not a folder");
}

// --quiet leaves only the final line on the standard output; --summary-json has every case
// with its status, the failures as on the standard error, and the provenance.
TEST(DiagnoseBadInput, QuietAndSummaryJsonSayTheSameAsTheFailureList) {
  const fs::path root = testing::FreshTempDir("diagnose-summary-json");
  const fs::path in = root / "in";
  CopyCase("sample-force-stiffness", in, "good-force");
  const fs::path missing = CopyCase("sample-force-none", in, "missing-file");
  fs::remove(missing / "torsion.csv");
  const fs::path summary = root / "summary.json";
  const testing::CliRun run =
      testing::RunCablefit("diagnose '" + in.string() + "' --out '" + (root / "out").string() +
                           "' --quiet --summary-json '" + summary.string() + "'");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 1) << run.out;
  EXPECT_EQ(run.out.rfind("diagnose: 1 of 2 case(s) diagnosed, 1 failed; ", 0), 0u) << run.out;
  EXPECT_EQ(CountLinesContaining(run.err, "diagnose: 1 failure(s):"), 1) << run.err;
  const json::Json j = json::ReadJsonFile(summary.string());
  EXPECT_EQ(j.at("format"), "cablefit-diagnose-summary/1");
  EXPECT_EQ(j.at("counts").at("cases"), 2);
  EXPECT_EQ(j.at("counts").at("diagnosed"), 1);
  EXPECT_EQ(j.at("counts").at("failed"), 1);
  ASSERT_EQ(j.at("failures").size(), 1u);
  const std::string failure = j.at("failures")[0].get<std::string>();
  EXPECT_NE(run.err.find("cablefit: " + failure + "\n"), std::string::npos) << failure;
  int diagnosed = 0;
  for (const json::Json& c : j.at("cases")) diagnosed += c.at("status") == "diagnosed" ? 1 : 0;
  EXPECT_EQ(diagnosed, 1);
  EXPECT_EQ(j.at("provenance").at("inputs").size(), 2u);
  EXPECT_NE(j.at("provenance").at("command_line").get<std::string>().find("--summary-json"),
            std::string::npos);
}

}  // namespace
}  // namespace cablefit
