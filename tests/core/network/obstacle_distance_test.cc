// The obstacle tree returns exactly what testing every triangle returns, on a closed tessellated
// solid (with shared edges and vertices, where ties decide the side) and on a triangle soup.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "obstacle_distance.h"

namespace cablefit {
namespace {

// A UV sphere: closed, outward faces, many shared edges and poles where faces meet at a vertex.
TriangleMesh Sphere(const Vec3& centre, double radius, int rings, int segments) {
  TriangleMesh m;
  const int nv = (rings + 1) * segments;
  m.vertices.resize(3, nv);
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments;
      m.vertices.col(i * segments + j) =
          centre + radius * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    }
  std::vector<Eigen::Vector3i> f;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const int a = i * segments + j, b = i * segments + (j + 1) % segments;
      const int c = a + segments, d = b + segments;
      f.emplace_back(a, c, b);
      f.emplace_back(b, c, d);
    }
  m.faces.resize(3, static_cast<int>(f.size()));
  for (size_t k = 0; k < f.size(); ++k) m.faces.col(static_cast<int>(k)) = f[k];
  return m;
}

TriangleMesh Soup(int n, std::mt19937* rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TriangleMesh m;
  m.vertices.resize(3, 3 * n);
  m.faces.resize(3, n);
  for (int k = 0; k < n; ++k) {
    const Vec3 c(u(*rng), u(*rng), u(*rng));
    for (int v = 0; v < 3; ++v) m.vertices.col(3 * k + v) = c + 0.1 * Vec3(u(*rng), u(*rng), u(*rng));
    m.faces.col(k) = Eigen::Vector3i(3 * k, 3 * k + 1, 3 * k + 2);
  }
  return m;
}

void ExpectSameAsScan(const ObstacleField& field, std::mt19937* rng, int queries) {
  std::uniform_real_distribution<double> u(-1.3, 1.3), range(0.01, 1.0);
  int found = 0;
  for (int q = 0; q < queries; ++q) {
    const Vec3 p(u(*rng), u(*rng), u(*rng));
    const double r = range(*rng);
    const ObstacleHit tree = field.Nearest(p, r);
    const ObstacleHit scan = field.NearestByScan(p, r);
    ASSERT_EQ(tree.obstacle, scan.obstacle) << "query " << q;
    if (scan.obstacle < 0) continue;
    ++found;
    EXPECT_NEAR(tree.distance, scan.distance, 1e-14) << "query " << q;
    EXPECT_LT((tree.point - scan.point).norm(), 1e-12) << "query " << q;
    EXPECT_LT((tree.normal - scan.normal).norm(), 1e-9) << "query " << q;
  }
  EXPECT_GT(found, queries / 10);  // the queries must reach the surface often enough to mean something
}

TEST(ObstacleField, TreeMatchesScanOnAClosedSolid) {
  std::mt19937 rng(7);
  ObstacleField field({{"ball", Sphere(Vec3(0.1, -0.2, 0.05), 0.8, 24, 48)},
                       {"small", Sphere(Vec3(0.9, 0.9, 0.9), 0.2, 6, 8)}});
  EXPECT_GT(field.num_triangles(), 2000);
  ExpectSameAsScan(field, &rng, 3000);
}

TEST(ObstacleField, TreeMatchesScanOnATriangleSoup) {
  std::mt19937 rng(11);
  ObstacleField field({{"soup", Soup(5000, &rng)}});
  ExpectSameAsScan(field, &rng, 2000);
}

TEST(ObstacleField, InsideAClosedSolidIsNegative) {
  ObstacleField field({{"ball", Sphere(Vec3::Zero(), 1.0, 32, 64)}});
  const ObstacleHit in = field.Nearest(Vec3(0.3, 0.1, -0.2), 2.0);
  ASSERT_EQ(in.obstacle, 0);
  EXPECT_LT(in.distance, 0.0);
  const ObstacleHit out = field.Nearest(Vec3(1.2, 0.0, 0.0), 0.5);
  ASSERT_EQ(out.obstacle, 0);
  EXPECT_NEAR(out.distance, 0.2, 0.01);
  EXPECT_GT(out.normal.x(), 0.99);
  EXPECT_EQ(field.Nearest(Vec3(3, 0, 0), 0.5).obstacle, -1);  // out of range
  EXPECT_EQ(ObstacleField({}).Nearest(Vec3::Zero(), 1.0).obstacle, -1);
}

// Degenerate and non-finite faces are left out instead of poisoning the tree's ordering.
TEST(ObstacleField, DegenerateAndNonFiniteFacesAreSkipped) {
  TriangleMesh m = Sphere(Vec3::Zero(), 1.0, 8, 16);
  const int faces = static_cast<int>(m.faces.cols());
  m.vertices.conservativeResize(3, m.vertices.cols() + 3);
  const int v = static_cast<int>(m.vertices.cols()) - 3;
  m.vertices.col(v) = Vec3(std::nan(""), 0, 0);
  m.vertices.col(v + 1) = Vec3(5, 5, 5);
  m.vertices.col(v + 2) = Vec3(5, 5, 5);
  m.faces.conservativeResize(3, faces + 2);
  m.faces.col(faces) = Eigen::Vector3i(v, v + 1, 0);      // NaN vertex
  m.faces.col(faces + 1) = Eigen::Vector3i(v + 1, v + 2, 1);  // zero area
  ObstacleField field({{"ball", m}});
  EXPECT_LT(field.num_triangles(), faces + 1);
  const ObstacleHit out = field.Nearest(Vec3(1.2, 0.0, 0.0), 0.5);
  ASSERT_EQ(out.obstacle, 0);
  EXPECT_GT(out.distance, 0.19);
  EXPECT_LT(out.distance, 0.21);
}

}  // namespace
}  // namespace cablefit
