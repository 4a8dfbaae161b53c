// Recovering a swept tube's centreline and diameter from its B-rep faces.
#pragma once

#include <TopoDS_Shape.hxx>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace cablefit {

struct RecoveredTube {
  Eigen::Matrix3Xd centres;  // 3 x n [OCCT unit], ordered along the tube
  double radius = 0.0;       // [OCCT unit] outer radius
  double inner_radius = 0.0; // [OCCT unit] bore of a hollow tube, 0 for a solid one
  double rms_residual = 0.0; // RMS circle-fit residual [OCCT unit]
};

struct TubeRecoveryOptions {
  double sample_spacing = 2.0;       // [OCCT unit] between cross-sections
  double min_area_fraction = 0.8;    // lateral area / total area
  double min_aspect = 2.0;           // length / diameter
};

/// A tube is a solid or shell whose lateral faces have circular cross-sections of one radius
/// along one surface parameter (a circle swept along a curve: cylinders, tori, extrusions,
/// revolutions, B-spline pipes), or of two radii along one centreline (a hollow tube).
/// Each lateral face is sampled across (circle fit: centre, radius) at stations along; the
/// stations of all faces are chained end to end into one open route. Returns nullopt when the
/// shape is not a single open tube (a box, a ring, a branched or closed shape) or is shorter
/// than `min_aspect` outer diameters.
std::optional<RecoveredTube> RecoverTube(const TopoDS_Shape& shape,
                                         const TubeRecoveryOptions& options);

}  // namespace cablefit
