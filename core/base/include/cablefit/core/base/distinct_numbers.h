// Two numbers in one error message that must read as different: "0.0201 m apart but only
// 0.0201 m of cable" hides the very difference the message is about.
#pragma once

#include <string>
#include <utility>

namespace cablefit {

/// `a` and `b` with 4 significant digits, or as many more (up to 17) as it takes for their texts
/// to differ when the values do.
std::pair<std::string, std::string> DistinctNumbers(double a, double b);

}  // namespace cablefit
