#include "cablefit/formats/truth_reader.h"

#include <filesystem>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/json_util.h"

namespace cablefit {
namespace {

constexpr const char* kTruthFormat = "cable-truth/1";

std::string TruthFilePath(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return (std::filesystem::path(path) / "truth.json").string();
  return path;
}

json::Json ReadTruthDocument(const std::string& file) {
  json::Json doc = json::ReadJsonFile(file);
  const json::FieldReader root(doc, file);
  const std::string format = root.RequireString("format");
  if (format != kTruthFormat)
    root.Fail("format", "is '" + format + "', expected '" + kTruthFormat + "'");
  return doc;
}

}  // namespace

CaseTruth ReadTruth(const std::string& path) {
  const std::string file = TruthFilePath(path);
  const json::Json doc = ReadTruthDocument(file);
  const json::FieldReader root(doc, file);
  CaseTruth truth;
  truth.case_name = root.RequireString("case");
  truth.effect = root.RequireString("effect");
  if (root.Has("interval") && !doc["interval"].is_null()) {
    const json::Json& iv = doc["interval"];
    if (!iv.is_array() || iv.size() != 2) root.Fail("interval", "must be null or [s_start, s_end]");
    truth.interval = std::make_pair(json::NumberValue(iv[0], file, "interval[0]"),
                                    json::NumberValue(iv[1], file, "interval[1]"));
  }
  if (root.Has("clamp") && !doc["clamp"].is_null()) {
    const json::Json& c = doc["clamp"];
    if (!c.is_number_integer() || c.get<long>() < 0)
      root.Fail("clamp", "must be null or a clamp index, got " + json::Describe(c));
    truth.clamp = c.get<int>();
  }
  if (root.Has("parameters")) {
    for (const auto& [name, value] : root.RequireObject("parameters").items()) {
      if (value.is_number())
        truth.parameters[name] = json::NumberValue(value, file, "parameters." + name);
    }
  }
  return truth;
}

Polyline ReadTruthCenterline(const std::string& path, const std::string& key) {
  const std::string file = TruthFilePath(path);
  const json::Json doc = ReadTruthDocument(file);
  const json::FieldReader root(doc, file);
  const json::FieldReader curve = root.Child("extra").Child(key);
  const json::Json& s = curve.RequireArray("s");
  const json::Json& xyz = curve.RequireArray("xyz");
  const std::string where = "extra." + key;
  if (s.size() != xyz.size())
    curve.FailHere("has " + std::to_string(s.size()) + " arc lengths but " +
                   std::to_string(xyz.size()) + " points");
  if (s.size() < 2) curve.FailHere("needs at least 2 points");
  Polyline line;
  const auto n = static_cast<Eigen::Index>(s.size());
  line.s.resize(n);
  line.points.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    line.s[i] = json::NumberValue(s[i], file, json::IndexKey(where + ".s", i));
    const json::Json& p = xyz[i];
    const std::string name = json::IndexKey(where + ".xyz", i);
    if (!p.is_array() || p.size() != 3)
      throw FileError(file, name + " must be an array of 3 numbers");
    for (int k = 0; k < 3; ++k) line.points(k, i) = json::NumberValue(p[k], file, json::IndexKey(name, k));
    if (i > 0 && line.s[i] < line.s[i - 1]) throw FileError(file, where + ".s decreases at index " + std::to_string(i));
  }
  return line;
}

}  // namespace cablefit
