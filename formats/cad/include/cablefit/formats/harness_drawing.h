// A harness as drawn in CAD, in neutral types: the cables' routes and the other solids around
// them (clips, brackets, housings). Produced by ReadCadFile(), consumed by the relax stage and by
// WriteRelaxedStep(). All lengths in metres, whatever unit the file used.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"

namespace cablefit {

/// Where a cable's centreline came from.
enum class CableSourceKind {
  kCurve,  ///< an edge or wire (B-spline, polyline, lines and arcs chained into one route)
  kTube,   ///< a tube solid or shell (a circle swept along the route), centreline recovered
  kMesh,   ///< a tessellated tube, centreline recovered by a skeleton
};
const char* ToString(CableSourceKind kind);

/// An sRGB colour, components in [0, 1] (the values a CAD user sees, not linear RGB).
struct SrgbColor {
  double r = 0.5, g = 0.5, b = 0.5;
};

/// The CAD shape behind a drawn item, kept so a writer can copy it unchanged. Opaque: its
/// definition lives in the CAD adapter, no CAD type leaks into this header.
struct CadShapeHandle;

/// The section of a flat (ribbon) cable: a rectangle or a stadium swept along the route, its wide
/// axis turning with the cable as drawn.
struct FlatSection {
  double width = 0.0;          ///< [m] along the wide axis
  double thickness = 0.0;      ///< [m] across it
  bool rounded_edges = false;  ///< a stadium (half-round edges), else a rectangle
  Eigen::Matrix3Xd wide_axes;  ///< 3 x n unit, at each centreline point, square to the tangent
};

/// One cable route.
struct DrawnCable {
  std::string name;              ///< the product/label name; "<name>#k" when one shape held k routes
  bool has_color = false;
  SrgbColor color;
  Polyline centreline;           ///< s from 0 [m], points 3 x n [m]
  double diameter = 0.0;         ///< [m] outer diameter; 0 when unknown (a bare curve)
  double inner_diameter = 0.0;   ///< [m] bore of a hollow tube (hose, conduit); 0 when solid
  /// A flat cable's section (then `diameter` is its width, the envelope clearance and clips
  /// see); absent for a round one.
  std::optional<FlatSection> flat;
  CableSourceKind source = CableSourceKind::kCurve;
  /// How far the recovered centreline may be from the true one [m]: for a curve, the largest
  /// chord deviation of the sampling; for a tube, the RMS residual of the cross-section circle
  /// fits (or of the surface distance to the tube for a mesh).
  double fit_error = 0.0;
  /// The tube solid it was recovered from, when read from CAD (null for curves and meshes).
  std::shared_ptr<const CadShapeHandle> shape;
  /// Unit direction (along increasing s) at s = 0 and at s = length where the drawing fixes it
  /// more exactly than the route's points do (a mesh tube's flat end cap: its normal). The clamp
  /// at that end holds it. Unset elsewhere.
  std::optional<Vec3> start_direction, end_direction;
};

/// A non-cable solid (clip, bracket): its shape is copied unchanged by the writer.
struct DrawnSolid {
  std::string name;
  bool has_color = false;
  SrgbColor color;
  TriangleMesh mesh;  ///< tessellation [m], for support and contact detection
  std::shared_ptr<const CadShapeHandle> shape;  ///< null when not read from CAD
};

/// Cable ends that coincide: a branch point of a bundle (three or more ends) or a splice.
struct CableJunction {
  Vec3 position = Vec3::Zero();  // [m]
  struct End {
    int cable = 0;        ///< index into HarnessDrawing::cables
    bool at_start = true; ///< the end at s = 0 (else at s = length)
  };
  std::vector<End> ends;
  /// The file joins these ends (a KBL node: the bundle runs on through it), so two ends are a
  /// splice too; ends found only because they touch need three to be a breakout.
  bool joined = false;
  std::string name;  ///< what the file calls the place ("Node_7"); empty when found by touch
};

struct HarnessDrawing {
  std::string source_path;
  std::string length_unit = "m";  ///< the unit the file declared ("mm", "m", "inch", ...)
  std::vector<DrawnCable> cables;
  std::vector<DrawnSolid> solids;
  std::vector<CableJunction> junctions;
  /// What was read but not taken as a cable, one line each with the reason ("'Profile': a
  /// closed planar curve (a sketch profile), not a cable route").
  std::vector<std::string> skipped;
  /// Doubts about the input as a whole, one line each ("the tubes are 0.04 mm across ...: if the
  /// file is in metres, use --unit m").
  std::vector<std::string> warnings;
};

/// Gives every cable a distinct name: an unnamed cable becomes "cable-<k>", a name used by
/// several cables gets "#<k>" appended, k counting in the geometric order of the cables (by the
/// lexicographically smaller of their end points, then the other end, coordinates rounded to
/// 1 um), so names do not depend on the order of the file. Unnamed solids become "solid-<k>".
void NameCablesUniquely(HarnessDrawing* drawing);

/// Finds cable ends closer than `tolerance` [m] to each other and records them as junctions
/// (only groups of two or more ends). Replaces `drawing->junctions`.
void FindJunctions(HarnessDrawing* drawing, double tolerance);

/// A solid part that is a short tube (a mesh component too short to be a cable of its own).
struct TubeSolid {
  int solid = 0;              ///< index into HarnessDrawing::solids
  Eigen::Matrix3Xd centres;   ///< 3 x n [m], its route
  double radius = 0.0;        ///< [m]
  int skipped_note = -1;      ///< the HarnessDrawing::skipped line that says why it is a part
};

/// Stripped core ends of multi-core cables in a drawing that did not come from ReadCadFile (a
/// mesh): a cable or tube part thinner than a cable's cores can be, rooted in that cable's end
/// section and running out of it, shorter than `min_aspect` of its diameters, is part of that
/// cable. It leaves the drawing with one `skipped` line naming the cable. A tube whose root meets
/// the ends of two other cables (within `junction_tolerance` [m]) is a breakout branch and stays.
void AbsorbCoreTails(const std::vector<TubeSolid>& tube_solids, double min_aspect,
                     double junction_tolerance, HarnessDrawing* drawing);

/// A relaxed cable to be written: a new centreline for input cable `source_cable`.
struct RelaxedCable {
  int source_cable = 0;  ///< index into the input HarnessDrawing::cables (name, colour, diameter)
  Polyline centreline;   ///< points 3 x n [m], n >= 2
  /// Tube diameter [m] for the output; 0 = the drawn diameter of the source cable.
  double diameter = 0.0;
  /// A flat cable's section, written as that strip instead of a round tube: its `wide_axes`
  /// (3 x n unit, one per centreline point, square to the tangent) turn the section along the
  /// relaxed centreline (the rod's material d1, which the clamps hold at the drawn wide axis).
  std::optional<FlatSection> flat = std::nullopt;
};

}  // namespace cablefit
