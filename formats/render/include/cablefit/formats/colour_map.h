// Perceptually uniform colour map and the value -> colour scale used by maps and colour bars.
#pragma once

#include <string>

#include "cablefit/formats/image.h"

namespace cablefit {

/// Viridis (van der Walt & Smith, matplotlib 2015, CC0): perceptually uniform, readable in
/// grey-scale and by the colour-blind. `t` in [0, 1] (clamped; NaN maps to the bottom colour).
Rgb Viridis(double t);

/// A linear value range mapped onto the colour map, e.g. deviation in millimetres.
struct ColourScale {
  double min = 0.0;  // value shown with the bottom colour
  double max = 1.0;  // value shown with the top colour (> min)
  std::string label = "deviation [mm]";

  /// Position of `value` on the scale, clamped to [0, 1].
  double Normalised(double value) const;
  Rgb Map(double value) const { return Viridis(Normalised(value)); }
  /// True when min < max and both are finite.
  bool IsValid(std::string* why) const;
};

}  // namespace cablefit
