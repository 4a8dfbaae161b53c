#include "cablefit/formats/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cablefit/core/base/errors.h"

namespace cablefit::json {
namespace {

TEST(JsonWriter, TextParsesBackToTheSameValues) {
  JsonWriter w;
  w.BeginObject();
  w.Key("name").String("sag \"quoted\" \\ tab\t");
  w.Key("x").Number(0.1);
  w.Key("big").Number(1.2345678901234567e300);
  w.Key("n").Integer(-42);
  w.Key("ok").Bool(true);
  w.Key("none").Null();
  w.Key("v").Numbers(Eigen::Vector3d(1.0 / 3.0, -2.5e-17, 7.0));
  w.Key("levels").Integers({24, 48, 96});
  w.Key("empty").BeginArray().EndArray();
  w.Key("list").BeginArray();
  w.BeginObject().Key("s").Number(0.5).EndObject();
  w.Number(2.0);
  w.EndArray();
  w.EndObject();
  const nlohmann::json j = nlohmann::json::parse(w.Finish());
  EXPECT_EQ(j.at("name"), "sag \"quoted\" \\ tab\t");
  EXPECT_EQ(j.at("x").get<double>(), 0.1);
  EXPECT_EQ(j.at("big").get<double>(), 1.2345678901234567e300);
  EXPECT_EQ(j.at("n").get<int>(), -42);
  EXPECT_TRUE(j.at("ok").get<bool>());
  EXPECT_TRUE(j.at("none").is_null());
  EXPECT_EQ(j.at("v")[0].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(j.at("v")[1].get<double>(), -2.5e-17);
  EXPECT_EQ(j.at("levels"), nlohmann::json({24, 48, 96}));
  EXPECT_TRUE(j.at("empty").is_array() && j.at("empty").empty());
  EXPECT_EQ(j.at("list")[0].at("s").get<double>(), 0.5);
  EXPECT_EQ(j.at("list")[1].get<double>(), 2.0);
}

TEST(JsonWriter, NonFiniteNumbersAreNullAndBadUtf8IsReplaced) {
  JsonWriter w;
  w.BeginObject();
  w.Key("nan").Number(std::nan(""));
  w.Key("v").Numbers(Eigen::Vector2d(std::numeric_limits<double>::infinity(), 1.0));
  w.Key("name").String(std::string("a\xff" "b"));
  w.EndObject();
  const nlohmann::json j = nlohmann::json::parse(w.Finish());
  EXPECT_TRUE(j.at("nan").is_null());
  EXPECT_TRUE(j.at("v")[0].is_null());
  EXPECT_EQ(j.at("name").get<std::string>(), "a\xEF\xBF\xBD" "b");
}

TEST(JsonWriter, TreeKeepsAnEmbeddedObject) {
  const nlohmann::json tree = {{"tool", "cablefit"}, {"inputs", {{{"sha256", nullptr}}}}, {"k", 3}};
  JsonWriter w;
  w.BeginObject().Key("provenance").Tree(tree).EndObject();
  EXPECT_EQ(nlohmann::json::parse(w.Finish()).at("provenance"), tree);
}

TEST(JsonWriter, MisuseIsAUsageError) {
  JsonWriter a;
  a.BeginObject();
  EXPECT_THROW(a.Number(1.0), UsageError);  // a value without a key
  JsonWriter b;
  b.BeginArray();
  EXPECT_THROW(b.Key("k"), UsageError);
  EXPECT_THROW(b.EndObject(), UsageError);
  EXPECT_THROW(b.Finish(), UsageError);  // still open
}

}  // namespace
}  // namespace cablefit::json
