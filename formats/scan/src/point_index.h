// Spatial index over a fixed set of 3-D points (k nearest neighbours, ball queries). The CGAL
// k-d tree lives behind a pimpl so that only point_index.cc pays CGAL's compile time.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace cablefit::scan {

class PointIndex {
 public:
  /// Indexes `points` (3 x n [m]); the matrix must outlive the index.
  explicit PointIndex(const Eigen::Matrix3Xd& points);
  ~PointIndex();
  PointIndex(const PointIndex&) = delete;
  PointIndex& operator=(const PointIndex&) = delete;

  /// Indices of the k nearest points to `query` (3 [m]), nearest first, with their distances
  /// [m] (the point itself is included when `query` is an indexed point).
  void Nearest(const Eigen::Vector3d& query, int k, std::vector<int>* indices,
               std::vector<double>* distances) const;
  /// Indices of all points within `radius` [m] of `query` (3 [m]), in no particular order.
  void WithinRadius(const Eigen::Vector3d& query, double radius, std::vector<int>* indices) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cablefit::scan
