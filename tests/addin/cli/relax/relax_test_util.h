// Helpers shared by the relax CLI tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::testing {

/// The cable object named `name` of a `cablefit-relax/1` file.
inline const json::Json& CableNamed(const json::Json& file, const std::string& name) {
  for (const json::Json& c : file.at("cables"))
    if (c.at("name") == name) return c;
  throw std::runtime_error("no cable " + name);
}

/// [m] The farthest any row of `varied`'s relaxed centreline is from the polyline of
/// `nominal`'s (two cable objects of `cablefit-relax/1` files): a tolerance excursion measured
/// from the outputs.
inline double FarthestFromCentreline(const json::Json& nominal, const json::Json& varied) {
  const json::Json& a = nominal.at("relaxed_centreline").at("rows");
  const json::Json& b = varied.at("relaxed_centreline").at("rows");
  auto row = [](const json::Json& r) {
    return Vec3(r[1].get<double>(), r[2].get<double>(), r[3].get<double>());
  };
  double far = 0.0;
  for (const json::Json& rb : b) {
    const Vec3 p = row(rb);
    double best = INFINITY;
    for (size_t i = 0; i + 1 < a.size(); ++i) {
      const Vec3 x0 = row(a[i]), d = row(a[i + 1]) - x0;
      const double t =
          d.squaredNorm() > 0 ? std::clamp((p - x0).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (p - (x0 + t * d)).norm());
    }
    far = std::max(far, best);
  }
  return far;
}

}  // namespace cablefit::testing
