// What a deviation picture shows, as plain data: no GL, no file format. The renderer
// (deviation_views.h) turns a Scene into pixels; the report and the CLI only fill Scenes.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/rod/rod_spec.h"
#include "cablefit/formats/colour_map.h"
#include "cablefit/formats/image.h"

namespace cablefit {

/// A cable drawn as a shaded tube around its centre line.
struct SceneTube {
  std::string name;
  Polyline centreline;        // 3 x n [m]; `s` is filled by chord length when empty
  double radius = 0.004;      // [m] drawn radius
  Eigen::VectorXd deviation;  // n [m] per centre-line vertex; empty -> drawn in `flat_colour`
  Rgb flat_colour{150, 150, 150};
};

/// A thin grey reference shape (drawn route, recorded shape) to compare the tube against.
struct SceneGhost {
  std::string name;
  Eigen::Matrix3Xd points;  // 3 x n [m], drawn as one connected line
  Rgb colour{140, 140, 140};
};

enum class SupportMarkerKind { kClamp, kClip, kPin };
std::string ToString(SupportMarkerKind kind);
/// How a support of the rod is drawn.
SupportMarkerKind MarkerOf(SupportKind kind);

/// A support, drawn as a marker (square = clamp, ring = clip, triangle = pin) with its label.
struct SceneSupport {
  SupportMarkerKind kind = SupportMarkerKind::kClamp;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // 3 [m]
  std::string label;  // e.g. "1"; empty -> its index + 1; blank (" ") -> no label
};

/// A part beside the cables (clip, bracket, duct), drawn as a translucent grey body so that
/// the cables inside it stay visible. It does not widen the views: they frame the cables.
struct SceneSolid {
  std::string name;
  TriangleMesh mesh;  // [m]
};

/// A text at a point of the model, with a small ring there: a cable's name at its largest
/// deviation, so the reader knows which tube is which and where it moved most.
struct SceneLabel {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // 3 [m]
  std::string text;
};

/// A stretch of one tube to draw attention to (e.g. the region a diagnosis blames).
struct ArcHighlight {
  int tube = 0;          // index into Scene::tubes
  double s_begin = 0.0;  // [m] arc length along that tube's centre line
  double s_end = 0.0;    // [m]
};

struct Scene {
  std::string title;  // shown above the views (side-by-side: above this scene's row)
  std::vector<SceneTube> tubes;
  std::vector<SceneGhost> ghosts;
  std::vector<SceneSupport> supports;
  std::vector<SceneLabel> labels;
  std::vector<SceneSolid> solids;
  Eigen::Matrix3Xd scan_points;  // 3 x m [m], already sub-sampled by the caller; may be empty
  std::vector<ArcHighlight> highlights;
  int highlighted_support = -1;  // index into `supports`, -1 for none
  std::string highlight_label = "highlighted";  // the legend's words for the highlights
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);  // 3 [m/s^2]; zero hides the arrow
  bool show_scale_bar = true;
  /// Colour-bar range in mm; when unset it spans the tubes' deviations (from 0 when all >= 0).
  std::optional<ColourScale> colour_scale;
};

/// The colour scale a scene is drawn with: its own, or one spanning its tubes' deviations [mm].
ColourScale EffectiveColourScale(const Scene& scene);
/// One scale spanning both scenes, so that two pictures compare colour for colour.
ColourScale CommonColourScale(const Scene& a, const Scene& b);

}  // namespace cablefit
