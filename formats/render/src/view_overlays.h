// 2-D annotations drawn over the rendered 3-D panels: panel frame and title, support markers
// and labels, gravity arrow, length scale bar, colour bar and legend.
#pragma once

#include <string>
#include <vector>

#include "cablefit/formats/deviation_views.h"
#include "cablefit/formats/scene.h"

namespace cablefit::render {

inline const Rgb kInk{40, 40, 40};
inline const Rgb kMutedInk{100, 100, 100};
inline const Rgb kFrame{205, 205, 205};
inline const Rgb kHighlight{214, 39, 40};

void DrawPanelFrame(Image& image, const ViewCamera& camera);
void DrawSupports(Image& image, const ViewCamera& camera, const Scene& scene);
/// Each of the scene's labels: a ring at its point and its text beside it.
void DrawLabels(Image& image, const ViewCamera& camera, const Scene& scene);
void DrawGravityArrow(Image& image, const ViewCamera& camera, const Eigen::Vector3d& gravity);
void DrawScaleBar(Image& image, const ViewCamera& camera);
/// Vertical colour bar with ticks, numbers and the scale's label as title.
void DrawColourBar(Image& image, int x, int y, int width, int height, const ColourScale& scale);
/// Explains the symbols that occur in `scenes` (ghost line, support kinds, scan points,
/// highlight), stacked downwards from (x, y). Returns the y below the last entry.
int DrawLegend(Image& image, int x, int y, const std::vector<const Scene*>& scenes,
               bool with_scan_points);
/// Metres as a short length label: "50 mm", "1.2 m", "0.5 mm".
std::string FormatLength(double metres);

}  // namespace cablefit::render
