// Splitting a mesh into connected components and a curve skeleton into routes.
#pragma once

#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "mcf_skeleton.h"

namespace cablefit {

/// The connected components of `mesh` (faces sharing edges; around an edge of more than two
/// faces, the faces bounding one solid), each re-indexed.
std::vector<TriangleMesh> ConnectedComponents(const TriangleMesh& mesh);

struct SkeletonRoute {
  std::vector<int> nodes;  ///< skeleton node indices in order
  bool start_is_end = false;  ///< the first node is a free end (degree 1), not a branch point
  bool finish_is_end = false;
};

/// Removes spurs (a free end joined to a branch point by a path shorter than `min_spur` [m], or
/// whose free end lies within `min_spur` of the rest of the skeleton), then returns every maximal path between nodes of degree != 2. A cycle without such a node
/// is returned as one route with neither end free.
std::vector<SkeletonRoute> SplitSkeleton(const CurveSkeleton& skeleton, double min_spur);

}  // namespace cablefit
