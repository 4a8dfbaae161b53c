// CGAL k-d tree (Search_traits_adapter over point indices), see CGAL Spatial Searching manual,
// "Using a Point Property Map" example; the only CGAL translation unit of formats/scan.
#include "point_index.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/function_output_iterator.hpp>

namespace cablefit::scan {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point3 = Kernel::Point_3;
using PointMap = CGAL::Pointer_property_map<Point3>::type;
using TraitsBase = CGAL::Search_traits_3<Kernel>;
using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, TraitsBase>;
using KnnSearch = CGAL::Orthogonal_k_neighbor_search<Traits>;
using Tree = KnnSearch::Tree;
using Splitter = Tree::Splitter;
using Distance = KnnSearch::Distance;
using Sphere = CGAL::Fuzzy_sphere<Traits>;

Point3 ToCgal(const Eigen::Vector3d& p) { return Point3(p.x(), p.y(), p.z()); }

// CGAL copies and assigns its output iterator, which a capturing lambda cannot do.
struct AppendIndex {
  std::vector<int>* out;
  void operator()(std::size_t i) const { out->push_back(static_cast<int>(i)); }
};

}  // namespace

struct PointIndex::Impl {
  std::vector<Point3> points;
  PointMap point_map;
  Traits traits;
  Tree tree;
  Distance distance;

  explicit Impl(const Eigen::Matrix3Xd& m)
      : points(MakePoints(m)),
        point_map(points.data()),
        traits(point_map),
        tree(boost::counting_iterator<std::size_t>(0),
             boost::counting_iterator<std::size_t>(points.size()), Splitter(), traits),
        distance(point_map) {
    tree.build();
  }

  static std::vector<Point3> MakePoints(const Eigen::Matrix3Xd& m) {
    std::vector<Point3> out;
    out.reserve(static_cast<std::size_t>(m.cols()));
    for (Eigen::Index i = 0; i < m.cols(); ++i) out.push_back(ToCgal(m.col(i)));
    return out;
  }
};

PointIndex::PointIndex(const Eigen::Matrix3Xd& points) : impl_(std::make_unique<Impl>(points)) {}
PointIndex::~PointIndex() = default;

void PointIndex::Nearest(const Eigen::Vector3d& query, int k, std::vector<int>* indices,
                         std::vector<double>* distances) const {
  indices->clear();
  if (distances) distances->clear();
  if (impl_->points.empty() || k <= 0) return;
  KnnSearch search(impl_->tree, ToCgal(query), static_cast<unsigned>(k), 0, true, impl_->distance);
  for (const auto& hit : search) {
    indices->push_back(static_cast<int>(hit.first));
    if (distances) distances->push_back(std::sqrt(hit.second));
  }
}

void PointIndex::WithinRadius(const Eigen::Vector3d& query, double radius,
                              std::vector<int>* indices) const {
  indices->clear();
  if (impl_->points.empty()) return;
  Sphere sphere(ToCgal(query), radius, 0.0, impl_->traits);
  impl_->tree.search(boost::make_function_output_iterator(AppendIndex{indices}), sphere);
}

}  // namespace cablefit::scan
