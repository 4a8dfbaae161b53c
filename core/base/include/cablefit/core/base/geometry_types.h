// Neutral geometric data types shared by every layer. Only Eigen: no OCCT, assimp, CGAL or GL
// type ever appears in a public header (adapters in formats/ convert at the boundary).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace cablefit {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// An ordered curve sampled at arc lengths.
struct Polyline {
  Eigen::VectorXd s;       // n [m], non-decreasing arc length (may be empty if unknown)
  Eigen::Matrix3Xd points;  // 3 x n [m]

  int size() const { return static_cast<int>(points.cols()); }
  /// Sum of chord lengths [m].
  double ChordLength() const;
  /// Fills `s` with cumulative chord length starting at `s0`.
  void ParameteriseByChords(double s0 = 0.0);
};

/// Unordered points, e.g. a laser scan of a cable's outer surface.
struct PointCloud {
  Eigen::Matrix3Xd points;  // 3 x n [m]
  int size() const { return static_cast<int>(points.cols()); }
};

/// Indexed triangle mesh.
struct TriangleMesh {
  Eigen::Matrix3Xd vertices;  // 3 x nv [m]
  Eigen::Matrix3Xi faces;     // 3 x nf, vertex indices, counter-clockwise seen from outside
};

/// The closed axis-aligned box [lo, hi] [m] as a solid's surface: 8 vertices, 12 triangles
/// facing outward (a support plate, a bench table).
TriangleMesh BoxMesh(const Vec3& lo, const Vec3& hi);

/// An orthonormal material frame: d3 is the tangent, d1 the material normal, d2 = d3 x d1.
struct Frame {
  Vec3 d1 = Vec3::UnitX();
  Vec3 d2 = Vec3::UnitY();
  Vec3 d3 = Vec3::UnitZ();

  /// Builds a frame from a tangent and a normal that need be neither unit nor exactly
  /// perpendicular (the normal is projected). Throws InvalidInput when they are (anti)parallel
  /// or not finite.
  static Frame FromTangentNormal(const Vec3& tangent, const Vec3& normal);
  /// Columns d1 d2 d3: maps material coordinates to world.
  Mat3 Matrix() const;
};

}  // namespace cablefit
