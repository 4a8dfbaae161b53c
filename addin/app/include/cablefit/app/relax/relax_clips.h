// Clips found from the drawing: where a cable's route passes through another solid (a clip,
// a grommet, a ring), the cable is held there. A solid is represented by the smaller of its
// axis-aligned and principal-axes bounding boxes, so a ring (torus) the cable threads counts as
// passing through, like a box clip moulded around it.
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit::addin {

/// An oriented box: centre + rotation (columns = box axes) + half extents.
struct OrientedBox {
  Vec3 centre = Vec3::Zero();       // 3 [m]
  Mat3 axes = Mat3::Identity();     // 3 x 3, columns unit box axes (world)
  Vec3 half_extent = Vec3::Zero();  // 3 [m] along each axis

  bool Contains(const Vec3& p) const;
  double Volume() const { return 8 * half_extent.prod(); }
};

/// The smaller (by volume) of the axis-aligned and the principal-axes box of the mesh's
/// vertices. Throws InvalidInput for a mesh without vertices.
OrientedBox BoundingBoxOf(const TriangleMesh& mesh);

/// A stretch of the route inside a solid's box.
struct ClipSpan {
  int solid = 0;
  std::string solid_name;
  double s_in = 0.0, s_out = 0.0;  // [m] entry and exit arc lengths
};

/// Stretches of `route` (s from 0 by chords) inside each box, entry/exit located by bisection
/// on the route's segments to `tolerance` [m]. Stretches touching either end of the route are
/// left out: a cable ending inside a housing is held by its end support already.
std::vector<ClipSpan> FindClipSpans(const Polyline& route, const std::vector<OrientedBox>& boxes,
                                    const std::vector<std::string>& names, double tolerance);

}  // namespace cablefit::addin
