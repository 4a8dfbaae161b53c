// Recovering a swept tube's centreline and diameter from its B-rep faces.
#pragma once

#include <Eigen/Core>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <optional>
#include <vector>

namespace cablefit {

struct RecoveredTube {
  Eigen::Matrix3Xd centres;  // 3 x n [OCCT unit], ordered along the tube
  double radius = 0.0;       // [OCCT unit] outer radius
  double inner_radius = 0.0; // [OCCT unit] bore of a hollow tube, 0 for a solid one
  double rms_residual = 0.0;  // RMS distance of the sections from circles of `radius` [OCCT unit]
  // The smallest and largest of the outer wall's section circles [OCCT unit]: apart by more than
  // a few thousandths of the radius only on a loosely approximated sweep.
  double min_section_radius = 0.0, max_section_radius = 0.0;
};

struct TubeRecoveryOptions {
  double sample_spacing = 2.0;       // [OCCT unit] between cross-sections
  double min_area_fraction = 0.8;    // lateral area / total area (end caps always allowed)
  double min_aspect = 2.0;           // length / diameter
};

/// A tube is a solid or shell whose lateral faces have circular cross-sections of one radius
/// along one surface parameter (a circle swept along a curve: cylinders, tori, extrusions,
/// revolutions, B-spline pipes), or of two radii along one centreline (a hollow tube). A surface
/// that is not analytic may be an approximation of a swept circle: half of it must be sections
/// near one radius, nearly all of it roughly round (tube_recovery.cc, Roundness). Each lateral
/// face is sampled across (circle fit: centre, radius) at stations along; the stations of all
/// faces are chained end to end into one open route (a bore drawn twice, by two faces that each
/// go all round, is filled: the surfaces of a conductor and of its insulation's bore). Returns
/// nullopt when the shape is not a single open tube (a box, a ring, a branched or closed shape)
/// or is shorter than `min_aspect` outer diameters.
std::optional<RecoveredTube> RecoverTube(const TopoDS_Shape& shape,
                                         const TubeRecoveryOptions& options);

/// The ends of a face as RecoverTube takes a tube's wall: the centres of its first and last
/// cross-sections [OCCT unit] and their radius; nullopt for a face that is no tube's wall.
struct TubeFaceEnds {
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  double radius = 0.0;
};
std::optional<TubeFaceEnds> LateralFaceEnds(const TopoDS_Face& face);

}  // namespace cablefit
