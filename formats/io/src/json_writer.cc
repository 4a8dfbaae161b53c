#include "cablefit/formats/json_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "cablefit/core/base/errors.h"

namespace cablefit::json {

JsonWriter::JsonWriter(int indent) : indent_(indent) { out_.reserve(1 << 16); }

void JsonWriter::NewLine() {
  out_ += '\n';
  out_.append(static_cast<size_t>(indent_) * stack_.size(), ' ');
}

void JsonWriter::BeforeValue() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  CABLEFIT_REQUIRE(stack_.empty() ? out_.empty() : !stack_.back().object,
                   "JsonWriter: a value inside an object needs a key");
  if (stack_.empty()) return;
  if (stack_.back().count++ > 0) out_ += ',';
  NewLine();
}

JsonWriter& JsonWriter::Key(std::string_view key) {
  CABLEFIT_REQUIRE(!stack_.empty() && stack_.back().object && !after_key_,
                   "JsonWriter: a key outside an object");
  if (stack_.back().count++ > 0) out_ += ',';
  NewLine();
  AppendQuoted(key);
  out_ += ": ";
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::BeginObject() {
  BeforeValue();
  out_ += '{';
  stack_.push_back({true, 0});
  return *this;
}

JsonWriter& JsonWriter::BeginArray() {
  BeforeValue();
  out_ += '[';
  stack_.push_back({false, 0});
  return *this;
}

void JsonWriter::Close(char bracket, bool object) {
  CABLEFIT_REQUIRE(!stack_.empty() && stack_.back().object == object && !after_key_,
                   "JsonWriter: unbalanced close");
  const bool empty = stack_.back().count == 0;
  stack_.pop_back();
  if (!empty) NewLine();
  out_ += bracket;
}

JsonWriter& JsonWriter::EndObject() {
  Close('}', true);
  return *this;
}

JsonWriter& JsonWriter::EndArray() {
  Close(']', false);
  return *this;
}

void JsonWriter::AppendNumber(double value) {
  if (!std::isfinite(value)) {
    out_ += "null";
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), value);
  out_.append(buf, r.ptr);
}

JsonWriter& JsonWriter::Number(double value) {
  BeforeValue();
  AppendNumber(value);
  return *this;
}

JsonWriter& JsonWriter::Integer(long long value) {
  BeforeValue();
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof(buf), value);
  out_.append(buf, r.ptr);
  return *this;
}

JsonWriter& JsonWriter::Bool(bool value) {
  BeforeValue();
  out_ += value ? "true" : "false";
  return *this;
}

JsonWriter& JsonWriter::Null() {
  BeforeValue();
  out_ += "null";
  return *this;
}

void JsonWriter::AppendQuoted(std::string_view text) {
  // Keys and most values are plain printable ASCII: copied as they are. Anything else goes
  // through nlohmann's escaping and its U+FFFD replacement, so that both writers agree on odd
  // names.
  const bool plain = std::all_of(text.begin(), text.end(), [](char c) {
    return c >= 0x20 && c < 0x7f && c != '"' && c != '\\';
  });
  if (plain) {
    out_ += '"';
    out_ += text;
    out_ += '"';
    return;
  }
  out_ += nlohmann::json(std::string(text)).dump(-1, ' ', false,
                                                 nlohmann::json::error_handler_t::replace);
}

JsonWriter& JsonWriter::String(std::string_view value) {
  BeforeValue();
  AppendQuoted(value);
  return *this;
}

JsonWriter& JsonWriter::Numbers(const Eigen::Ref<const Eigen::VectorXd>& values) {
  BeforeValue();
  out_ += '[';
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (i > 0) out_ += ", ";
    AppendNumber(values[i]);
  }
  out_ += ']';
  return *this;
}

JsonWriter& JsonWriter::Integers(const std::vector<int>& values) {
  BeforeValue();
  out_ += '[';
  for (size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out_ += ", ";
    out_ += std::to_string(values[i]);
  }
  out_ += ']';
  return *this;
}

JsonWriter& JsonWriter::Tree(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::object:
      BeginObject();
      for (const auto& [key, item] : value.items()) Key(key).Tree(item);
      return EndObject();
    case nlohmann::json::value_t::array:
      BeginArray();
      for (const auto& item : value) Tree(item);
      return EndArray();
    case nlohmann::json::value_t::string: return String(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean: return Bool(value.get<bool>());
    case nlohmann::json::value_t::number_integer: return Integer(value.get<long long>());
    case nlohmann::json::value_t::number_unsigned:
      return Integer(static_cast<long long>(value.get<unsigned long long>()));
    case nlohmann::json::value_t::number_float: return Number(value.get<double>());
    default: return Null();
  }
}

std::string JsonWriter::Finish() {
  CABLEFIT_REQUIRE(stack_.empty() && !after_key_, "JsonWriter: unclosed object or array");
  out_ += '\n';
  return std::move(out_);
}

}  // namespace cablefit::json
