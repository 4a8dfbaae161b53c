#include "tube_mesh.h"

#include <algorithm>

#include <cmath>
#include <numbers>

namespace cablefit::render {
namespace {

using Eigen::Vector3d;

Vector3d AnyPerpendicular(const Vector3d& t) {
  const Vector3d helper = std::abs(t.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  return t.cross(helper).normalized();
}

void PushVertex(TubeMesh& mesh, const Vector3d& p, const Vector3d& n, const Vector3d& t, Rgb colour) {
  for (int k = 0; k < 3; ++k) {
    mesh.tangents.push_back(static_cast<float>(t[k]));
    mesh.positions.push_back(static_cast<float>(p[k]));
    mesh.normals.push_back(static_cast<float>(n[k]));
  }
  mesh.colours.push_back(colour.r / 255.0f);
  mesh.colours.push_back(colour.g / 255.0f);
  mesh.colours.push_back(colour.b / 255.0f);
}

}  // namespace

void TubeMesh::Append(const TubeMesh& other) {
  const auto offset = static_cast<std::uint32_t>(positions.size() / 3);
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  colours.insert(colours.end(), other.colours.begin(), other.colours.end());
  tangents.insert(tangents.end(), other.tangents.begin(), other.tangents.end());
  for (std::uint32_t i : other.indices) indices.push_back(i + offset);
}

TubeMesh BuildTubeMesh(const Eigen::Matrix3Xd& points, double radius, int sides,
                       const std::vector<Rgb>& colours) {
  TubeMesh mesh;
  // Distinct consecutive points only: a zero-length segment has no tangent.
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    if (!points.col(i).allFinite()) continue;
    if (keep.empty() || (points.col(i) - points.col(keep.back())).norm() > radius * 1e-6)
      keep.push_back(i);
  }
  const auto n = static_cast<Eigen::Index>(keep.size());
  if (n < 2 || sides < 3) return mesh;
  auto point = [&](Eigen::Index k) { return Vector3d(points.col(keep[static_cast<std::size_t>(k)])); };
  auto colour = [&](Eigen::Index k) {
    const auto i = static_cast<std::size_t>(keep[static_cast<std::size_t>(k)]);
    return i < colours.size() ? colours[i] : Rgb{150, 150, 150};
  };
  // Vertex tangents: average of adjacent segment directions (smooth shading across joints).
  std::vector<Vector3d> tangents(static_cast<std::size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k) {
    const Vector3d in = k > 0 ? (point(k) - point(k - 1)).normalized() : Vector3d::Zero();
    const Vector3d out = k + 1 < n ? (point(k + 1) - point(k)).normalized() : Vector3d::Zero();
    Vector3d t = in + out;
    if (t.norm() < 1e-9) t = out.norm() > 0 ? out : in;  // a hairpin: keep one side
    tangents[static_cast<std::size_t>(k)] = t.normalized();
  }
  Vector3d normal = AnyPerpendicular(tangents[0]);
  const double step = 2.0 * std::numbers::pi / sides;
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    if (k > 0) {
      // Double reflection (Wang et al. 2008, Alg. 1): reflect across the bisector plane of the
      // segment, then across the plane that maps the reflected tangent onto the new one.
      const Vector3d v1 = point(k) - point(k - 1);
      const double c1 = v1.squaredNorm();
      const Vector3d r_l = normal - (2.0 / c1) * v1.dot(normal) * v1;
      const Vector3d t_l = tangents[ku - 1] - (2.0 / c1) * v1.dot(tangents[ku - 1]) * v1;
      const Vector3d v2 = tangents[ku] - t_l;
      const double c2 = v2.squaredNorm();
      normal = c2 > 1e-20 ? Vector3d(r_l - (2.0 / c2) * v2.dot(r_l) * v2) : r_l;
      normal = (normal - normal.dot(tangents[ku]) * tangents[ku]).normalized();
    }
    const Vector3d binormal = tangents[ku].cross(normal);
    for (int j = 0; j < sides; ++j) {
      const Vector3d dir = std::cos(j * step) * normal + std::sin(j * step) * binormal;
      PushVertex(mesh, point(k) + radius * dir, dir, tangents[ku], colour(k));
    }
  }
  const auto ring = static_cast<std::uint32_t>(sides);
  for (std::uint32_t k = 0; k + 1 < static_cast<std::uint32_t>(n); ++k)
    for (std::uint32_t j = 0; j < ring; ++j) {
      const std::uint32_t a = k * ring + j, b = k * ring + (j + 1) % ring;
      const std::uint32_t c = a + ring, d = b + ring;
      // dir(j) x dir(j+1) points along +t, so (a, b, d) is counter-clockwise from outside.
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
    }
  // Flat end caps: the cable is solid, an open end would show the inside.
  for (int end = 0; end < 2; ++end) {
    const Eigen::Index k = end == 0 ? 0 : n - 1;
    const Vector3d t = tangents[static_cast<std::size_t>(k)] * (end == 0 ? -1.0 : 1.0);
    const auto first = static_cast<std::uint32_t>(mesh.positions.size() / 3);
    PushVertex(mesh, point(k), t, Vector3d::Zero(), colour(k));
    for (std::uint32_t j = 0; j < ring; ++j) {
      const std::uint32_t src = static_cast<std::uint32_t>(k) * ring + j;
      const Vector3d p(mesh.positions[3 * src], mesh.positions[3 * src + 1], mesh.positions[3 * src + 2]);
      PushVertex(mesh, p, t, Vector3d::Zero(), colour(k));
    }
    for (std::uint32_t j = 0; j < ring; ++j) {
      const std::uint32_t a = first + 1 + j, b = first + 1 + (j + 1) % ring;
      if (end == 0)
        mesh.indices.insert(mesh.indices.end(), {first, b, a});
      else
        mesh.indices.insert(mesh.indices.end(), {first, a, b});
    }
  }
  return mesh;
}

Eigen::Matrix3Xd SliceByArcLength(const Eigen::VectorXd& s, const Eigen::Matrix3Xd& points,
                                  double s_begin, double s_end) {
  std::vector<Vector3d> out;
  const Eigen::Index n = std::min<Eigen::Index>(s.size(), points.cols());
  auto at = [&](double target) {
    for (Eigen::Index i = 1; i < n; ++i)
      if (s[i] >= target) {
        const double len = s[i] - s[i - 1];
        const double f = len > 0 ? (target - s[i - 1]) / len : 0.0;
        return Vector3d(points.col(i - 1) + f * (points.col(i) - points.col(i - 1)));
      }
    return Vector3d(points.col(n - 1));
  };
  if (n >= 2 && s_end > s_begin && s_end >= s[0] && s_begin <= s[n - 1]) {
    out.push_back(at(std::max(s_begin, s[0])));
    for (Eigen::Index i = 0; i < n; ++i)
      if (s[i] > s_begin && s[i] < s_end) out.push_back(points.col(i));
    out.push_back(at(std::min(s_end, s[n - 1])));
  }
  Eigen::Matrix3Xd result(3, static_cast<Eigen::Index>(out.size()));
  for (std::size_t i = 0; i < out.size(); ++i) result.col(static_cast<Eigen::Index>(i)) = out[i];
  return result;
}

std::vector<Eigen::Index> ThinnedIndices(const Eigen::Matrix3Xd& points, double tolerance,
                                         double max_length) {
  const Eigen::Index n = points.cols();
  std::vector<Eigen::Index> keep;
  if (n == 0) return keep;
  keep.push_back(0);
  Eigen::Index last = 0;
  // Does the chord from `last` to j stay within tolerance of every point between?
  auto chord_fits = [&](Eigen::Index j) {
    const Eigen::Vector3d a = points.col(last), ab = points.col(j) - a;
    const double len2 = ab.squaredNorm();
    if (len2 > max_length * max_length) return false;
    for (Eigen::Index k = last + 1; k < j; ++k) {
      const Eigen::Vector3d ak = points.col(k) - a;
      const double w = len2 > 0 ? std::clamp(ak.dot(ab) / len2, 0.0, 1.0) : 0.0;
      if ((ak - w * ab).squaredNorm() > tolerance * tolerance) return false;
    }
    return true;
  };
  for (Eigen::Index j = 2; j < n; ++j) {
    if (chord_fits(j)) continue;
    last = j - 1;
    keep.push_back(last);
  }
  if (n > 1) keep.push_back(n - 1);
  return keep;
}

}  // namespace cablefit::render
