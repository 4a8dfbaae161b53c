// A JSON text written as it is made, without building a tree first: for result files with
// thousands of numbers (solution profiles), where nlohmann's tree of heap nodes costs more than
// the solve that produced them. Keys come out in the order they are written; short arrays of
// numbers stay on one line so that the file reads like a table.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace cablefit::json {

class JsonWriter {
 public:
  /// `indent` spaces per level (the files people open: 2).
  explicit JsonWriter(int indent = 2);

  JsonWriter& BeginObject();
  JsonWriter& EndObject();
  JsonWriter& BeginArray();
  JsonWriter& EndArray();
  /// The next value's key; only inside an object.
  JsonWriter& Key(std::string_view key);

  /// Shortest round-trip text; null when not finite (JSON has no NaN).
  JsonWriter& Number(double value);
  JsonWriter& Integer(long long value);
  JsonWriter& Bool(bool value);
  JsonWriter& Null();
  /// Escaped as JSON requires; bytes that are not UTF-8 become U+FFFD.
  JsonWriter& String(std::string_view value);
  /// Numbers on one line: [x, y, z] (non-finite entries null).
  JsonWriter& Numbers(const Eigen::Ref<const Eigen::VectorXd>& values);
  JsonWriter& Integers(const std::vector<int>& values);
  /// A small tree made elsewhere (provenance), laid out like the rest.
  JsonWriter& Tree(const nlohmann::json& value);

  /// The text with a final newline; every object and array must be closed.
  std::string Finish();

 private:
  void BeforeValue();
  void NewLine();
  void AppendQuoted(std::string_view text);
  void AppendNumber(double value);
  void Close(char bracket, bool object);

  struct Level {
    bool object = false;
    int count = 0;
  };
  int indent_;
  std::string out_;
  std::vector<Level> stack_;
  bool after_key_ = false;
};

}  // namespace cablefit::json
