// nlohmann::json helpers for every reader and writer of JSON files: validated field access that
// throws one-line FileErrors naming the file and the field ("cable.length must be positive"), and
// conversions of Eigen values for output. nlohmann types stay out of the other public headers.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::json {

using Json = nlohmann::json;

/// Parses a JSON file. Throws FileError when it is missing, unreadable or not valid JSON (the
/// message keeps nlohmann's line/column but drops its "[json.exception...]" prefix).
Json ReadJsonFile(const std::string& path);

/// Writes `value` atomically with `indent` spaces (-1 = compact). Doubles are written in
/// shortest round-trip form, NaN/Inf as null.
void WriteJsonFile(const std::string& path, const Json& value, int indent = 2);

/// Dotted field name for messages: JoinKey("clamps[0]", "s") == "clamps[0].s"; an empty
/// parent gives just `key`.
std::string JoinKey(const std::string& parent, const std::string& key);
/// "clamps" + 2 -> "clamps[2]".
std::string IndexKey(const std::string& parent, std::size_t index);

/// Read access to an object's fields with validation. `where` is the dotted name of `object`
/// inside the file ("" for the root); every failure throws FileError(file, "<field> ...").
/// The reader keeps a reference: `object` must outlive it.
class FieldReader {
 public:
  FieldReader(const Json& object, std::string file, std::string where = "");

  bool Has(const std::string& key) const;
  const Json& RequireObject(const std::string& key) const;
  const Json& RequireArray(const std::string& key) const;
  std::string RequireString(const std::string& key) const;
  /// A finite number (strings such as "NaN" or "1e400" are rejected with the value quoted).
  double RequireNumber(const std::string& key) const;
  /// A finite number > 0.
  double RequirePositive(const std::string& key) const;
  /// A finite number >= 0.
  double RequireNonNegative(const std::string& key) const;
  /// `fallback` when absent; validated like RequireNumber when present.
  double OptionalNumber(const std::string& key, double fallback) const;
  /// An array of three finite numbers.
  Vec3 RequireVec3(const std::string& key) const;

  /// A reader for the object in field `key`.
  FieldReader Child(const std::string& key) const;
  /// Throws FileError(file, "<where.key>: <problem>").
  [[noreturn]] void Fail(const std::string& key, const std::string& problem) const;
  /// Throws FileError(file, "<where>: <problem>") (just `problem` at the root).
  [[noreturn]] void FailHere(const std::string& problem) const;

  const Json& object() const { return object_; }
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }

 private:
  const Json& Require(const std::string& key) const;
  const Json& object_;
  std::string file_;
  std::string where_;
};

/// Validates that `value` (the field called `name` in `file`) is a finite number and returns it.
double NumberValue(const Json& value, const std::string& file, const std::string& name);

/// Short description of a JSON value's type for messages ("string \"NaN\"", "array", ...).
std::string Describe(const Json& value);

// ---- output ----

/// A number, or null when not finite (JSON has no NaN).
Json NumberOrNull(double value);
/// [x, y, z].
Json ToJson(const Vec3& v);
/// Row-major nested arrays: [[row 0], [row 1], ...]; non-finite entries become null.
Json MatrixToJson(const Eigen::MatrixXd& m);

/// Rejects fields of `r`'s object outside `allowed` (FileError naming the field), so a typo in a
/// hand-written file is an error, not a silently ignored default.
void RequireKnownKeys(const FieldReader& r, const std::set<std::string>& allowed);

}  // namespace cablefit::json
