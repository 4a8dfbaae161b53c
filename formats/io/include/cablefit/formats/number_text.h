// Text <-> double conversions shared by the CSV, PLY and JSON code: strict parsing (a whole cell
// or nothing, locale independent) and shortest round-trip formatting.
#pragma once

#include <string>
#include <string_view>

namespace cablefit {

/// Shortest text that reads back to exactly `value` (std::to_chars); "nan", "inf", "-inf" for
/// non-finite values.
std::string FormatDouble(double value);

enum class ParsedNumber { kFinite, kNaN, kInfinite, kNotANumber };

/// Parses all of `text` (surrounding spaces and a leading '+' allowed) as a double. Accepts
/// "nan"/"inf" spellings so callers can report them as such; kNotANumber leaves `*value` untouched.
ParsedNumber ParseDouble(std::string_view text, double* value);

/// Parses all of `text` as a base-10 integer.
bool ParseInteger(std::string_view text, long* value);

}  // namespace cablefit
