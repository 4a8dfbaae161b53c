// The relax command's private geometry: tangents and twist-free frames on drawn routes, and
// clips found from the solids a route passes through.
#include "relax/relax_route.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cablefit/app/relax/relax_clips.h"

namespace cablefit::addin {
namespace {

// A line of 0.1 m given by its two ends, then a quarter circle of radius 0.05 m sampled every
// ~1 mm: the uneven sampling CAD curves come with.
Polyline LineThenArc() {
  std::vector<Vec3> p = {Vec3(-0.1, 0, 0)};
  for (int i = 0; i <= 80; ++i) {
    const double a = 0.5 * M_PI * i / 80;
    p.push_back(Vec3(0.05 * std::sin(a), 0, 0.05 * (1 - std::cos(a))));
  }
  Polyline route;
  route.points.resize(3, static_cast<Eigen::Index>(p.size()));
  for (size_t i = 0; i < p.size(); ++i) route.points.col(static_cast<Eigen::Index>(i)) = p[i];
  return route;
}

TEST(RelaxRoute, TangentsAreAccurateDespiteUnevenSampling) {
  const Polyline route = CleanRoute(LineThenArc());
  const double length = route.s[route.size() - 1];
  EXPECT_NEAR(length, 0.1 + 0.025 * M_PI, 1e-4);  // chords of the arc fall short by O(h^2)
  EXPECT_LT((RouteTangent(route, 0.0) - Vec3::UnitX()).norm(), 1e-9);
  EXPECT_LT((RouteTangent(route, 0.05) - Vec3::UnitX()).norm(), 1e-9);
  EXPECT_LT((RouteTangent(route, length) - Vec3::UnitZ()).norm(), 1e-4);
  // Mid-arc: 45 degrees.
  EXPECT_LT((RouteTangent(route, 0.1 + 0.0125 * M_PI) - Vec3(1, 0, 1).normalized()).norm(), 1e-4);
}

// Radius of the circle through three points (infinite when they are collinear).
double Circumradius(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double area2 = (b - a).cross(c - a).norm();
  return area2 > 0 ? (b - a).norm() * (c - b).norm() * (c - a).norm() / (2 * area2)
                   : std::numeric_limits<double>::infinity();
}

TEST(RelaxRoute, RoundedRouteTurnsACornerIntoABendOfAboutTheWidth) {
  // Two legs of 0.1 m meeting at a right angle, as a degree-1 KBL centre curve draws it.
  Polyline corner;
  corner.points.resize(3, 3);
  corner.points << 0, 0.1, 0.1,  //
      0, 0, 0.1,                 //
      0, 0, 0;
  const double width = 0.01;
  const Polyline rounded = RoundedRoute(CleanRoute(corner), width);
  // The ends stay, and so do the legs away from the corner.
  EXPECT_LT((rounded.points.col(0) - Vec3(0, 0, 0)).norm(), 1e-12);
  EXPECT_LT((rounded.points.col(rounded.size() - 1) - Vec3(0.1, 0.1, 0)).norm(), 1e-12);
  double tightest = std::numeric_limits<double>::infinity(), off_legs = 0, far_off = 0;
  for (Eigen::Index i = 1; i + 1 < rounded.size(); ++i) {
    const Vec3 p = rounded.points.col(i);
    tightest = std::min(tightest, Circumradius(rounded.points.col(i - 1), p, rounded.points.col(i + 1)));
    const double to_legs = std::min(std::hypot(p.y(), p.z()) + std::max(0.0, p.x() - 0.1),
                                    std::hypot(p.x() - 0.1, p.z()) + std::max(0.0, -p.y()));
    off_legs = std::max(off_legs, to_legs);
    if ((p - Vec3(0.1, 0, 0)).norm() > 2 * width) far_off = std::max(far_off, to_legs);
  }
  EXPECT_GT(tightest, 0.25 * width);  // a bend the writer's spline and sweep can follow
  EXPECT_LT(off_legs, 0.5 * width);   // still the drawn route, to a fraction of the diameter
  EXPECT_LT(far_off, 1e-9);           // the Gaussian reaches 3 sigma = 1.5 widths, no further
}

TEST(RelaxRoute, RoundedRouteLeavesAStraightRouteAndAGentleArcAlmostAlone) {
  Polyline line;
  line.points.resize(3, 2);
  line.points << 0, 0.3, 0, 0.1, 0, -0.2;
  const Polyline straight = RoundedRoute(CleanRoute(line), 0.02);
  for (Eigen::Index i = 0; i < straight.size(); ++i) {
    const Vec3 p = straight.points.col(i);
    EXPECT_LT(p.cross(Vec3(0.3, 0.1, -0.2).normalized()).norm(), 1e-12);
  }
  EXPECT_NEAR(straight.s[straight.size() - 1], std::sqrt(0.14), 1e-12);
  // The arc of LineThenArc (radius 0.05 m): moved by about width^2 / (8 R) = 0.25 mm.
  const double width = 0.01;
  const Polyline route = CleanRoute(LineThenArc());
  const Polyline rounded = RoundedRoute(route, width);
  double moved = 0;
  for (Eigen::Index i = 0; i < rounded.size(); ++i) {
    double d = 0;
    NearestArcLength(route, rounded.points.col(i), &d);
    moved = std::max(moved, d);
  }
  EXPECT_LT(moved, 2 * width * width / (8 * 0.05));
  EXPECT_GT(moved, 0.0);
}

TEST(RelaxRoute, TransportedNormalsOfAPlanarCurveStayNormalToItsPlane) {
  const Polyline route = CleanRoute(LineThenArc());
  const Eigen::Matrix3Xd n = TransportedNormals(route, Vec3(0.3, 1, 0));  // projected: +y
  for (Eigen::Index i = 0; i < n.cols(); ++i) {
    EXPECT_LT((n.col(i) - Vec3::UnitY()).norm(), 1e-9) << i;
  }
  // Started in the plane, the normal turns with the curve (no twist either way).
  const Eigen::Matrix3Xd m = TransportedNormals(route, Vec3::UnitZ());
  EXPECT_LT((m.col(0) - Vec3::UnitZ()).norm(), 1e-9);
  EXPECT_LT((m.col(m.cols() - 1) - Vec3(-1, 0, 0)).norm(), 1e-4);
}

TEST(RelaxRoute, NearestArcLengthProjectsOntoTheRoute) {
  const Polyline route = CleanRoute(LineThenArc());
  double d = 0;
  EXPECT_NEAR(NearestArcLength(route, Vec3(-0.06, 0.01, 0), &d), 0.04, 1e-12);
  EXPECT_NEAR(d, 0.01, 1e-12);
}

// A torus (ring clip) as a triangle mesh: centre c, axis along x, radii R and r.
TriangleMesh Ring(const Vec3& c, double big, double small) {
  TriangleMesh m;
  const int nu = 24, nv = 12;
  m.vertices.resize(3, nu * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      const double rho = big + small * std::cos(v);
      m.vertices.col(i * nv + j) =
          c + Vec3(small * std::sin(v), rho * std::cos(u), rho * std::sin(u));
    }
  m.faces.resize(3, 0);
  return m;
}

Polyline Straight(const Vec3& a, const Vec3& b, int n) {
  Polyline p;
  p.points.resize(3, n);
  for (int i = 0; i < n; ++i) p.points.col(i) = a + (b - a) * i / (n - 1.0);
  return CleanRoute(p);
}

TEST(RelaxClips, ARouteThreadingARingIsClippedAtItsCentre) {
  const Vec3 c(0.2, 0.01, 0.0);
  const std::vector<OrientedBox> boxes = {BoundingBoxOf(Ring(c, 0.008, 0.002))};
  const std::vector<std::string> names = {"ring"};
  const Polyline through = Straight(Vec3(0, 0.01, 0), Vec3(0.4, 0.01, 0), 201);
  const auto spans = FindClipSpans(through, boxes, names, 1e-7);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].solid_name, "ring");
  EXPECT_NEAR(0.5 * (spans[0].s_in + spans[0].s_out), 0.2, 1e-6);
  EXPECT_NEAR(spans[0].s_out - spans[0].s_in, 0.004, 1e-6);  // the ring's thickness along x
  // Passing beside it, or ending inside it (a housing, held by the end support): no clip.
  EXPECT_TRUE(FindClipSpans(Straight(Vec3(0, 0.05, 0), Vec3(0.4, 0.05, 0), 201), boxes, names, 1e-7)
                  .empty());
  EXPECT_TRUE(FindClipSpans(Straight(Vec3(0, 0.01, 0), Vec3(0.2, 0.01, 0), 101), boxes, names, 1e-7)
                  .empty());
}

TEST(RelaxClips, BoundingBoxOfATiltedBoxIsTheBoxItself) {
  TriangleMesh m;
  m.vertices.resize(3, 8);
  const Mat3 rot = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1) ? 0.05 : -0.05, (k & 2) ? 0.01 : -0.01, (k & 4) ? 0.02 : -0.02);
    m.vertices.col(k) = rot * corner + Vec3(1, 2, 3);
  }
  const OrientedBox box = BoundingBoxOf(m);
  EXPECT_NEAR(box.Volume(), 0.1 * 0.02 * 0.04, 1e-12);
  EXPECT_TRUE(box.Contains(Vec3(1, 2, 3) + rot * Vec3(0.049, 0.009, -0.019)));
  EXPECT_FALSE(box.Contains(Vec3(1, 2, 3) + rot * Vec3(0.0, 0.011, 0.0)));
}

// The indexed projection answers what the scan of every segment answers, on a route sampled
// as finely as KBL curves are, for points near it and far from it.
TEST(RelaxRoute, RouteProjectorIsTheScansNearestPoint) {
  Polyline route;
  route.points.resize(3, 4001);
  for (int i = 0; i <= 4000; ++i) {
    const double t = 1e-3 * i;
    route.points.col(i) = Vec3(t, 0.2 * std::sin(3 * t), 0.05 * std::cos(7 * t));
  }
  route.ParameteriseByChords();
  const RouteProjector projector(route);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p(0.02 * k, 0.3 * std::cos(k), 0.1 * std::sin(0.7 * k));
    double d_scan = 0.0, d_tree = 0.0;
    const double s_scan = NearestArcLength(route, p, &d_scan);
    const double s_tree = projector.NearestArcLength(p, &d_tree);
    EXPECT_EQ(s_tree, s_scan) << k;
    EXPECT_EQ(d_tree, d_scan) << k;
  }
}

}  // namespace
}  // namespace cablefit::addin
