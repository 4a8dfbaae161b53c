#include "cablefit/formats/truth_reader.h"

#include <gtest/gtest.h>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/case_reader.h"
#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using testing::FreshTempDir;
using testing::WriteText;

fs::path PublicCase(const char* name) { return testing::PublicCasesDir() / name; }

TEST(TruthReader, ReadsEveryPublicTruth) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(testing::PublicCasesDir())) {
    if (!fs::exists(e.path() / "truth.json")) continue;
    SCOPED_TRACE(e.path().string());
    ++n;
    const CaseTruth truth = ReadTruth(e.path().string());
    EXPECT_EQ(truth.case_name, e.path().filename().string());
    EXPECT_FALSE(truth.effect.empty());
    if (truth.interval) {
      EXPECT_LE(truth.interval->first, truth.interval->second);
    }
  }
  EXPECT_EQ(n, 11);
}

TEST(TruthReader, FieldsOfKnownSamples) {
  const CaseTruth orient = ReadTruth((PublicCase("sample-clamp_orientation") / "truth.json").string());
  EXPECT_EQ(orient.effect, "clamp_orientation");
  ASSERT_TRUE(orient.clamp.has_value());
  EXPECT_EQ(*orient.clamp, 1);
  ASSERT_TRUE(orient.interval.has_value());
  EXPECT_DOUBLE_EQ(orient.interval->first, 0.11574091370558376);
  EXPECT_DOUBLE_EQ(orient.parameters.at("angle"), 0.19143387354102978);
  EXPECT_EQ(orient.parameters.count("axis"), 0u);  // vectors are not scalar parameters

  const CaseTruth aniso = ReadTruth(PublicCase("sample-anisotropic_bending").string());
  EXPECT_FALSE(aniso.clamp.has_value());
  EXPECT_DOUBLE_EQ(aniso.parameters.at("ratio"), 1.5);
  EXPECT_EQ(aniso.parameters.count("convention"), 0u);

  const CaseTruth none = ReadTruth(PublicCase("sample-none").string());
  EXPECT_EQ(none.effect, "none");
  EXPECT_FALSE(none.interval.has_value());
  EXPECT_TRUE(none.parameters.empty());
}

TEST(TruthReader, CenterlinesSpanTheClamps) {
  const auto dir = PublicCase("sample-twist_preload");
  const RecordingCase rc = ReadRecordingCase(dir.string());
  for (const char* key : {"nominal_centerline", "truth_centerline"}) {
    SCOPED_TRACE(key);
    const Polyline line = ReadTruthCenterline((dir / "truth.json").string(), key);
    ASSERT_GE(line.size(), 2);
    EXPECT_NEAR(line.s[0], 0.0, 1e-9);
    EXPECT_NEAR(line.s[line.size() - 1], rc.nominal.length, 1e-6);
    EXPECT_LT((line.points.col(0) - rc.nominal.supports.front().position).norm(), 1e-4);
    EXPECT_LT((line.points.col(line.size() - 1) - rc.nominal.supports.back().position).norm(), 1e-4);
  }
}

TEST(TruthReader, RejectsMalformedTruth) {
  const auto dir = FreshTempDir("io");
  const auto path = (dir / "truth.json").string();
  const auto expect = [&](const std::string& text, const char* message) {
    WriteText(path, text);
    EXPECT_THROW_WITH(ReadTruth(path), FileError, message);
  };
  expect(R"({"format": "cable-truth/9", "case": "c", "effect": "none"})", "format is 'cable-truth/9'");
  expect(R"({"format": "cable-truth/1", "effect": "none"})", "missing field case");
  expect(R"({"format": "cable-truth/1", "case": "c", "effect": "none", "interval": [1]})",
         "interval must be null or [s_start, s_end]");
  expect(R"({"format": "cable-truth/1", "case": "c", "effect": "none", "interval": [0, "x"]})",
         "interval[1] must be a number");
  expect(R"({"format": "cable-truth/1", "case": "c", "effect": "none", "clamp": 0.5})",
         "clamp must be null or a clamp index");
  expect(R"({"format": "cable-truth/1", "case": "c", "effect": "none", "parameters": 3})",
         "parameters must be an object");

  const auto curve = [&](const std::string& extra, const char* message) {
    WriteText(path, R"({"format": "cable-truth/1", "case": "c", "effect": "none", "extra": )" + extra + "}");
    EXPECT_THROW_WITH(ReadTruthCenterline(path, "truth_centerline"), FileError, message);
  };
  curve("{}", "missing field extra.truth_centerline");
  curve(R"({"truth_centerline": {"s": [0, 1], "xyz": [[0, 0, 0]]}})", "2 arc lengths but 1 points");
  curve(R"({"truth_centerline": {"s": [0], "xyz": [[0, 0, 0]]}})", "at least 2 points");
  curve(R"({"truth_centerline": {"s": [0, 1], "xyz": [[0, 0, 0], [1, 0]]}})",
        "extra.truth_centerline.xyz[1] must be an array of 3 numbers");
  curve(R"({"truth_centerline": {"s": [1, 0], "xyz": [[0, 0, 0], [1, 0, 0]]}})", "s decreases at index 1");
}

}  // namespace
}  // namespace cablefit
