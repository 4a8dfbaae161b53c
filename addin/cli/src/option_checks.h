// Checks of numeric options that CLI11's own validators let through: NaN passes every range
// check (all comparisons with NaN are false) and "inf" is a number to strtod.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <string>

namespace cablefit::addin {

/// A time limit in seconds: a finite number >= 0 (0 = no limit). At most a year, because a larger
/// value is a typo and would overflow the deadline clock.
inline CLI::Validator TimeoutSeconds() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !std::isfinite(v) || v < 0 || v > 3.2e7) {
          return "must be a number of seconds from 0 (no limit) to 3.2e7, got '" + text + "'";
        }
        return {};
      },
      "SECONDS");
}

/// A worker count: a whole number from 0 (one per core) to 1024.
inline CLI::Validator JobCount() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const long v = std::strtol(text.c_str(), &end, 10);
        if (end == text.c_str() || *end != '\0' || v < 0 || v > 1024) {
          return "must be a whole number from 0 (one per core) to 1024, got '" + text + "'";
        }
        return {};
      },
      "N");
}

}  // namespace cablefit::addin
