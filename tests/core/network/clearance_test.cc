// Clearance of a tube to a solid and to another tube against closed forms: a sagging arc above
// a plane (lowest point height minus radius), a cable passing a box corner (point-to-box
// distance), two skew straight cables (distance of skew lines minus both radii).
#include "cablefit/core/network/clearance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace cablefit {
namespace {

Polyline FromPoints(const Eigen::Matrix3Xd& points) {
  Polyline p;
  p.points = points;
  p.ParameteriseByChords();
  return p;
}

// The plane z = 0 as two triangles facing +z, 2 m square.
TriangleMesh Plane() {
  TriangleMesh m;
  m.vertices.resize(3, 4);
  m.vertices << -1, 1, 1, -1, -1, -1, 1, 1, 0, 0, 0, 0;
  m.faces.resize(3, 2);
  m.faces << 0, 0, 1, 2, 2, 3;
  return m;
}

// The closed box [lo, hi], outward faces.
TriangleMesh Box(const Vec3& lo, const Vec3& hi) {
  TriangleMesh m;
  m.vertices.resize(3, 8);
  for (int k = 0; k < 8; ++k)
    m.vertices.col(k) =
        Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  // Two triangles per face, counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  m.faces.resize(3, 12);
  for (int f = 0; f < 6; ++f) {
    m.faces.col(2 * f) << quads[f][0], quads[f][1], quads[f][2];
    m.faces.col(2 * f + 1) << quads[f][0], quads[f][2], quads[f][3];
  }
  return m;
}

TEST(ClearanceTest, SaggingArcAbovePlaneIsLowestHeightMinusRadius) {
  // A circular arc of radius R whose lowest point is at height h: clearance = h - r.
  const double R = 0.5, h = 0.037, r = 0.004;
  const int n = 201;
  Eigen::Matrix3Xd pts(3, n);
  for (int i = 0; i < n; ++i) {
    const double x = -0.3 + 0.6 * i / (n - 1) + 0.0013;
    pts.col(i) = Vec3(x, 0.2, h + R - std::sqrt(R * R - x * x));
  }
  const Polyline c = FromPoints(pts);
  const SolidClearance plane(Plane());
  const ClearanceHit hit = plane.ToTube(c, r);
  ASSERT_TRUE(hit.found());
  // The sample nearest x = 0 is the lowest: its height in closed form.
  double lowest = 1e9;
  for (int i = 0; i < n; ++i) lowest = std::min(lowest, pts(2, i));
  EXPECT_NEAR(hit.clearance, lowest - r, 1e-12);
  EXPECT_NEAR(hit.clearance, h - r, 2e-6);  // the arc's own lowest point, within the sampling
  EXPECT_NEAR(hit.other.z(), 0.0, 1e-12);
  EXPECT_NEAR(hit.other.x(), hit.point.x(), 1e-12);
}

TEST(ClearanceTest, CablePastABoxIsPointToBoxDistanceAndNegativeInside) {
  const Vec3 lo(0, 0, 0), hi(0.1, 0.2, 0.05);
  const SolidClearance box(Box(lo, hi));
  const Eigen::AlignedBox3d ref(lo, hi);
  const double r = 0.003;
  // A straight cable passing the corner (hi.x, hi.y, *) diagonally, 0.02 m away at closest.
  const int n = 101;
  Eigen::Matrix3Xd pts(3, n);
  for (int i = 0; i < n; ++i) {
    const double t = -0.2 + 0.4 * i / (n - 1);
    pts.col(i) = Vec3(0.1 + 0.02 / std::sqrt(2.0) + t, 0.2 + 0.02 / std::sqrt(2.0) - t, 0.025);
  }
  const Polyline c = FromPoints(pts);
  const ClearanceHit hit = box.ToTube(c, r);
  double expected = 1e9;
  for (int i = 0; i < n; ++i) expected = std::min(expected, ref.exteriorDistance(Vec3(pts.col(i))));
  EXPECT_NEAR(hit.clearance, expected - r, 1e-12);
  EXPECT_NEAR(hit.clearance, 0.02 - r, 1e-12);  // the sample at t = 0 is the closest point
  // Through the box: the deepest sample is inside, the clearance negative (depth + radius).
  Eigen::Matrix3Xd through(3, 3);
  through << -0.1, 0.05, 0.2, 0.1, 0.1, 0.1, 0.02, 0.02, 0.02;
  const ClearanceHit inside = box.ToTube(FromPoints(through), r);
  EXPECT_NEAR(inside.clearance, -0.02 - r, 1e-12);  // 0.02 below the top face, the nearest
}

TEST(ClearanceTest, SkewCablesAreLineDistanceMinusRadii) {
  // a along x at z = 0; b along (0, 1, 1) through (0.3, 0, 0.1): skew lines 0.1 / sqrt(2) apart.
  Eigen::Matrix3Xd pa(3, 7), pb(3, 5);
  for (int i = 0; i < 7; ++i) pa.col(i) = Vec3(-0.11 + 0.1 * i, 0, 0);
  for (int i = 0; i < 5; ++i) pb.col(i) = Vec3(0.3, -0.23 + 0.1 * i, 0.1 - 0.23 + 0.1 * i);
  const Polyline a = FromPoints(pa), b = FromPoints(pb);
  const Vec3 d1(1, 0, 0), d2 = Vec3(0, 1, 1).normalized();
  const double line_distance =
      std::abs((Vec3(0.3, 0, 0.1)).dot(d1.cross(d2))) / d1.cross(d2).norm();
  const double ra = 0.004, rb = 0.006;
  const ClearanceHit hit = TubeToTubeClearance(a, ra, {}, b, rb, {});
  EXPECT_NEAR(hit.clearance, line_distance - ra - rb, 1e-12);
  EXPECT_NEAR(hit.point.x(), 0.3, 1e-12);
  EXPECT_NEAR(hit.s, 0.41, 1e-12);
  // Leaving out a's end beyond the crossing moves the closest point to the kept end.
  const ClearanceHit skipped = TubeToTubeClearance(a, ra, {0.0, 0.25}, b, rb, {});
  EXPECT_GT(skipped.clearance, hit.clearance + 1e-3);
  EXPECT_LE(skipped.s, 0.6 - 0.25 + 1e-12);
}

// Many random wavy tubes: each tube's nearest other tube and that clearance are what measuring
// every pair gives, with and without the ends left out at shared ends; the tubes within reach
// include every pair closer than the reach.
TEST(ClearanceTest, TubeIndexFindsWhatEveryPairGives) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Polyline> lines;
  std::vector<TubeClearanceIndex::Tube> tubes;
  for (int t = 0; t < 40; ++t) {
    const Vec3 start(u(rng), u(rng), 0.3 * u(rng));
    const Vec3 dir = Vec3(u(rng) - 0.5, u(rng) - 0.5, 0.2 * (u(rng) - 0.5)).normalized();
    Eigen::Matrix3Xd p(3, 60);
    for (int i = 0; i < 60; ++i)
      p.col(i) = start + 0.005 * i * dir + Vec3(0, 0, 0.01 * std::sin(0.3 * i + t));
    lines.push_back(FromPoints(p));
  }
  // Tube 1 starts where tube 0 ends: a junction whose ends are left out.
  lines[1].points.colwise() += Vec3(lines[0].points.rightCols<1>() - lines[1].points.col(0));
  for (size_t t = 0; t < lines.size(); ++t) tubes.push_back({&lines[t], 0.002 + 0.0001 * t});
  const TubeClearanceIndex index(tubes);
  auto skip = [&](int a, int b) {
    TubeSkip s;
    if (a + b == 1) (a == 0 ? s.end : s.start) = 0.02;
    return s;
  };
  for (int i = 0; i < static_cast<int>(tubes.size()); ++i) {
    int best_j = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < static_cast<int>(tubes.size()); ++j) {
      if (j == i) continue;
      const ClearanceHit h = TubeToTubeClearance(lines[i], tubes[i].radius, skip(i, j), lines[j],
                                                 tubes[j].radius, skip(j, i));
      if (h.clearance < best) {
        best = h.clearance;
        best_j = j;
      }
    }
    double found = 0.0;
    EXPECT_EQ(index.Nearest(i, skip, &found), best_j) << i;
    EXPECT_NEAR(found, best, 1e-12) << i;
    const double reach = 0.05;
    const std::vector<int> near = index.Within(i, reach);
    for (int j = 0; j < static_cast<int>(tubes.size()); ++j) {
      if (j == i) continue;
      const ClearanceHit h = TubeToTubeClearance(lines[i], tubes[i].radius, {}, lines[j],
                                                 tubes[j].radius, {});
      if (h.clearance <= reach) {
        EXPECT_TRUE(std::count(near.begin(), near.end(), j)) << i << " " << j;
      }
    }
    EXPECT_LT(near.size(), tubes.size() - 1) << "far tubes are not within reach";
  }
}

}  // namespace
}  // namespace cablefit
