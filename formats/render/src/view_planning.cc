#include "view_planning.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tube_mesh.h"

namespace cablefit {

Eigen::Vector2d ViewCamera::Project(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d v = rotation * p;
  return {origin_px.x() + (v.x() - centre.x()) * pixels_per_metre,
          origin_px.y() - (v.y() - centre.y()) * pixels_per_metre};
}

namespace render {
namespace {

struct Box2 {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  bool Empty() const { return !(lo.x() <= hi.x()); }
};

Box2 ProjectedBox(const Eigen::Matrix3d& rotation, const std::vector<FramingPoint>& points) {
  Box2 box;
  for (const FramingPoint& fp : points) {
    const Eigen::Vector2d v = (rotation * fp.p).head<2>();
    box.lo = box.lo.cwiseMin(v - Eigen::Vector2d::Constant(fp.pad));
    box.hi = box.hi.cwiseMax(v + Eigen::Vector2d::Constant(fp.pad));
  }
  return box;
}

Eigen::Matrix3d Rows(const Eigen::Vector3d& right, const Eigen::Vector3d& up,
                     const Eigen::Vector3d& toward) {
  Eigen::Matrix3d r;
  r.row(0) = right.transpose();
  r.row(1) = up.transpose();
  r.row(2) = toward.transpose();
  return r;
}

}  // namespace

std::vector<FramingPoint> FramingPoints(const Scene& scene, bool with_scan_points) {
  std::vector<FramingPoint> points;
  for (const SceneTube& tube : scene.tubes)
    for (Eigen::Index i = 0; i < tube.centreline.points.cols(); ++i)
      if (tube.centreline.points.col(i).allFinite())
        points.push_back({tube.centreline.points.col(i), tube.radius});
  for (const SceneGhost& ghost : scene.ghosts)
    for (Eigen::Index i = 0; i < ghost.points.cols(); ++i)
      if (ghost.points.col(i).allFinite()) points.push_back({ghost.points.col(i), 0.0});
  for (const SceneSupport& support : scene.supports)
    if (support.position.allFinite()) points.push_back({support.position, 0.0});
  if (with_scan_points)
    for (Eigen::Index i = 0; i < scene.scan_points.cols(); ++i)
      if (scene.scan_points.col(i).allFinite()) points.push_back({scene.scan_points.col(i), 0.0});
  return points;
}

std::vector<NamedView> ChooseViews(const std::vector<FramingPoint>& points) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  const std::array<NamedView, 3> axis_views = {{
      {"front (X\u2013Z)", Rows(x, z, -y)},
      {"top (X\u2013Y)", Rows(x, y, z)},
      {"side (Y\u2013Z)", Rows(y, z, x)},
  }};
  std::array<double, 3> area{};
  for (std::size_t i = 0; i < 3; ++i) {
    const Box2 box = ProjectedBox(axis_views[i].rotation, points);
    area[i] = box.Empty() ? 0.0 : (box.hi - box.lo).prod();
  }
  // Drop the view with the smallest area; ties keep the conventional order front, top, side.
  std::size_t drop = 2;
  for (std::size_t i = 0; i < 3; ++i)
    if (area[i] < area[drop] * (1.0 - 1e-9)) drop = i;
  const Eigen::Vector3d toward = Eigen::Vector3d(1, -1, 1).normalized();
  const Eigen::Vector3d up = (z - z.dot(toward) * toward).normalized();
  std::vector<NamedView> views = {{"isometric", Rows(up.cross(toward), up, toward)}};
  for (std::size_t i = 0; i < 3; ++i)
    if (i != drop) views.push_back(axis_views[i]);
  return views;
}

ViewCamera FrameView(const NamedView& view, const std::vector<FramingPoint>& points, int x, int y,
                     int width, int height, double pixels_per_metre) {
  ViewCamera camera;
  camera.title = view.title;
  camera.rotation = view.rotation;
  camera.x = x;
  camera.y = y;
  camera.width = width;
  camera.height = height;
  const double area_w = std::max(1, width - 2 * kPanelSideInset);
  const double area_h = std::max(1, height - kPanelTitleBand - kPanelFooterBand);
  camera.origin_px = {x + width / 2.0, y + kPanelTitleBand + area_h / 2.0};
  Box2 box = ProjectedBox(view.rotation, points);
  if (box.Empty()) box.lo = box.hi = Eigen::Vector2d::Zero();
  camera.centre = (box.lo + box.hi) / 2.0;
  const Eigen::Vector2d size = (box.hi - box.lo).cwiseMax(1e-6);
  // 4 % breathing room around the geometry.
  camera.pixels_per_metre = pixels_per_metre > 0.0
                                ? pixels_per_metre
                                : 0.96 * std::min(area_w / size.x(), area_h / size.y());
  return camera;
}

/// Largest scale at which `points` fit the panel rectangle's drawing area.
double FittingScale(const NamedView& view, const std::vector<FramingPoint>& points, int width,
                    int height) {
  return FrameView(view, points, 0, 0, width, height).pixels_per_metre;
}

}  // namespace render
}  // namespace cablefit
