#include "cablefit/formats/json_util.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/core/base/errors.h"
#include "io_test_files.h"
#include "test_support.h"

namespace cablefit::json {
namespace {

using cablefit::testing::FreshTempDir;

TEST(JsonUtil, FieldReaderValidates) {
  const Json doc = Json::parse(R"({"a": {"n": 2.5, "neg": -1, "s": "NaN", "v": [1, 2, 3],
                                         "v2": [1, null, 3], "arr": []}})");
  const FieldReader root(doc, "f.json");
  const FieldReader a = root.Child("a");
  EXPECT_EQ(a.where(), "a");
  EXPECT_EQ(a.RequireNumber("n"), 2.5);
  EXPECT_EQ(a.RequirePositive("n"), 2.5);
  EXPECT_EQ(a.OptionalNumber("missing", 7.0), 7.0);
  EXPECT_EQ(a.RequireVec3("v"), Vec3(1, 2, 3));
  EXPECT_TRUE(a.RequireArray("arr").empty());
  EXPECT_THROW_WITH(a.RequireNumber("s"), FileError, "f.json: a.s must be a number, got string \"NaN\"");
  EXPECT_THROW_WITH(a.RequirePositive("neg"), FileError, "a.neg must be positive, got -1");
  EXPECT_THROW_WITH(a.RequireNonNegative("neg"), FileError, "a.neg must not be negative");
  EXPECT_THROW_WITH(a.RequireNumber("x"), FileError, "missing field a.x");
  EXPECT_THROW_WITH(a.RequireVec3("v2"), FileError, "a.v2[1] must be a number, got null");
  EXPECT_THROW_WITH(a.RequireVec3("arr"), FileError, "a.arr must be an array of 3 numbers, got an array of 0");
  EXPECT_THROW_WITH(a.RequireString("n"), FileError, "a.n must be a string, got 2.5");
  EXPECT_THROW_WITH(a.Child("v"), FileError, "a.v must be an object, got an array");
  EXPECT_THROW_WITH(root.RequireArray("a"), FileError, "a must be an array, got an object");
  EXPECT_THROW_WITH(FieldReader(Json(3), "g.json", "x"), FileError, "g.json: x: must be a JSON object");
}

TEST(JsonUtil, NumberValueRejectsNonFinite) {
  EXPECT_EQ(NumberValue(Json(3), "f", "k"), 3.0);
  EXPECT_THROW_WITH(NumberValue(Json(HUGE_VAL), "f", "k"), FileError, "k is not a finite number");
  EXPECT_THROW_WITH(NumberValue(Json(true), "f", "k"), FileError, "k must be a number, got true");
}

TEST(JsonUtil, OutputConversions) {
  EXPECT_EQ(ToJson(Vec3(1, std::nan(""), 3)).dump(), "[1.0,null,3.0]");
  Eigen::MatrixXd m(2, 3);
  m << 1, 2, 3, 4, 5, HUGE_VAL;
  EXPECT_EQ(MatrixToJson(m).dump(), "[[1.0,2.0,3.0],[4.0,5.0,null]]");
  EXPECT_TRUE(NumberOrNull(std::nan("")).is_null());
  EXPECT_EQ(NumberOrNull(2.0).get<double>(), 2.0);
}

TEST(JsonUtil, WriteReadRoundTripsFullPrecision) {
  const auto dir = FreshTempDir("io");
  const auto path = (dir / "x" / "out.json").string();
  const double third = 1.0 / 3.0, tiny = 1.2345678901234567e-300;
  Json doc = {{"third", third}, {"tiny", tiny}, {"nan", NumberOrNull(std::nan(""))}, {"v", ToJson(Vec3(0.1, 0.2, 0.3))}};
  WriteJsonFile(path, doc);
  const Json back = ReadJsonFile(path);
  EXPECT_EQ(back["third"].get<double>(), third);
  EXPECT_EQ(back["tiny"].get<double>(), tiny);
  EXPECT_TRUE(back["nan"].is_null());
  EXPECT_EQ(back["v"][1].get<double>(), 0.2);
}

TEST(JsonUtil, AStringThatIsNotUtf8IsWrittenWithReplacementCharacters) {
  // A name out of a Latin-1 file: the result file is written, the bad byte replaced.
  const auto dir = FreshTempDir("io");
  const auto path = (dir / "latin1.json").string();
  WriteJsonFile(path, Json{{"name", std::string("Kabelbaum T\xfcr")}, {"n", 2}});
  const Json back = ReadJsonFile(path);
  EXPECT_EQ(back["name"].get<std::string>(), "Kabelbaum T\xef\xbf\xbdr");
  EXPECT_EQ(back["n"].get<int>(), 2);
}

TEST(JsonUtil, ReadJsonFileErrors) {
  const auto dir = FreshTempDir("io");
  EXPECT_THROW_WITH(ReadJsonFile((dir / "none.json").string()), FileError, "no such file");
  EXPECT_THROW_WITH(ReadJsonFile(dir.string()), FileError, "is a directory");
  cablefit::testing::WriteText(dir / "bad.json", "{\"a\": 1,}");
  try {
    ReadJsonFile((dir / "bad.json").string());
    ADD_FAILURE() << "accepted";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.problem()).rfind("not valid JSON: parse error at line 1", 0), 0u) << e.what();
  }
}

TEST(JsonUtil, Keys) {
  EXPECT_EQ(JoinKey("", "a"), "a");
  EXPECT_EQ(JoinKey("clamps[0]", "s"), "clamps[0].s");
  EXPECT_EQ(IndexKey("clamps", 2), "clamps[2]");
}

}  // namespace
}  // namespace cablefit::json
