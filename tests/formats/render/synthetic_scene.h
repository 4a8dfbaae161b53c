// A known case for the renderer tests and benchmark: a cable sagging between two clamps, with a
// deviation that peaks at a known arc length.
#pragma once

#include <cmath>
#include <numbers>

#include "cablefit/formats/scene.h"

namespace cablefit::testing {

struct SaggingCable {
  double length = 0.6;     // [m] span
  double sag = 0.08;       // [m] mid-span drop
  double peak_s = 0.4;     // [m] arc length of the worst deviation (chord parameter)
  double peak_mm = 15.0;   // [mm] worst deviation
  double width = 0.05;     // [m] Gaussian width of the deviation bump
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // 3 [m] shifts the whole cable

  /// Centre-line point at chord parameter u in [0, 1] (3 [m]).
  Eigen::Vector3d Point(double u) const {
    return offset + Eigen::Vector3d(length * u, 0.02 * std::sin(2 * std::numbers::pi * u),
                                    -sag * std::sin(std::numbers::pi * u));
  }
  double DeviationM(double s) const {
    return peak_mm * 1e-3 * std::exp(-std::pow((s - peak_s) / width, 2));
  }

  /// The tube, a ghost displaced by the deviation (the "recorded" shape), two clamps, a clip.
  Scene Build(int n = 241) const {
    Scene scene;
    SceneTube tube;
    tube.name = "cable";
    tube.radius = 0.005;
    tube.centreline.points.resize(3, n);
    for (int i = 0; i < n; ++i) tube.centreline.points.col(i) = Point(i / (n - 1.0));
    tube.centreline.ParameteriseByChords();
    tube.deviation.resize(n);
    for (int i = 0; i < n; ++i) tube.deviation[i] = DeviationM(tube.centreline.s[i]);
    SceneGhost ghost;
    ghost.name = "recorded shape";
    ghost.points = tube.centreline.points;
    for (int i = 0; i < n; ++i) ghost.points(2, i) += tube.deviation[i];
    scene.supports = {{SupportMarkerKind::kClamp, Point(0.0), "1"},
                      {SupportMarkerKind::kClip, Point(0.25), "2"},
                      {SupportMarkerKind::kClamp, Point(1.0), "3"}};
    scene.tubes.push_back(std::move(tube));
    scene.ghosts.push_back(std::move(ghost));
    return scene;
  }
};

}  // namespace cablefit::testing
