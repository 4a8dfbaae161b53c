#include "mcf_skeleton.h"

#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>
#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"

namespace cablefit {

CurveSkeleton ComputeMcfSkeleton(const TriangleMesh& mesh) {
  using Kernel = CGAL::Simple_cartesian<double>;
  using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
  using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<Surface>;
  // CGAL's default random generator is seeded from the clock, and the flow's Delaunay poles
  // depend on its insertion order: without a fixed seed the same mesh gave different routes (a
  // 12-triangle cube was a 23 mm "tube" in about one run of thirty). The generator is per thread.
  CGAL::get_default_random() = CGAL::Random(0);
  Surface surface;
  std::vector<Surface::Vertex_index> index(mesh.vertices.cols());
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    index[v] = surface.add_vertex({mesh.vertices(0, v), mesh.vertices(1, v), mesh.vertices(2, v)});
  }
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) {
    if (surface.add_face(index[mesh.faces(0, f)], index[mesh.faces(1, f)],
                         index[mesh.faces(2, f)]) == Surface::null_face()) {
      throw InvalidInput("the mesh is not manifold (an edge has more than two faces, or faces "
                         "are inconsistently oriented)");
    }
  }
  if (!CGAL::is_closed(surface)) throw InvalidInput("the mesh is not a closed surface");
  if (!CGAL::is_triangle_mesh(surface)) throw InvalidInput("the mesh is not triangulated");

  // CAD tessellations span a straight stretch with long slivers: the flow has no vertex there to
  // contract, and the skeleton covers the bends only. Remesh isotropically first, to edges for
  // about kTargetTriangles equilateral triangles (the flow costs ~0.4 s per 12k triangles).
  constexpr double kTargetTriangles = 15000;
  const double area = CGAL::Polygon_mesh_processing::area(surface);
  const double target_edge = std::sqrt(4 * area / (std::sqrt(3.0) * kTargetTriangles));
  CGAL::Polygon_mesh_processing::isotropic_remeshing(
      faces(surface), target_edge, surface,
      CGAL::parameters::number_of_iterations(3));
  surface.collect_garbage();

  Skeletonization::Skeleton skeleton;
  CGAL::extract_mean_curvature_flow_skeleton(surface, skeleton);
  CurveSkeleton result;
  const auto n = boost::num_vertices(skeleton);
  result.nodes.resize(3, static_cast<Eigen::Index>(n));
  result.vertex_points.resize(n);
  for (auto v : CGAL::make_range(vertices(skeleton))) {
    const auto& p = skeleton[v].point;
    result.nodes.col(static_cast<Eigen::Index>(v)) << p.x(), p.y(), p.z();
    for (auto sv : skeleton[v].vertices) {
      const auto& q = surface.point(sv);
      result.vertex_points[v].push_back(Eigen::Vector3d(q.x(), q.y(), q.z()));
    }
  }
  for (auto e : CGAL::make_range(edges(skeleton))) {
    result.edges.emplace_back(static_cast<int>(source(e, skeleton)),
                              static_cast<int>(target(e, skeleton)));
  }
  return result;
}

}  // namespace cablefit
