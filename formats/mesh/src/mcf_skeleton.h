// Curve skeleton of a closed triangle mesh (the only place CGAL is compiled: it is slow).
#pragma once

#include <utility>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

struct CurveSkeleton {
  Eigen::Matrix3Xd nodes;                  // 3 x n [m]
  std::vector<std::pair<int, int>> edges;  // node index pairs
  // per node: the (remeshed) surface points that collapsed onto it [m]
  std::vector<std::vector<Eigen::Vector3d>> vertex_points;
};

/// Mean-curvature-flow skeleton (A. Tagliasacchi, I. Alhashim, M. Olson, H. Zhang, "Mean
/// Curvature Skeletons", Computer Graphics Forum 31(5), 2012; CGAL's implementation).
/// `mesh` must be one closed, manifold component (it is remeshed isotropically first). Throws
/// InvalidInput otherwise.
CurveSkeleton ComputeMcfSkeleton(const TriangleMesh& mesh);

/// ComputeMcfSkeleton run in the helper process (skeleton_in_child.cc), so that the result does
/// not depend on what this process did before. Throws InvalidInput as ComputeMcfSkeleton does,
/// and when the helper crashes or runs longer than `max_seconds`. Computes in this process when
/// no helper can be started.
CurveSkeleton ComputeMcfSkeletonInHelper(const TriangleMesh& mesh, double max_seconds);

/// [s] How long the skeleton of `mesh` may take: 60 s plus 1 ms per input triangle. The flow
/// itself runs on ~15 000 remeshed triangles whatever the input (~0.5 s), the remeshing grows
/// with the input; a healthy 6 000-triangle tube takes ~0.8 s in all, so this leaves a margin of
/// 50x and more, and a mesh that sends CGAL into a loop fails in about a minute, not ten.
double SkeletonSecondsFor(const TriangleMesh& mesh);

}  // namespace cablefit
