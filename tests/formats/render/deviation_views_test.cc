#include "cablefit/formats/deviation_views.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/png_file.h"
#include "synthetic_scene.h"
#include "colour_distance.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::ColourDistance;

// llvmpipe's output varies slightly with SIMD width; shading adds a little on top.
constexpr double kColourTolerance = 40.0;

bool InAnyPanel(const ViewLayout& layout, int x, int y) {
  for (const auto& p : layout.panels)
    if (x >= p.camera.x && x < p.camera.x + p.camera.width && y >= p.camera.y && y < p.camera.y + p.camera.height)
      return true;
  return false;
}

// Smallest distance to `colour` over the panels' pixels.
double ClosestInPanels(const Image& image, const ViewLayout& layout, Rgb colour) {
  double best = 1e9;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (InAnyPanel(layout, x, y)) best = std::min(best, ColourDistance(image.At(x, y), colour));
  return best;
}

double ClosestNear(const Image& image, const Eigen::Vector2d& p, int half, Rgb colour) {
  double best = 1e9;
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx) {
      const int x = static_cast<int>(p.x()) + dx, y = static_cast<int>(p.y()) + dy;
      if (image.Contains(x, y)) best = std::min(best, ColourDistance(image.At(x, y), colour));
    }
  return best;
}

TEST(DeviationViews, RendersTheKnownCaseWithItsColourRange) {
  const testing::SaggingCable cable;
  Scene scene = cable.Build();
  scene.title = "synthetic sagging cable";
  scene.highlights.push_back({0, cable.peak_s - 0.05, cable.peak_s + 0.05});
  const RenderOptions options;
  const ViewLayout layout = PlanDeviationViews(scene, options);
  const Image image = RenderDeviationViews(scene, options);
  WritePng((cablefit::testing::FreshTempDir("render") / "deviation_views.png").string(), image);
  ASSERT_EQ(image.width, 1600);
  ASSERT_EQ(image.height, 1000);
  ASSERT_EQ(layout.panels.size(), 3u);

  // Not blank: the tubes cover a visible share of the panels.
  long coloured = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (InAnyPanel(layout, x, y) && ColourDistance(image.At(x, y), Viridis(0.0)) < kColourTolerance) ++coloured;
  EXPECT_GT(coloured, 2000);

  // Range: the scale spans 0 .. peak, and both ends of the map show on the tube.
  EXPECT_NEAR(layout.colour_scale.min, 0.0, 1e-12);
  EXPECT_NEAR(layout.colour_scale.max, cable.peak_mm, 0.05);
  EXPECT_LT(ClosestInPanels(image, layout, Viridis(0.0)), kColourTolerance);
  EXPECT_LT(ClosestInPanels(image, layout, Viridis(1.0)), kColourTolerance);

  // Where the peak projects, every panel shows the colour bar's top colour.
  const Eigen::Vector3d peak = cable.Point(cable.peak_s / scene.tubes[0].centreline.s[scene.tubes[0].centreline.size() - 1]);
  for (const auto& panel : layout.panels) {
    const Eigen::Vector2d px = panel.camera.Project(peak);
    EXPECT_LT(ClosestNear(image, px, 2, Viridis(1.0)), kColourTolerance)
        << panel.camera.title << " at " << px.transpose();
    // ... and the far end of the cable, where the deviation is ~0, the bottom colour.
    const Eigen::Vector2d low = panel.camera.Project(cable.Point(0.08));
    EXPECT_LT(ClosestNear(image, low, 2, Viridis(0.0)), kColourTolerance) << panel.camera.title;
  }
}

TEST(DeviationViews, ChoosesTheViewsThatShowTheShape) {
  // The cable spans X and sags in Z; its Y extent is small: front (X-Z) and top (X-Y) show
  // most, the side view (along the cable) least.
  const Scene scene = testing::SaggingCable{}.Build();
  const ViewLayout layout = PlanDeviationViews(scene, RenderOptions{});
  EXPECT_EQ(layout.panels[0].camera.title, "isometric");
  EXPECT_EQ(layout.panels[1].camera.title.substr(0, 5), "front");
  EXPECT_EQ(layout.panels[2].camera.title.substr(0, 3), "top");
  // Auto-framing: every tube point lands inside its panel.
  for (const auto& panel : layout.panels)
    for (Eigen::Index i = 0; i < scene.tubes[0].centreline.size(); ++i) {
      const Eigen::Vector2d p = panel.camera.Project(scene.tubes[0].centreline.points.col(i));
      EXPECT_GT(p.x(), panel.camera.x);
      EXPECT_LT(p.x(), panel.camera.x + panel.camera.width);
      EXPECT_GT(p.y(), panel.camera.y);
      EXPECT_LT(p.y(), panel.camera.y + panel.camera.height);
    }
}

TEST(DeviationViews, AForcedRangeRecoloursTheTube) {
  const testing::SaggingCable cable;
  const Scene scene = cable.Build();
  RenderOptions options;
  options.colour_scale = ColourScale{0.0, 2.0 * cable.peak_mm, "deviation [mm]"};
  const ViewLayout layout = PlanDeviationViews(scene, options);
  const Image image = RenderDeviationViews(scene, options);
  // The peak is now mid-scale: the top colour must not appear on the tube.
  EXPECT_GT(ClosestInPanels(image, layout, Viridis(1.0)), 60.0);
  const Eigen::Vector3d peak = cable.Point(cable.peak_s / scene.tubes[0].centreline.s[scene.tubes[0].centreline.size() - 1]);
  EXPECT_LT(ClosestNear(image, layout.panels[1].camera.Project(peak), 2, Viridis(0.5)), kColourTolerance);
}

TEST(DeviationViews, SideBySideSharesOneColourScale) {
  testing::SaggingCable small;
  small.peak_mm = 5.0;
  testing::SaggingCable large;
  Scene baseline = small.Build();
  baseline.title = "baseline";
  Scene fitted = large.Build();
  fitted.title = "fitted";
  const RenderOptions options;
  const ViewLayout layout = PlanSideBySide(baseline, fitted, options);
  ASSERT_EQ(layout.panels.size(), 6u);
  EXPECT_NEAR(layout.colour_scale.max, large.peak_mm, 0.05);
  const Image image = RenderSideBySide(baseline, fitted, options);
  WritePng((cablefit::testing::FreshTempDir("render") / "side_by_side.png").string(), image);
  // Same framing in both rows; the baseline's 5 mm peak is a third of the way up the scale.
  for (int col = 0; col < 3; ++col) {
    const ViewCamera& a = layout.panels[static_cast<std::size_t>(col)].camera;
    const ViewCamera& b = layout.panels[static_cast<std::size_t>(col + 3)].camera;
    EXPECT_EQ(a.title, b.title);
    EXPECT_DOUBLE_EQ(a.pixels_per_metre, b.pixels_per_metre);
  }
  const double u = large.peak_s / large.Build().tubes[0].centreline.s.tail(1)[0];
  const ViewCamera& top_front = layout.panels[1].camera;
  const ViewCamera& bottom_front = layout.panels[4].camera;
  EXPECT_LT(ClosestNear(image, bottom_front.Project(large.Point(u)), 2, Viridis(1.0)), kColourTolerance);
  EXPECT_LT(ClosestNear(image, top_front.Project(small.Point(u)), 2, Viridis(5.0 / 15.0)), kColourTolerance);
  EXPECT_GT(ClosestNear(image, top_front.Project(small.Point(u)), 2, Viridis(1.0)), 60.0);
}

// The renderer's context is one per process: warmed up on another thread, it draws the same
// picture here as before the warm-up, to the byte.
TEST(DeviationViews, AWarmUpOnAnotherThreadLeavesThePictureUnchanged) {
  const Scene scene = testing::SaggingCable{}.Build();
  RenderOptions options;
  options.width = 900;
  options.height = 600;
  const Image before = RenderDeviationViews(scene, options);
  std::thread([&] { WarmUpRenderer(options); }).join();
  const Image after = RenderDeviationViews(scene, options);
  ASSERT_EQ(before.width, after.width);
  ASSERT_EQ(before.height, after.height);
  EXPECT_TRUE(before.pixels == after.pixels);
  // And a picture drawn on yet another thread, after the warm-up.
  Image elsewhere;
  std::thread([&] { elsewhere = RenderDeviationViews(scene, options); }).join();
  EXPECT_TRUE(before.pixels == elsewhere.pixels);
}

TEST(DeviationViews, RejectsBadInput) {
  Scene scene = testing::SaggingCable{}.Build();
  RenderOptions options;
  options.width = 10;
  EXPECT_THROW_WITH(RenderDeviationViews(scene, options), UsageError, "width");
  scene.tubes[0].deviation.resize(3);
  EXPECT_THROW_WITH(RenderDeviationViews(scene, RenderOptions{}), InvalidInput, "3 deviations");
  scene = testing::SaggingCable{}.Build();
  scene.tubes[0].radius = 0.0;
  EXPECT_THROW_WITH(RenderDeviationViews(scene, RenderOptions{}), InvalidInput, "radius");
}

TEST(DeviationViews, ALabelMarksItsPointWithACrossAndItsTextBeside) {
  const testing::SaggingCable cable;
  Scene scene = cable.Build();
  const RenderOptions options;
  const ViewLayout layout = PlanDeviationViews(scene, options);
  const Image plain = RenderDeviationViews(scene, options);
  // 30 mm beside the cable, so the tube does not hide it in any view.
  scene.labels.push_back({cable.Point(0.5) + Eigen::Vector3d(0, 0.03, 0.03), "cable_7: 12.5 mm"});
  const Image labelled = RenderDeviationViews(scene, options);
  WritePng((cablefit::testing::FreshTempDir("render") / "label.png").string(), labelled);
  for (const auto& panel : layout.panels) {
    const Eigen::Vector2d at = panel.camera.Project(scene.labels[0].position);
    // The cross's arms, 4 px from the point along a diagonal, in ink.
    EXPECT_LT(ClosestNear(labelled, at + Eigen::Vector2d(3, 3), 1, Rgb{30, 30, 30}), 80.0)
        << panel.camera.title;
    // The text to its lower right changes the pixels there.
    int changed = 0;
    for (int y = static_cast<int>(at.y()) + 6; y < at.y() + 22; ++y)
      for (int x = static_cast<int>(at.x()) + 8; x < at.x() + 90; ++x)
        if (labelled.Contains(x, y) && ColourDistance(labelled.At(x, y), plain.At(x, y)) > 60) ++changed;
    EXPECT_GT(changed, 30) << panel.camera.title;
  }
}

TEST(DeviationViews, APartIsDrawnTranslucentWithoutHidingTheCable) {
  const testing::SaggingCable cable;
  Scene scene = cable.Build();
  const RenderOptions options;
  const ViewLayout layout = PlanDeviationViews(scene, options);
  const Image plain = RenderDeviationViews(scene, options);
  // A block around the middle of the cable, 60 mm on a side.
  const Eigen::Vector3d c = cable.Point(0.5);
  TriangleMesh box;
  box.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i)
    box.vertices.col(i) = c + 0.03 * Eigen::Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  box.faces.resize(3, 12);
  box.faces << 0, 1, 4, 5, 0, 1, 2, 3, 0, 2, 1, 3,  //
      2, 3, 5, 7, 1, 5, 6, 7, 4, 6, 5, 7,           //
      3, 2, 6, 6, 4, 4, 7, 6, 2, 4, 7, 7;
  scene.solids.push_back({"block", box});
  const Image with = RenderDeviationViews(scene, options);
  ASSERT_EQ(PlanDeviationViews(scene, options).panels.size(), layout.panels.size());
  for (const auto& panel : layout.panels) {
    const Eigen::Vector2d on = panel.camera.Project(c);
    // The cable itself keeps its colour (the part is drawn behind it, translucent).
    EXPECT_LT(ColourDistance(with.At(static_cast<int>(on.x()), static_cast<int>(on.y())),
                             plain.At(static_cast<int>(on.x()), static_cast<int>(on.y()))),
              kColourTolerance)
        << panel.camera.title;
  }
  // Somewhere in the panels the block made white pixels grey.
  int greyed = 0;
  for (int yy = 0; yy < with.height; ++yy)
    for (int xx = 0; xx < with.width; ++xx)
      if (InAnyPanel(layout, xx, yy) && ColourDistance(plain.At(xx, yy), Rgb{255, 255, 255}) < 5 &&
          ColourDistance(with.At(xx, yy), Rgb{255, 255, 255}) > 25)
        ++greyed;
  EXPECT_GT(greyed, 1000);
}

}  // namespace
}  // namespace cablefit

namespace cablefit {
namespace {

TEST(DeviationViews, DrawsScanPointsPinsAndTheHighlightedSupport) {
  const testing::SaggingCable cable;
  Scene scene = cable.Build();
  scene.supports.push_back({SupportMarkerKind::kPin, cable.Point(0.75), "P"});
  scene.highlighted_support = 3;
  // A scan of the recorded shape, thinned by the caller: points 40 mm beside the cable so they
  // are not hidden by the tube in any view.
  const int m = 200;
  scene.scan_points.resize(3, m);
  for (int i = 0; i < m; ++i) scene.scan_points.col(i) = cable.Point(i / (m - 1.0)) + Eigen::Vector3d(0, 0.04, 0.04);
  const RenderOptions options;
  const ViewLayout layout = PlanDeviationViews(scene, options);
  const Image image = RenderDeviationViews(scene, options);
  WritePng((cablefit::testing::FreshTempDir("render") / "scan_and_supports.png").string(), image);
  for (const auto& panel : layout.panels) {
    const Eigen::Vector2d scan = panel.camera.Project(scene.scan_points.col(m / 3));
    EXPECT_LT(ClosestNear(image, scan, 1, Rgb{70, 70, 70}), 60.0) << panel.camera.title;
    // The red ring around the highlighted pin, 15 px from its centre.
    const Eigen::Vector2d pin = panel.camera.Project(scene.supports[3].position);
    double best = 1e9;
    for (int k = 0; k < 16; ++k) {
      const double a = k * 3.14159265 / 8;
      best = std::min(best, ClosestNear(image, pin + 15.0 * Eigen::Vector2d(std::cos(a), std::sin(a)), 0, Rgb{214, 39, 40}));
    }
    EXPECT_LT(best, 40.0) << panel.camera.title;
  }
}

}  // namespace
}  // namespace cablefit
