// Axis ticks at "nice" values (1, 2, 5 x 10^k) and their labels.
// Source: P. S. Heckbert, "Nice numbers for graph labels", Graphics Gems I (1990), 61-63.
#pragma once

#include <string>
#include <vector>

namespace cablefit::render {

struct Ticks {
  double step = 1.0;
  std::vector<double> values;  // ascending, inside [lo, hi] (plus rounding slack)
  int decimals = 0;            // digits after the point needed to tell ticks apart
};

/// A nice number close to `x` > 0: rounded (nearest) or not smaller (ceiling).
double NiceNumber(double x, bool round);
/// About `target` ticks covering [lo, hi].
Ticks NiceTicks(double lo, double hi, int target);
/// `value` printed with `decimals` digits, "-0" shown as "0", with a proper minus sign.
std::string FormatTick(double value, int decimals);

}  // namespace cablefit::render
