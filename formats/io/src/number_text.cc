#include "cablefit/formats/number_text.h"

#include <charconv>
#include <cmath>

namespace cablefit {
namespace {

std::string_view Trim(std::string_view text) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

}  // namespace

std::string FormatDouble(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof(buf), value);
  return std::string(buf, result.ptr);
}

ParsedNumber ParseDouble(std::string_view text, double* value) {
  text = Trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return ParsedNumber::kNotANumber;
  double parsed = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (result.ptr != text.data() + text.size()) return ParsedNumber::kNotANumber;
  if (result.ec == std::errc::result_out_of_range) {
    // from_chars leaves the value unset on overflow; underflow to zero is harmless but overflow
    // is a number no physical quantity here can have.
    const auto exp = text.find_first_of("eE");
    const bool tiny = exp != std::string_view::npos && exp + 1 < text.size() && text[exp + 1] == '-';
    if (tiny) {
      *value = 0.0;
      return ParsedNumber::kFinite;
    }
    *value = text.front() == '-' ? -HUGE_VAL : HUGE_VAL;
    return ParsedNumber::kInfinite;
  }
  if (result.ec != std::errc()) return ParsedNumber::kNotANumber;
  *value = parsed;
  if (std::isnan(parsed)) return ParsedNumber::kNaN;
  if (std::isinf(parsed)) return ParsedNumber::kInfinite;
  return ParsedNumber::kFinite;
}

bool ParseInteger(std::string_view text, long* value) {
  text = Trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  long parsed = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return false;
  *value = parsed;
  return true;
}

}  // namespace cablefit
