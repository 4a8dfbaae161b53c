// Small builders for rod-network tests.
#pragma once

#include <cmath>

#include "cablefit/core/network/network_spec.h"

namespace cablefit::testing {

inline MaterialSpec TestMaterial(double ei = 0.05, double density = 0.1, double diameter = 0.008) {
  MaterialSpec m;
  m.bending_stiffness = ei;                // [N m^2]
  m.torsional_stiffness = ei / 1.3;        // [N m^2]
  m.linear_density = density;              // [kg/m]
  m.diameter = diameter;                   // [m]
  return m;
}

inline Polyline StraightRoute(const Vec3& a, const Vec3& b) {
  Polyline p;
  p.points.resize(3, 2);
  p.points.col(0) = a;
  p.points.col(1) = b;
  p.ParameteriseByChords();
  return p;
}

inline SupportSpec Clamp(double s, const Vec3& position, const Vec3& tangent,
                         const Vec3& normal = Vec3::UnitZ()) {
  SupportSpec sp;
  sp.kind = SupportKind::kClamp;
  sp.s = s;
  sp.position = position;
  sp.tangent = tangent;
  sp.normal = normal;
  return sp;
}

}  // namespace cablefit::testing
