// SweepTubeMesh: rings of vertices around a centreline, carried along by parallel transport
// (rotation-minimising), so the tube does not twist; flat caps closed by a centre vertex.
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/mesh_file.h"

namespace cablefit {

TriangleMesh SweepTubeMesh(const Polyline& centreline, double diameter, int sides) {
  const int n = centreline.size();
  if (n < 2) throw InvalidInput("a tube centreline needs at least 2 points");
  if (!(diameter > 0) || sides < 3) throw InvalidInput("a tube needs diameter > 0 and >= 3 sides");
  const Eigen::Matrix3Xd& p = centreline.points;  // 3 x n [m]
  std::vector<Vec3> tangents(n);
  for (int i = 0; i < n; ++i) {
    const Vec3 t = p.col(std::min(i + 1, n - 1)) - p.col(std::max(i - 1, 0));
    if (t.norm() <= 0) throw InvalidInput("a tube centreline has repeated points");
    tangents[i] = t.normalized();
  }
  Vec3 normal = tangents[0].unitOrthogonal();
  const double r = 0.5 * diameter;
  TriangleMesh mesh;
  mesh.vertices.resize(3, n * sides + 2);
  for (int i = 0; i < n; ++i) {
    if (i > 0) {  // parallel transport of the normal from the previous tangent to this one
      normal = Eigen::Quaterniond::FromTwoVectors(tangents[i - 1], tangents[i]) * normal;
      normal = (normal - normal.dot(tangents[i]) * tangents[i]).normalized();
    }
    const Vec3 binormal = tangents[i].cross(normal);
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * M_PI * k / sides;
      mesh.vertices.col(i * sides + k) = p.col(i) + r * (std::cos(a) * normal + std::sin(a) * binormal);
    }
  }
  const int start_centre = n * sides, end_centre = n * sides + 1;
  mesh.vertices.col(start_centre) = p.col(0);
  mesh.vertices.col(end_centre) = p.col(n - 1);
  mesh.faces.resize(3, 2 * (n - 1) * sides + 2 * sides);
  int f = 0;
  for (int i = 0; i + 1 < n; ++i) {
    for (int k = 0; k < sides; ++k) {
      const int a = i * sides + k, b = i * sides + (k + 1) % sides;
      const int c = a + sides, d = b + sides;
      mesh.faces.col(f++) << a, b, d;  // outward: (normal, binormal, tangent) is right-handed
      mesh.faces.col(f++) << a, d, c;
    }
  }
  for (int k = 0; k < sides; ++k) {
    mesh.faces.col(f++) << start_centre, (k + 1) % sides, k;
    mesh.faces.col(f++) << end_centre, (n - 1) * sides + k, (n - 1) * sides + (k + 1) % sides;
  }
  return mesh;
}

}  // namespace cablefit
