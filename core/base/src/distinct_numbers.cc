#include "cablefit/core/base/distinct_numbers.h"

#include <sstream>

namespace cablefit {
namespace {

std::string WithDigits(double value, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << value;
  return os.str();
}

}  // namespace

std::pair<std::string, std::string> DistinctNumbers(double a, double b) {
  int digits = 4;
  while (digits < 17 && a != b && WithDigits(a, digits) == WithDigits(b, digits)) ++digits;
  return {WithDigits(a, digits), WithDigits(b, digits)};
}

}  // namespace cablefit
