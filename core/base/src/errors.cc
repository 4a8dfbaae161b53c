#include "cablefit/core/base/errors.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace cablefit {

std::string OneLine(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u != 0x7f) {
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += ' ';
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    }
  }
  return out;
}

void AbortOnBrokenInvariant(const char* condition, const char* file, int line,
                            const std::string& message) {
  std::fprintf(stderr, "cablefit: internal error: %s (%s) at %s:%d\n", message.c_str(), condition,
               file, line);
  std::abort();
}

std::string MessageNumber(double value) {
  std::ostringstream os;
  os.precision(4);
  os << value;
  return os.str();
}

}  // namespace cablefit
