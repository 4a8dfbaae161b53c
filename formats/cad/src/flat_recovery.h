// Recovering a flat (ribbon) cable from a solid: a rectangle or a stadium (a rectangle with
// half-round edges) swept along a route, as flat house wiring, FFC and ribbon cables are drawn.
#pragma once

#include <TopoDS_Shape.hxx>
#include <optional>

#include <Eigen/Core>

namespace cablefit {

struct RecoveredFlat {
  Eigen::Matrix3Xd centres;    // 3 x n [OCCT unit], from one end face to the other
  Eigen::Matrix3Xd wide_axes;  // 3 x n unit, the section's wide axis at each centre
  double width = 0.0;          // [OCCT unit] median over the stations
  double thickness = 0.0;      // [OCCT unit] median over the stations
  bool rounded_edges = false;  // stadium rather than rectangle (end face fills < 95 % of w x t)
};

struct FlatRecoveryOptions {
  double sample_spacing = 2.0;  // [OCCT unit] between cross-sections
  /// width / thickness at least this: below it the section is nearly round, and a round
  /// cable's bending is isotropic enough that the tube reader's circle is the better model.
  double min_width_ratio = 1.5;
};

/// A flat strip is a solid or shell with two planar end faces of the same rectangular or
/// stadium outline (the two smallest planar faces, together under a fifth of the area), such
/// that plane cuts marched from one end face along the strip, each perpendicular to the last
/// step, find the same outline all the way to the other end face. Each cut gives a centre (the
/// middle of the outline's extent along its principal axes) and the wide axis (the outline's
/// principal axis of largest spread), so axes that turn with the drawn cable are followed.
/// Returns nullopt for anything else. Holes inside the outline (cores drawn as bores of the
/// jacket) do not change the extent and so are allowed.
std::optional<RecoveredFlat> RecoverFlatStrip(const TopoDS_Shape& shape,
                                              const FlatRecoveryOptions& options);

}  // namespace cablefit
