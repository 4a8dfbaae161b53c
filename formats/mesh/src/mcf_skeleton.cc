#include "mcf_skeleton.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>

#include "cablefit/core/errors.h"

namespace cablefit {

CurveSkeleton ComputeMcfSkeleton(const TriangleMesh& mesh) {
  using Kernel = CGAL::Simple_cartesian<double>;
  using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
  using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<Surface>;
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

  Skeletonization::Skeleton skeleton;
  CGAL::extract_mean_curvature_flow_skeleton(surface, skeleton);
  CurveSkeleton result;
  const auto n = boost::num_vertices(skeleton);
  result.nodes.resize(3, static_cast<Eigen::Index>(n));
  result.vertices.resize(n);
  for (auto v : CGAL::make_range(vertices(skeleton))) {
    const auto& p = skeleton[v].point;
    result.nodes.col(static_cast<Eigen::Index>(v)) << p.x(), p.y(), p.z();
    // Surface_mesh indices follow insertion order, so idx() is the input vertex index.
    for (auto sv : skeleton[v].vertices) result.vertices[v].push_back(static_cast<int>(sv.idx()));
  }
  for (auto e : CGAL::make_range(edges(skeleton))) {
    result.edges.emplace_back(static_cast<int>(source(e, skeleton)),
                              static_cast<int>(target(e, skeleton)));
  }
  return result;
}

}  // namespace cablefit
