#include "ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cablefit::render {

double NiceNumber(double x, bool round) {
  const double exponent = std::floor(std::log10(x));
  const double fraction = x / std::pow(10.0, exponent);
  double nice;
  if (round)
    nice = fraction < 1.5 ? 1 : fraction < 3 ? 2 : fraction < 7 ? 5 : 10;
  else
    nice = fraction <= 1 ? 1 : fraction <= 2 ? 2 : fraction <= 5 ? 5 : 10;
  return nice * std::pow(10.0, exponent);
}

Ticks NiceTicks(double lo, double hi, int target) {
  Ticks ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) {
    ticks.values = {std::isfinite(lo) ? lo : 0.0};
    return ticks;
  }
  const double range = NiceNumber(hi - lo, false);
  ticks.step = NiceNumber(range / std::max(1, target - 1), true);
  const double first = std::ceil(lo / ticks.step - 1e-9) * ticks.step;
  for (double v = first; v <= hi + ticks.step * 1e-9; v += ticks.step)
    ticks.values.push_back(std::abs(v) < ticks.step * 1e-9 ? 0.0 : v);
  ticks.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(ticks.step) + 1e-9)));
  return ticks;
}

std::string FormatTick(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string text(buffer);
  if (text.find_first_not_of("-0.") == std::string::npos) return std::string(text.size() > 1 && text[0] == '-' ? text.substr(1) : text);
  if (text[0] == '-') text = "\u2212" + text.substr(1);  // typographic minus
  return text;
}

}  // namespace cablefit::render
