#include "cablefit/app/bench/drawn_shapes.h"

#include <cmath>

#include "cablefit/core/base/helix.h"

namespace cablefit::addin {
namespace {

MaterialSpec Material(double ei, double density, double diameter) {
  MaterialSpec m;
  m.bending_stiffness = ei;         // [N m^2]
  m.torsional_stiffness = ei / 1.3; // [N m^2], a solid round section
  m.linear_density = density;       // [kg/m]
  m.diameter = diameter;            // [m]
  return m;
}

Polyline Corners(const std::vector<Vec3>& corners) {
  Polyline z;
  z.points.resize(3, static_cast<Eigen::Index>(corners.size()));
  for (size_t k = 0; k < corners.size(); ++k) z.points.col(static_cast<Eigen::Index>(k)) = corners[k];
  z.ParameteriseByChords();
  return z;
}

// A sine wave of one period across `span` [m] whose arc length exceeds the span by `slack`.
Polyline NearlyTaut(double span, double slack) {
  const int n = 121;
  // Arc length of a sin(2 pi x / L) over one period ~ L (1 + (pi a / L)^2).
  const double amp = span * std::sqrt(slack) / M_PI;
  Polyline w;
  w.points.resize(3, n);
  for (int k = 0; k < n; ++k) {
    const double x = span * k / (n - 1);
    w.points.col(k) = Vec3(x, 0, amp * std::sin(2 * M_PI * x / span));
  }
  w.ParameteriseByChords();
  return w;
}

SupportSpec ClampAt(const Polyline& route, bool at_end) {
  const int n = route.size();
  SupportSpec sp;
  sp.kind = SupportKind::kClamp;
  sp.s = at_end ? route.s[n - 1] : 0.0;
  sp.position = route.points.col(at_end ? n - 1 : 0);
  sp.tangent = at_end ? Vec3((route.points.col(n - 1) - route.points.col(n - 2)).normalized())
                      : Vec3((route.points.col(1) - route.points.col(0)).normalized());
  sp.normal = sp.tangent.cross(Vec3::UnitZ()).norm() > 0.1 ? Vec3::UnitZ() : Vec3::UnitX();
  return sp;
}

DrawnShapeCase Clamped(const std::string& name, const Polyline& route, const MaterialSpec& m,
                       double element_length) {
  BranchSpec b;
  b.name = name;
  b.length = route.s[route.size() - 1];
  b.material = m;
  b.route = route;
  b.supports = {ClampAt(route, false), ClampAt(route, true)};
  DrawnShapeCase c;
  c.name = name;
  c.spec.name = name;
  c.spec.branches = {b};
  c.element_length = element_length;
  return c;
}

}  // namespace

std::vector<DrawnShapeCase> DrawnShapeCases() {
  const MaterialSpec spring_wire = Material(0.02, 0.05, 0.004);
  std::vector<DrawnShapeCase> cases;
  cases.push_back(Clamped("drawn_coil_5_turns", SampleHelix(0.02, 0.012, 5), spring_wire, 0.01));
  cases.push_back(Clamped("drawn_spring_30_turns", SampleHelix(0.02, 0.02, 30), spring_wire, 0.02));
  cases.push_back(Clamped("drawn_kinks",
                          Corners({Vec3(0, 0, 0), Vec3(0.15, 0, 0), Vec3(0.15, 0, -0.15),
                                   Vec3(0.3, 0, -0.15), Vec3(0.3, 0, 0), Vec3(0.45, 0, 0)}),
                          Material(0.05, 0.1, 0.008), 0.01));
  cases.push_back(Clamped("drawn_taut_0.2_pct", NearlyTaut(0.6, 0.002),
                          Material(0.01, 0.1, 0.006), 0.01));
  return cases;
}

}  // namespace cablefit::addin
