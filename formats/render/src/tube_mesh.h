// Triangle mesh of a tube swept along a polyline, with smooth normals and per-vertex colours.
// Frames along the curve are rotation-minimising (parallel transport), computed with the double
// reflection method: W. Wang, B. Juettler, D. Zheng, Y. Liu, "Computation of rotation minimizing
// frames", ACM Trans. Graph. 27(1), 2008, Algorithm 1. Unlike Frenet frames they do not flip on
// straight or inflecting stretches, so the shading has no seams or twists.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "cablefit/formats/image.h"

namespace cablefit::render {

struct TubeMesh {
  std::vector<float> positions;  // 3 per vertex [m]
  std::vector<float> normals;    // 3 per vertex, unit
  std::vector<float> colours;    // 3 per vertex, linear 0..1 (sRGB bytes / 255)
  std::vector<float> tangents;   // 3 per vertex: the centre line's unit tangent; zero on caps
  std::vector<std::uint32_t> indices;  // 3 per triangle, counter-clockwise from outside
  void Append(const TubeMesh& other);
};

/// Sweeps a circle of `radius` [m] with `sides` facets along `points` (3 x n [m]), colouring
/// vertex ring i with `colours[i]` (size n), and closes both ends with flat caps. Consecutive
/// duplicate points are skipped; fewer than two distinct points give an empty mesh.
TubeMesh BuildTubeMesh(const Eigen::Matrix3Xd& points, double radius, int sides,
                       const std::vector<Rgb>& colours);

/// Indices of `points` (3 x n [m]) a picture needs: the first and last, and between them as few
/// as keep every skipped point within `tolerance` [m] of the chord that replaces it and every
/// chord at most `max_length` [m] long (greedy, in order). A relaxed centre line has a node every
/// fraction of a millimetre; drawn at picture resolution most of them are invisible, and each
/// costs llvmpipe a ring of vertices.
std::vector<Eigen::Index> ThinnedIndices(const Eigen::Matrix3Xd& points, double tolerance,
                                         double max_length);

/// The part of a polyline with arc length in [s_begin, s_end] (ends interpolated).
/// `s` n [m] non-decreasing, `points` 3 x n [m]; returns 3 x k [m].
Eigen::Matrix3Xd SliceByArcLength(const Eigen::VectorXd& s, const Eigen::Matrix3Xd& points,
                                  double s_begin, double s_end);

}  // namespace cablefit::render
