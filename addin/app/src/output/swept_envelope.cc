#include "cablefit/app/output/swept_envelope.h"

#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/solver/centerline_sampling.h"

namespace cablefit::addin {

void AppendMesh(const TriangleMesh& b, TriangleMesh* a) {
  const Eigen::Index nv = a->vertices.cols(), nf = a->faces.cols();
  a->vertices.conservativeResize(3, nv + b.vertices.cols());
  a->vertices.rightCols(b.vertices.cols()) = b.vertices;
  a->faces.conservativeResize(3, nf + b.faces.cols());
  a->faces.rightCols(b.faces.cols()) = b.faces.array() + static_cast<int>(nv);
}

TriangleMesh TubeSurface(const Eigen::Matrix3Xd& input, double radius, int sides) {
  CABLEFIT_REQUIRE(sides >= 3 && radius > 0, "TubeSurface needs 3+ sides and a positive radius");
  // Distinct points only: a repeated point has no tangent.
  std::vector<Vec3> p;
  for (Eigen::Index i = 0; i < input.cols(); ++i)
    if (p.empty() || (input.col(i) - p.back()).norm() > 1e-12) p.push_back(input.col(i));
  const int n = static_cast<int>(p.size());
  TriangleMesh m;
  if (n < 2) return m;
  std::vector<Vec3> t(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Vec3 a = p[static_cast<size_t>(std::max(i - 1, 0))];
    const Vec3 b = p[static_cast<size_t>(std::min(i + 1, n - 1))];
    t[static_cast<size_t>(i)] = (b - a).normalized();
  }
  // Parallel transport of a normal: project the last one onto the next normal plane.
  Vec3 normal = t[0].unitOrthogonal();
  // Circumscribed polygon: its facets touch the circle of `radius` from outside.
  const double r = radius / std::cos(M_PI / sides);
  m.vertices.resize(3, static_cast<Eigen::Index>(n) * sides + 2);
  for (int i = 0; i < n; ++i) {
    const Vec3& ti = t[static_cast<size_t>(i)];
    Vec3 projected = normal - normal.dot(ti) * ti;
    normal = projected.norm() > 1e-9 ? Vec3(projected.normalized()) : Vec3(ti.unitOrthogonal());
    const Vec3 binormal = ti.cross(normal);
    for (int j = 0; j < sides; ++j) {
      const double a = 2 * M_PI * (j + 0.5) / sides;
      m.vertices.col(i * sides + j) =
          p[static_cast<size_t>(i)] + r * (std::cos(a) * normal + std::sin(a) * binormal);
    }
  }
  const int c0 = n * sides, c1 = n * sides + 1;
  m.vertices.col(c0) = p.front();
  m.vertices.col(c1) = p.back();
  m.faces.resize(3, static_cast<Eigen::Index>(2 * (n - 1) * sides + 2 * sides));
  Eigen::Index f = 0;
  auto v = [sides](int i, int j) { return i * sides + (j % sides); };
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j < sides; ++j) {
      // Angle grows counter-clockwise about the tangent: (ring j -> j+1) x tangent is outward.
      m.faces.col(f++) << v(i, j), v(i, j + 1), v(i + 1, j + 1);
      m.faces.col(f++) << v(i, j), v(i + 1, j + 1), v(i + 1, j);
    }
  for (int j = 0; j < sides; ++j) {
    m.faces.col(f++) << c0, v(0, j + 1), v(0, j);          // faces -t at the start
    m.faces.col(f++) << c1, v(n - 1, j), v(n - 1, j + 1);  // faces +t at the end
  }
  return m;
}

TriangleMesh SweptEnvelope(const std::vector<Polyline>& shapes, double radius,
                           const EnvelopeOptions& options, std::vector<size_t>* used) {
  CABLEFIT_REQUIRE(options.max_shapes >= 2 && options.min_rings >= 2 &&
                       options.max_rings >= options.min_rings,
                   "invalid EnvelopeOptions");
  // Which shapes: all, or evenly spaced ones when there are too many.
  std::vector<size_t> pick;
  const size_t n = shapes.size();
  const size_t cap = static_cast<size_t>(options.max_shapes);
  if (n <= cap) {
    for (size_t i = 0; i < n; ++i) pick.push_back(i);
  } else {
    for (size_t k = 0; k < cap; ++k) pick.push_back(k * (n - 1) / (cap - 1));
  }
  TriangleMesh out;
  std::vector<Polyline> taken;
  if (used) used->clear();
  for (size_t i : pick) {
    const Polyline& shape = shapes[i];
    if (shape.size() < 2) continue;
    const double length = shape.s[shape.size() - 1] - shape.s[0];
    const int rings = std::clamp(static_cast<int>(std::ceil(length / (2 * radius))) + 1,
                                 options.min_rings, options.max_rings);
    const Eigen::VectorXd at = UniformArcLengths(length, rings).array() + shape.s[0];
    Polyline sampled = SampleCenterline(shape, at);
    bool repeat = false;
    for (const Polyline& earlier : taken)
      if (earlier.size() == sampled.size() &&
          (earlier.points - sampled.points).colwise().norm().maxCoeff() <=
              options.repeat_tolerance)
        repeat = true;
    if (repeat) continue;
    AppendMesh(TubeSurface(sampled.points, radius, options.sides), &out);
    taken.push_back(std::move(sampled));
    if (used) used->push_back(i);
  }
  return out;
}

double WindingNumber(const TriangleMesh& mesh, const Vec3& p) {
  double total = 0.0;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) {
    const Vec3 a = mesh.vertices.col(mesh.faces(0, f)) - p;
    const Vec3 b = mesh.vertices.col(mesh.faces(1, f)) - p;
    const Vec3 c = mesh.vertices.col(mesh.faces(2, f)) - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double det = a.dot(b.cross(c));
    const double div = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2 * std::atan2(det, div);
  }
  return total / (4 * M_PI);
}

}  // namespace cablefit::addin
