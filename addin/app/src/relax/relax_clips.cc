#include "cablefit/app/relax/relax_clips.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "relax/relax_route.h"

namespace cablefit::addin {
namespace {

OrientedBox BoxAlong(const Eigen::Matrix3Xd& v, const Mat3& axes) {  // v: 3 x n [m]
  const Eigen::Matrix3Xd local = axes.transpose() * v;               // 3 x n [m]
  const Vec3 lo = local.rowwise().minCoeff();
  const Vec3 hi = local.rowwise().maxCoeff();
  OrientedBox box;
  box.axes = axes;
  box.centre = axes * (0.5 * (lo + hi));
  box.half_extent = 0.5 * (hi - lo);
  return box;
}

}  // namespace

bool OrientedBox::Contains(const Vec3& p) const {
  const Vec3 local = axes.transpose() * (p - centre);
  return (local.cwiseAbs().array() <= half_extent.array()).all();
}

OrientedBox BoundingBoxOf(const TriangleMesh& mesh) {
  const Eigen::Matrix3Xd& v = mesh.vertices;
  if (v.cols() == 0) throw InvalidInput("a solid has no tessellation");
  const OrientedBox aligned = BoxAlong(v, Mat3::Identity());
  const Vec3 mean = v.rowwise().mean();
  const Eigen::Matrix3Xd centred = v.colwise() - mean;  // 3 x n [m]
  Eigen::SelfAdjointEigenSolver<Mat3> eig(centred * centred.transpose());
  const OrientedBox principal = BoxAlong(v, eig.eigenvectors());
  return principal.Volume() < aligned.Volume() ? principal : aligned;
}

std::vector<ClipSpan> FindClipSpans(const Polyline& route, const std::vector<OrientedBox>& boxes,
                                    const std::vector<std::string>& names, double tolerance) {
  std::vector<ClipSpan> spans;
  const Eigen::Index n = route.size();
  for (size_t b = 0; b < boxes.size(); ++b) {
    const OrientedBox& box = boxes[b];
    // The arc length in [s0, s1] where Contains() flips, assuming one flip (bisection).
    auto crossing = [&](double s0, double s1) {
      const bool inside0 = box.Contains(RoutePoint(route, s0));
      while (s1 - s0 > tolerance) {
        const double mid = 0.5 * (s0 + s1);
        (box.Contains(RoutePoint(route, mid)) == inside0 ? s0 : s1) = mid;
      }
      return 0.5 * (s0 + s1);
    };
    bool inside = box.Contains(route.points.col(0));
    bool touches_start = inside;
    double s_in = 0.0;
    for (Eigen::Index i = 1; i < n; ++i) {
      const bool now = box.Contains(route.points.col(i));
      if (now == inside) continue;
      const double s = crossing(route.s[i - 1], route.s[i]);
      if (now) {
        s_in = s;
      } else if (!touches_start) {
        spans.push_back({static_cast<int>(b), names[b], s_in, s});
      }
      if (!now) touches_start = false;
      inside = now;
    }
    // A stretch still open at the end touches the end: left out.
  }
  std::sort(spans.begin(), spans.end(),
            [](const ClipSpan& a, const ClipSpan& b) { return a.s_in < b.s_in; });
  return spans;
}

}  // namespace cablefit::addin
