// Draws the 3-D content of deviation-map panels (tubes, halos, ghosts, scan points) with GL.
#pragma once

#include <vector>

#include "cablefit/formats/deviation_views.h"
#include "cablefit/formats/scene.h"

namespace cablefit::render {

struct GlPanelJob {
  const Scene* scene = nullptr;
  ViewCamera camera;  // in final-picture pixels
};

/// Renders every job's panel at `supersample` times its size, averaged down into a picture of
/// width x height pixels, background `background` everywhere else. `scales[k]` colours scene k's tubes; jobs refer to
/// scenes by pointer, `scenes` lists the distinct ones in the order of `scales`.
Image RenderPanels3d(int width, int height, int supersample, Rgb background,
                     const std::vector<const Scene*>& scenes, const std::vector<ColourScale>& scales,
                     const std::vector<GlPanelJob>& jobs, const RenderOptions& options);

}  // namespace cablefit::render
