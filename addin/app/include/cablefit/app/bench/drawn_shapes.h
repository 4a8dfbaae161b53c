// Single cables drawn in shapes that are hard to relax from: a coil and a long spring drawn as
// curves, a zig-zag of right-angle kinks, a stretch drawn nearly taut. Each is clamped at both
// ends as drawn. Built for `cablefit bench` (one row per shape).
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/network/network_spec.h"

namespace cablefit::addin {

struct DrawnShapeCase {
  std::string name;            ///< the bench row's name ("drawn_spring_30_turns")
  NetworkSpec spec;            ///< one branch, clamped at both drawn ends
  double element_length = 0.0; ///< [m] the resolution to solve it at
};

/// The shapes, in a fixed order.
std::vector<DrawnShapeCase> DrawnShapeCases();

}  // namespace cablefit::addin
