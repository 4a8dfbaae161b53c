#include "cablefit/formats/json_util.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/file_kind.h"
#include "cablefit/formats/input_file.h"
#include "cablefit/formats/number_text.h"

namespace cablefit::json {

Json ReadJsonFile(const std::string& path) {
  const std::string text = ReadInputFile(path, kMaxTextInputBytes, "a JSON file");
  // JSON leaves repeated keys undefined and the parser would keep the last one silently: a case
  // or harness file with two "length" entries must be refused, not read one way by us and another
  // way by the tool that wrote it.
  std::vector<std::set<std::string>> keys_of_open_objects;
  const auto refuse_repeated_keys = [&](int /*depth*/, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start: keys_of_open_objects.emplace_back(); break;
      case Json::parse_event_t::object_end: keys_of_open_objects.pop_back(); break;
      case Json::parse_event_t::key:
        if (!keys_of_open_objects.back().insert(parsed.get<std::string>()).second) {
          throw FileError(path, "key \"" + parsed.get<std::string>() +
                                    "\" appears twice in one object; remove one of them");
        }
        break;
      default: break;
    }
    return true;
  };
  try {
    return Json::parse(text, refuse_repeated_keys);
  } catch (const nlohmann::json::exception& e) {
    // parse_error, and out_of_range for literals such as 1e999 that overflow a double.
    std::string message = e.what();
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ..." -> drop the tag.
    const auto tag_end = message.find("] ");
    if (message.rfind("[json.exception", 0) == 0 && tag_end != std::string::npos)
      message = message.substr(tag_end + 2);
    // A file of another kind says what it is rather than where the JSON parser gave up.
    const FileKind kind = SniffFileKind(path);
    if (kind != FileKind::kUnknown && kind != FileKind::kJson)
      throw FileError(path, "not JSON: it is " + DescribeFileKind(kind));
    throw FileError(path, "not valid JSON: " + message);
  }
}

void WriteJsonFile(const std::string& path, const Json& value, int indent) {
  // A string that is not UTF-8 (a name out of a file that uses another encoding) is written with
  // U+FFFD for its bad bytes: one odd name must not cost the whole result file.
  const std::string text =
      value.dump(indent, ' ', false, Json::error_handler_t::replace) + "\n";
  WriteFileAtomically(path, text);
}

std::string JoinKey(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string IndexKey(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string Describe(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case Json::value_t::string: {
      std::string text = value.get<std::string>();
      if (text.size() > 40) text = text.substr(0, 40) + "...";
      return "string \"" + text + "\"";
    }
    case Json::value_t::array: return "an array";
    case Json::value_t::object: return "an object";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return FormatDouble(value.get<double>());
    default: return "an unsupported value";
  }
}

double NumberValue(const Json& value, const std::string& file, const std::string& name) {
  if (!value.is_number())
    throw FileError(file, name + " must be a number, got " + Describe(value));
  const double x = value.get<double>();
  // nlohmann turns literals such as 1e400 into inf.
  if (!std::isfinite(x)) throw FileError(file, name + " is not a finite number");
  return x;
}

FieldReader::FieldReader(const Json& object, std::string file, std::string where)
    : object_(object), file_(std::move(file)), where_(std::move(where)) {
  if (!object_.is_object())
    FailHere("must be a JSON object, got " + Describe(object_));
}

void FieldReader::Fail(const std::string& key, const std::string& problem) const {
  throw FileError(file_, JoinKey(where_, key) + " " + problem);
}

void FieldReader::FailHere(const std::string& problem) const {
  throw FileError(file_, where_.empty() ? problem : where_ + ": " + problem);
}

bool FieldReader::Has(const std::string& key) const { return object_.contains(key); }

const Json& FieldReader::Require(const std::string& key) const {
  const auto it = object_.find(key);
  if (it == object_.end()) throw FileError(file_, "missing field " + JoinKey(where_, key));
  return *it;
}

const Json& FieldReader::RequireObject(const std::string& key) const {
  const Json& v = Require(key);
  if (!v.is_object()) Fail(key, "must be an object, got " + Describe(v));
  return v;
}

const Json& FieldReader::RequireArray(const std::string& key) const {
  const Json& v = Require(key);
  if (!v.is_array()) Fail(key, "must be an array, got " + Describe(v));
  return v;
}

std::string FieldReader::RequireString(const std::string& key) const {
  const Json& v = Require(key);
  if (!v.is_string()) Fail(key, "must be a string, got " + Describe(v));
  return v.get<std::string>();
}

double FieldReader::RequireNumber(const std::string& key) const {
  return NumberValue(Require(key), file_, JoinKey(where_, key));
}

double FieldReader::RequirePositive(const std::string& key) const {
  const double x = RequireNumber(key);
  if (!(x > 0.0)) Fail(key, "must be positive, got " + FormatDouble(x));
  return x;
}

double FieldReader::RequireNonNegative(const std::string& key) const {
  const double x = RequireNumber(key);
  if (x < 0.0) Fail(key, "must not be negative, got " + FormatDouble(x));
  return x;
}

double FieldReader::OptionalNumber(const std::string& key, double fallback) const {
  return Has(key) ? RequireNumber(key) : fallback;
}

Vec3 FieldReader::RequireVec3(const std::string& key) const {
  const Json& v = Require(key);
  if (!v.is_array() || v.size() != 3)
    Fail(key, "must be an array of 3 numbers, got " +
                  (v.is_array() ? "an array of " + std::to_string(v.size()) : Describe(v)));
  const std::string name = JoinKey(where_, key);
  Vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = NumberValue(v[i], file_, IndexKey(name, i));
  return out;
}

FieldReader FieldReader::Child(const std::string& key) const {
  return FieldReader(RequireObject(key), file_, JoinKey(where_, key));
}

Json NumberOrNull(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json ToJson(const Vec3& v) { return Json::array({NumberOrNull(v.x()), NumberOrNull(v.y()), NumberOrNull(v.z())}); }

Json MatrixToJson(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    Json row = Json::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(NumberOrNull(m(r, c)));
    rows.push_back(std::move(row));
  }
  return rows;
}

void RequireKnownKeys(const FieldReader& r, const std::set<std::string>& allowed) {
  for (auto it = r.object().begin(); it != r.object().end(); ++it) {
    if (!allowed.count(it.key())) r.Fail(it.key(), "is not a known field");
  }
}

}  // namespace cablefit::json
