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

}  // namespace cablefit::addin
