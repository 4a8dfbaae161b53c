// Curve skeleton of a closed triangle mesh (the only place CGAL is compiled: it is slow).
#pragma once

#include <utility>
#include <vector>

#include "cablefit/core/geometry_types.h"

namespace cablefit {

struct CurveSkeleton {
  Eigen::Matrix3Xd nodes;                  // 3 x n [m]
  std::vector<std::pair<int, int>> edges;  // node index pairs
  std::vector<std::vector<int>> vertices;  // per node: the mesh vertices that collapsed onto it
};

/// Mean-curvature-flow skeleton (A. Tagliasacchi, I. Alhashim, M. Olson, H. Zhang, "Mean
/// Curvature Skeletons", Computer Graphics Forum 31(5), 2012; CGAL's implementation).
/// `mesh` must be one closed, manifold component. Throws InvalidInput otherwise.
CurveSkeleton ComputeMcfSkeleton(const TriangleMesh& mesh);

}  // namespace cablefit
