// Choosing and framing the views of a deviation picture (pure geometry, no GL).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cablefit/formats/deviation_views.h"
#include "cablefit/formats/scene.h"

namespace cablefit::render {

struct NamedView {
  std::string title;
  Eigen::Matrix3d rotation;  // 3 x 3, rows: right, up, towards the viewer
};

/// A point that must be visible, with the margin around it [m] (a tube's radius).
struct FramingPoint {
  Eigen::Vector3d p;  // 3 [m]
  double pad = 0.0;   // [m]
};

std::vector<FramingPoint> FramingPoints(const Scene& scene, bool with_scan_points);

/// Isometric view plus the two axis-aligned views whose projected bounding box of `points` is
/// largest (the third one looks along the geometry's thinnest direction and shows least).
std::vector<NamedView> ChooseViews(const std::vector<FramingPoint>& points);

/// Panel chrome shared by layout and overlays [px].
inline constexpr int kPanelTitleBand = 34;
inline constexpr int kPanelFooterBand = 46;
inline constexpr int kPanelSideInset = 16;

/// Camera showing all `points` as large as fits into the panel's drawing area (between the
/// title band and the footer). `pixels_per_metre` > 0 forces the scale (shared framing).
ViewCamera FrameView(const NamedView& view, const std::vector<FramingPoint>& points, int x, int y,
                     int width, int height, double pixels_per_metre = 0.0);

/// Largest scale [px/m] at which `points` fit a panel of that size.
double FittingScale(const NamedView& view, const std::vector<FramingPoint>& points, int width,
                    int height);

}  // namespace cablefit::render
