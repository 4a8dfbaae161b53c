// How far a rendered pixel is from the colour a picture test looks for.
#pragma once

#include <cmath>

#include "cablefit/formats/image.h"

namespace cablefit::testing {

/// Euclidean distance between two colours in 8-bit RGB units (0 .. 441).
inline double ColourDistance(const Rgb& a, const Rgb& b) {
  const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return std::sqrt(dr * dr + dg * dg + db * db);
}

}  // namespace cablefit::testing
