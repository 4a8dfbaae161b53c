#include "contact_frame.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "cablefit/core/base/errors.h"

namespace cablefit::internal {
namespace {

// Least-squares slope dx/ds of the points at `indices`.
Vec3 Slope(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& point_s,
           const std::vector<Eigen::Index>& indices) {
  double s_mean = 0.0;
  Vec3 x_mean = Vec3::Zero();
  for (Eigen::Index i : indices) {
    s_mean += point_s[i];
    x_mean += points.col(i);
  }
  s_mean /= static_cast<double>(indices.size());
  x_mean /= static_cast<double>(indices.size());
  Vec3 sxs = Vec3::Zero();
  double sss = 0.0;
  for (Eigen::Index i : indices) {
    const double ds = point_s[i] - s_mean;
    sxs += ds * (points.col(i) - x_mean);
    sss += ds * ds;
  }
  return sss > 0 ? Vec3(sxs / sss) : Vec3::Zero();
}

}  // namespace

ContactFrame RecordedContactFrame(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& point_s,
                                  double s, double window, const Vec3& gravity) {
  const Eigen::Index n = points.cols();
  if (n < 2 || point_s.size() != n) throw InvalidInput("a contact frame needs two recorded points");
  // A scan of the points, not a search: arc lengths from a recording need not be sorted.
  std::vector<Eigen::Index> near;
  for (double w = std::max(window, 1e-9);; w *= 2) {
    near.clear();
    for (Eigen::Index i = 0; i < n; ++i)
      if (std::abs(point_s[i] - s) <= w) near.push_back(i);
    if (near.size() >= std::min<std::size_t>(4, static_cast<std::size_t>(n)) ||
        static_cast<Eigen::Index>(near.size()) == n || !(w < 1e12))
      break;
  }
  ContactFrame f;
  f.tangent = near.size() >= 2 ? Slope(points, point_s, near) : Vec3::Zero();
  if (!(f.tangent.norm() > 0)) f.tangent = points.col(n - 1) - points.col(0);
  if (!(f.tangent.norm() > 0)) f.tangent = Vec3::UnitX();
  f.tangent.normalize();
  const Vec3 against = gravity.norm() > 0 ? Vec3(-gravity.normalized()) : Vec3::Zero();
  f.up = against - against.dot(f.tangent) * f.tangent;
  // Within about 6 degrees of vertical the projection of gravity no longer picks a direction.
  if (f.up.norm() < 0.1) f.up = f.tangent.unitOrthogonal();
  f.up.normalize();
  f.side = f.tangent.cross(f.up);
  return f;
}

}  // namespace cablefit::internal
