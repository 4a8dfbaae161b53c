#include "cablefit/core/base/geometry_types.h"

#include <cmath>

#include "cablefit/core/base/errors.h"

namespace cablefit {

double Polyline::ChordLength() const {
  double len = 0.0;
  for (int i = 1; i < size(); ++i) len += (points.col(i) - points.col(i - 1)).norm();
  return len;
}

void Polyline::ParameteriseByChords(double s0) {
  s.resize(size());
  if (size() == 0) return;
  s[0] = s0;
  for (int i = 1; i < size(); ++i) s[i] = s[i - 1] + (points.col(i) - points.col(i - 1)).norm();
}

Frame Frame::FromTangentNormal(const Vec3& tangent, const Vec3& normal) {
  if (!tangent.allFinite() || !normal.allFinite())
    throw InvalidInput("tangent or normal is not finite");
  const double tn = tangent.norm();
  if (tn < 1e-12) throw InvalidInput("tangent has zero length");
  Frame f;
  f.d3 = tangent / tn;
  Vec3 n = normal - normal.dot(f.d3) * f.d3;
  // The normal only fixes the twist; if it is (nearly) parallel to the tangent it fixes nothing.
  if (n.norm() < 1e-6 * std::max(1.0, normal.norm()))
    throw InvalidInput("normal is parallel to the tangent");
  f.d1 = n.normalized();
  f.d2 = f.d3.cross(f.d1);
  return f;
}

Mat3 Frame::Matrix() const {
  Mat3 m;
  m.col(0) = d1;
  m.col(1) = d2;
  m.col(2) = d3;
  return m;
}

TriangleMesh BoxMesh(const Vec3& lo, const Vec3& hi) {
  TriangleMesh m;
  m.vertices.resize(3, 8);
  for (int k = 0; k < 8; ++k)
    m.vertices.col(k) = Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  // Vertex k has bit 0 for x, 1 for y, 2 for z: each quad lists its corners counter-clockwise
  // seen from outside (-z, +z, -y, +y, -x, +x).
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  m.faces.resize(3, 12);
  for (int f = 0; f < 6; ++f) {
    m.faces.col(2 * f) << quads[f][0], quads[f][1], quads[f][2];
    m.faces.col(2 * f + 1) << quads[f][0], quads[f][2], quads[f][3];
  }
  return m;
}

}  // namespace cablefit
