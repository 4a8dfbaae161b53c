// Deviation maps: a cable drawn as a shaded tube coloured by its deviation, seen from an
// isometric and the two most informative axis-aligned directions, with colour bar, supports,
// ghost reference shape, gravity arrow and length scale. Rendered off-screen with OSMesa.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "cablefit/formats/image.h"
#include "cablefit/formats/scene.h"

namespace cablefit {

struct RenderOptions {
  int width = 1600;      // [px] final picture
  int height = 1000;     // [px]
  int supersample = 2;   // the 3-D views are rendered this many times larger, then averaged
                         // (OSMesa buffers have no multisampling): 1 disables anti-aliasing
  int tube_sides = 18;   // facets around the tube; normals are smooth, so 18 looks round
  bool show_scan_points = true;
  /// Forces the colour scale (e.g. the same range for pictures shown next to each other);
  /// unset: the scene's own, else the scenes' deviation range.
  std::optional<ColourScale> colour_scale;
  /// True when all fields are usable; otherwise `why` says which is not.
  bool IsValid(std::string* why) const;
};

/// An orthographic camera looking at one panel of the picture.
struct ViewCamera {
  std::string title;           // e.g. "isometric", "front (X\u2013Z)"
  Eigen::Matrix3d rotation;    // 3 x 3, rows: screen right, screen up, towards the viewer (world -> view)
  Eigen::Vector2d centre;      // 2 [m] view-plane coordinates shown at `origin_px`
  Eigen::Vector2d origin_px;   // 2 [px] in the final picture (x right, y down)
  double pixels_per_metre = 1.0;
  int x = 0, y = 0, width = 0, height = 0;  // panel rectangle in the final picture [px]

  /// Final-picture pixel coordinates of world point `p` (3 [m]); pixel (i, j) covers
  /// [i, i+1) x [j, j+1).
  Eigen::Vector2d Project(const Eigen::Vector3d& p) const;
};

/// Where each panel goes and how it is seen; computed before rendering so callers (tests, the
/// report's image maps) can find where a world point lands.
struct ViewLayout {
  struct Panel {
    ViewCamera camera;
    int scene = 0;  // which scene (0, or 1 for the second one of a side-by-side picture)
  };
  std::vector<Panel> panels;
  ColourScale colour_scale;
  int colour_bar_x = 0, colour_bar_y = 0, colour_bar_width = 0, colour_bar_height = 0;  // [px]
};

/// Layout of RenderDeviationViews. Throws UsageError when the options are invalid.
ViewLayout PlanDeviationViews(const Scene& scene, const RenderOptions& options);
/// Layout of RenderSideBySide: one row per scene, same views, framing and colour scale.
ViewLayout PlanSideBySide(const Scene& first, const Scene& second, const RenderOptions& options);

/// Isometric + two orthographic views of `scene`, colour bar and annotations.
Image RenderDeviationViews(const Scene& scene, const RenderOptions& options);
/// Gets the renderer ready for pictures of `options`' size: opens OSMesa, makes the off-screen
/// context and shaders and draws a small scene once, so that llvmpipe has compiled its shader
/// variants (about 0.3 s on the first picture of a process otherwise). Any thread: the GL
/// context is one per process, entered by one thread at a time. Throws like
/// RenderDeviationViews; a caller warming up in the background may ignore that (the picture
/// itself reports it).
void WarmUpRenderer(const RenderOptions& options);

/// The frames of an animation as RenderDeviationViews draws them, on one layout: the views are
/// chosen and framed on every frame's points together, so the camera stands still from frame to
/// frame, and the colour scale is the options', else the first frame's.
std::vector<Image> RenderDeviationSequence(const std::vector<Scene>& frames,
                                           const RenderOptions& options);
/// `first` (e.g. baseline) above `second` (e.g. fitted), on one colour scale.
Image RenderSideBySide(const Scene& first, const Scene& second, const RenderOptions& options);

}  // namespace cablefit
