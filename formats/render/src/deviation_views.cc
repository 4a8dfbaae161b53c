#include "cablefit/formats/deviation_views.h"

#include <algorithm>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "font.h"
#include "gl_scene.h"
#include "view_overlays.h"
#include "view_planning.h"

namespace cablefit {
namespace {

using render::FramingPoint;
using render::NamedView;

constexpr int kMargin = 14;
constexpr int kGap = 12;
constexpr int kColourColumn = 190;  // right-hand column: colour bar and legend [px]
constexpr int kHeader = 48;         // figure / row title band [px]
const Rgb kWhite{255, 255, 255};

void Validate(const Scene& scene, const RenderOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw UsageError("render options: " + why);
  for (std::size_t i = 0; i < scene.tubes.size(); ++i) {
    const SceneTube& tube = scene.tubes[i];
    const std::string name = "tube " + std::to_string(i) + (tube.name.empty() ? "" : " '" + tube.name + "'");
    if (!(tube.radius > 0.0) || !std::isfinite(tube.radius))
      throw InvalidInput(name + ": radius must be positive");
    if (tube.deviation.size() != 0 && tube.deviation.size() != tube.centreline.points.cols())
      throw InvalidInput(name + ": " + std::to_string(tube.deviation.size()) + " deviations for " +
                         std::to_string(tube.centreline.points.cols()) + " centre-line points");
  }
  if (scene.colour_scale && !scene.colour_scale->IsValid(&why)) throw UsageError("colour scale: " + why);
}

ColourScale ScaleFor(const Scene& scene, const RenderOptions& options) {
  return options.colour_scale ? *options.colour_scale : EffectiveColourScale(scene);
}

void PlaceColourBar(ViewLayout& layout, const RenderOptions& options, int top) {
  layout.colour_bar_x = options.width - kColourColumn + 22;
  layout.colour_bar_y = top + 44;
  layout.colour_bar_width = 24;
  layout.colour_bar_height = std::max(60, static_cast<int>((options.height - top) * 0.5));
}

Image Compose(const std::vector<const Scene*>& scenes, const ViewLayout& layout,
              const RenderOptions& options, const std::vector<std::pair<int, std::string>>& titles) {
  std::vector<render::GlPanelJob> jobs;
  for (const auto& panel : layout.panels)
    jobs.push_back({scenes[static_cast<std::size_t>(panel.scene)], panel.camera});
  const std::vector<ColourScale> scales(scenes.size(), layout.colour_scale);
  Image image = render::RenderPanels3d(options.width, options.height, options.supersample, kWhite,
                                      scenes, scales, jobs, options);
  for (const auto& panel : layout.panels) {
    const Scene& scene = *scenes[static_cast<std::size_t>(panel.scene)];
    render::DrawPanelFrame(image, panel.camera);
    render::DrawSupports(image, panel.camera, scene);
    render::DrawLabels(image, panel.camera, scene);
    render::DrawGravityArrow(image, panel.camera, scene.gravity);
    if (scene.show_scale_bar) render::DrawScaleBar(image, panel.camera);
  }
  render::DrawColourBar(image, layout.colour_bar_x, layout.colour_bar_y, layout.colour_bar_width,
                        layout.colour_bar_height, layout.colour_scale);
  render::DrawLegend(image, layout.colour_bar_x, layout.colour_bar_y + layout.colour_bar_height + 50,
                     scenes, options.show_scan_points);
  for (const auto& [y, text] : titles)
    render::Font::Get(render::FontWeight::kBold).Draw(image, kMargin + 2, y, text, 21, render::kInk);
  return image;
}

}  // namespace

bool RenderOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (width < 640 || height < 400 || width > 8192 || height > 8192)
    return fail("width x height must lie between 640 x 400 and 8192 x 8192 px");
  if (supersample < 1 || supersample > 4) return fail("supersample must be 1 .. 4");
  if (tube_sides < 3 || tube_sides > 128) return fail("tube_sides must be 3 .. 128");
  if (colour_scale && !colour_scale->IsValid(why)) return false;
  return true;
}

namespace {

// The single-scene layout framed on `points` (one scene's, or every frame's of a sequence).
ViewLayout PlanOnPoints(const std::vector<FramingPoint>& points, bool titled,
                        const ColourScale& scale, const RenderOptions& options) {
  ViewLayout layout;
  layout.colour_scale = scale;
  const int top = titled ? kHeader : kMargin;
  const int x0 = kMargin, x1 = options.width - kColourColumn, y1 = options.height - kMargin;
  const int iso_w = (x1 - x0 - kGap) / 2;
  const int right_x = x0 + iso_w + kGap;
  const int half_h = (y1 - top - kGap) / 2;
  const std::vector<NamedView> views = render::ChooseViews(points);
  layout.panels.push_back({render::FrameView(views[0], points, x0, top, iso_w, y1 - top), 0});
  layout.panels.push_back({render::FrameView(views[1], points, right_x, top, x1 - right_x, half_h), 0});
  layout.panels.push_back(
      {render::FrameView(views[2], points, right_x, top + half_h + kGap, x1 - right_x, y1 - top - half_h - kGap), 0});
  PlaceColourBar(layout, options, top);
  return layout;
}

}  // namespace

ViewLayout PlanDeviationViews(const Scene& scene, const RenderOptions& options) {
  Validate(scene, options);
  return PlanOnPoints(render::FramingPoints(scene, options.show_scan_points), !scene.title.empty(),
                      ScaleFor(scene, options), options);
}

ViewLayout PlanSideBySide(const Scene& first, const Scene& second, const RenderOptions& options) {
  Validate(first, options);
  Validate(second, options);
  ViewLayout layout;
  layout.colour_scale = options.colour_scale ? *options.colour_scale : CommonColourScale(first, second);
  // Both rows are framed on the union of both scenes: the same world point lands at the same
  // place in each row, so the eye can compare shapes directly.
  std::vector<FramingPoint> points = render::FramingPoints(first, options.show_scan_points);
  const std::vector<FramingPoint> more = render::FramingPoints(second, options.show_scan_points);
  points.insert(points.end(), more.begin(), more.end());
  const std::vector<NamedView> views = render::ChooseViews(points);
  const int x0 = kMargin, x1 = options.width - kColourColumn;
  const int col_w = (x1 - x0 - 2 * kGap) / 3;
  const int row_h = (options.height - kMargin - 2 * kHeader) / 2;
  for (int row = 0; row < 2; ++row) {
    const int y = kHeader + row * (row_h + kHeader);
    for (int col = 0; col < 3; ++col)
      layout.panels.push_back(
          {render::FrameView(views[static_cast<std::size_t>(col)], points, x0 + col * (col_w + kGap), y, col_w, row_h), row});
  }
  PlaceColourBar(layout, options, kHeader);
  return layout;
}

Image RenderDeviationViews(const Scene& scene, const RenderOptions& options) {
  const ViewLayout layout = PlanDeviationViews(scene, options);
  std::vector<std::pair<int, std::string>> titles;
  if (!scene.title.empty()) titles.emplace_back(kHeader - 16, scene.title);
  return Compose({&scene}, layout, options, titles);
}

void WarmUpRenderer(const RenderOptions& options) {
  // Everything a harness picture draws: a deviation-coloured tube with a highlighted stretch, a
  // flat-coloured one, a ghost, a part, a support and a label.
  Scene scene;
  scene.title = "warm-up";
  SceneTube tube;
  tube.centreline.points.resize(3, 3);
  tube.centreline.points << 0, 0.1, 0.2, 0, 0.02, 0, 0, -0.03, 0;
  tube.deviation = Eigen::Vector3d(0, 0.01, 0.002);
  scene.tubes.push_back(tube);
  tube.centreline.points.row(1).array() += 0.05;
  tube.deviation.resize(0);
  scene.tubes.push_back(tube);
  scene.highlights.push_back({0, 0.02, 0.08});
  SceneGhost ghost;
  ghost.points = scene.tubes[0].centreline.points;
  ghost.points.row(2).setZero();
  scene.ghosts.push_back(ghost);
  SceneSolid part;
  part.mesh.vertices.resize(3, 3);
  part.mesh.vertices << 0, 0.02, 0, 0, 0, 0.02, 0, 0, 0;
  part.mesh.faces.resize(3, 1);
  part.mesh.faces << 0, 1, 2;
  scene.solids.push_back(part);
  SceneSupport clamp;
  scene.supports.push_back(clamp);
  scene.labels.push_back({Eigen::Vector3d(0.1, 0.02, -0.03), "warm-up"});
  RenderDeviationViews(scene, options);
}

std::vector<Image> RenderDeviationSequence(const std::vector<Scene>& frames,
                                           const RenderOptions& options) {
  std::vector<Image> images;
  if (frames.empty()) return images;
  std::vector<FramingPoint> points;
  bool titled = false;
  for (const Scene& frame : frames) {
    Validate(frame, options);
    const std::vector<FramingPoint> more = render::FramingPoints(frame, options.show_scan_points);
    points.insert(points.end(), more.begin(), more.end());
    titled = titled || !frame.title.empty();
  }
  const ViewLayout layout = PlanOnPoints(points, titled, ScaleFor(frames.front(), options), options);
  for (const Scene& frame : frames) {
    std::vector<std::pair<int, std::string>> titles;
    if (!frame.title.empty()) titles.emplace_back(kHeader - 16, frame.title);
    images.push_back(Compose({&frame}, layout, options, titles));
  }
  return images;
}

Image RenderSideBySide(const Scene& first, const Scene& second, const RenderOptions& options) {
  const ViewLayout layout = PlanSideBySide(first, second, options);
  const int row_h = (options.height - kMargin - 2 * kHeader) / 2;
  std::vector<std::pair<int, std::string>> titles = {
      {kHeader - 16, first.title.empty() ? "first" : first.title},
      {kHeader + row_h + kHeader - 16, second.title.empty() ? "second" : second.title}};
  return Compose({&first, &second}, layout, options, titles);
}

}  // namespace cablefit
