// The set-up the effect-model tests share: a 1 m cable between two clamps 0.8 m apart, recorded
// as drawn straight from the first clamp to the second.
#pragma once

#include <vector>

#include "shape_effects.h"

namespace cablefit::testing {

inline RodSpec TwoClamps() {
  RodSpec spec;
  spec.length = 1.0;
  spec.material.bending_stiffness = 0.02;
  spec.material.torsional_stiffness = 0.015;
  spec.material.linear_density = 0.05;
  spec.material.diameter = 0.008;
  SupportSpec a;
  a.position = Vec3(0, 0, 0);
  a.tangent = Vec3(1, 0, 0);
  a.normal = Vec3(0, 0, 1);
  SupportSpec b = a;
  b.s = 1.0;
  b.position = Vec3(0.8, 0, 0);
  spec.supports = {a, b};
  return spec;
}

/// The effect models for `nominal` recorded straight between its first and last clamp, with the
/// nominal reaction moments `moments` [N m].
inline std::vector<EffectModel> StraightRecordingModels(const RodSpec& nominal,
                                                        const std::vector<double>& moments) {
  const Vec3 a = nominal.supports.front().position, b = nominal.supports.back().position;
  Eigen::Matrix3Xd points(3, 11);
  Eigen::VectorXd s(11);
  for (int i = 0; i <= 10; ++i) {
    points.col(i) = a + (b - a) * (i / 10.0);
    s[i] = nominal.length * i / 10.0;
  }
  return BuildEffectModels(nominal, moments, points, s);
}

}  // namespace cablefit::testing
