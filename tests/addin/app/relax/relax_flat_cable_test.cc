// A flat cable relaxes with its anisotropic section, held at its clamps by its drawn wide axis:
// a cantilevered strip flat side up sags by the flatwise EI, the same strip on edge by the
// edgewise EI (25 times stiffer for 10 x 2 mm).
#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/app/relax/relax_cable.h"

namespace cablefit::addin {
namespace {

constexpr double kLength = 0.06, kWidth = 0.010, kThickness = 0.002;  // [m]

// A straight horizontal strip along x, its wide axis `wide` at every point.
HarnessDrawing Strip(const Vec3& wide) {
  DrawnCable c;
  c.name = "strip";
  const int n = 31;
  c.centreline.points.resize(3, n);
  for (int i = 0; i < n; ++i) c.centreline.points.col(i) = Vec3(kLength * i / (n - 1), 0, 0.1);
  c.centreline.ParameteriseByChords();
  c.diameter = kWidth;
  c.source = CableSourceKind::kTube;
  FlatSection f;
  f.width = kWidth;
  f.thickness = kThickness;
  f.wide_axes = wide.replicate(1, n);
  c.flat = f;
  HarnessDrawing d;
  d.cables.push_back(c);
  return d;
}

// Tip deflection of the strip clamped at x = 0, free at the other end.
double TipSag(const Vec3& wide, CableRelaxation* out = nullptr) {
  HarnessConfig config;
  EndConfig free_end;
  free_end.free = true;
  config.defaults.end = free_end;
  const HarnessDrawing d = Strip(wide);
  CableRelaxation r = RelaxCable(SetUpCable(d, 0, {}, config), SimulationOptions{}, 5.0);
  EXPECT_TRUE(r.ok());
  const double sag = 0.1 - r.relaxed.points(2, r.relaxed.size() - 1);
  if (out) *out = std::move(r);
  return sag;
}

TEST(RelaxFlatCable, ACantileverSagsByTheFlatwiseOrEdgewiseStiffnessOfItsDrawnSection) {
  CableRelaxation flat;
  const double flat_sag = TipSag(Vec3::UnitY(), &flat);
  const double edge_sag = TipSag(Vec3::UnitZ());
  const MaterialSpec& m = flat.setup.spec.material;
  // Rectangle: I = w t^3 / 12 flatwise, t w^3 / 12 edgewise, with the bundle's modulus.
  const double ei_flat = kDefaultBundleModulus * kWidth * std::pow(kThickness, 3) / 12;
  const double ei_edge = kDefaultBundleModulus * kThickness * std::pow(kWidth, 3) / 12;
  EXPECT_NEAR(m.bending_ratio, ei_edge / ei_flat, 1e-9);
  EXPECT_NEAR(m.bending_stiffness, std::sqrt(ei_flat * ei_edge), 1e-12);
  // Cantilever under its own weight q: tip deflection q L^4 / (8 EI) (Timoshenko & Gere,
  // Mechanics of Materials, table of beam deflections), small here (2 % of L), so linear
  // theory holds to well under 1 %.
  const double q = m.linear_density * 9.81;
  EXPECT_NEAR(flat_sag, q * std::pow(kLength, 4) / (8 * ei_flat), 0.01 * flat_sag);
  EXPECT_NEAR(edge_sag, q * std::pow(kLength, 4) / (8 * ei_edge), 0.01 * edge_sag);
  // An isotropic rod of the mean EI would sag the same either way.
  EXPECT_GT(flat_sag / edge_sag, 20.0);
}

}  // namespace
}  // namespace cablefit::addin
