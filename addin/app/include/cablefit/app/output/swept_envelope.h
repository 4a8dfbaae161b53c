// The swept envelope of a cable: one triangle mesh that encloses its tube in every one of a set
// of shapes (the poses of a motion, the corners of a tolerance box). The construction is the
// plain one: the union of the closed tube surfaces of the shapes, concatenated into one mesh
// (overlapping shells, not a boolean union: a point is inside the envelope when it is inside
// any shell, i.e. its winding number is at least 1). Each tube's cross-section polygon
// circumscribes the tube's circle, so the facets touch the tube from outside. Between two
// shapes nothing is added: the motion between consecutive poses is covered as densely as the
// poses are.
#pragma once

#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::addin {

struct EnvelopeOptions {
  int sides = 12;          ///< polygon sides of a tube's cross-section (>= 3)
  int min_rings = 17;      ///< cross-sections per shape, at least...
  int max_rings = 97;      ///< ...and at most; about one per diameter in between
  /// [m] a shape closer than this to an earlier shape at every sample adds nothing and is left
  /// out (the way back of a there-and-back motion).
  double repeat_tolerance = 1e-6;
  /// Most shapes in one envelope; with more, evenly spaced ones (first and last kept), and
  /// SweptEnvelope says how many it used.
  int max_shapes = 401;
};

/// The closed surface of a tube of `radius` [m] around `points` (3 x n [m], n >= 2 distinct):
/// rings of `sides` vertices on rotation-minimising frames (parallel transport), flat end
/// caps, faces counter-clockwise seen from outside.
TriangleMesh TubeSurface(const Eigen::Matrix3Xd& points, double radius, int sides);

/// The envelope of a cable of `radius` [m] over `shapes` (centrelines with arc length; all of
/// the same cable). `used` (optional) gets the indices of the shapes that went into the mesh.
TriangleMesh SweptEnvelope(const std::vector<Polyline>& shapes, double radius,
                           const EnvelopeOptions& options, std::vector<size_t>* used = nullptr);

/// Generalised winding number of `mesh` at `p` (sum of the triangles' signed solid angles over
/// 4 pi; A. Van Oosterom, J. Strackee, IEEE Trans. Biomed. Eng. 30(2), 1983): for a union of
/// closed outward shells, the number of shells around `p`.
double WindingNumber(const TriangleMesh& mesh, const Vec3& p);

/// Appends `b` to `a` (indices shifted).
void AppendMesh(const TriangleMesh& b, TriangleMesh* a);

}  // namespace cablefit::addin
