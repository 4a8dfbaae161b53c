// A flat (ribbon) cable's solid in OCCT: its rectangle or stadium swept along the centreline,
// the section's wide axis turning as a guide curve beside the spine says.
#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

namespace cablefit {

/// The section of a flat strip [OCCT unit].
struct FlatProfile {
  double width = 0.0;          ///< along the wide axis
  double thickness = 0.0;      ///< across it
  bool rounded_edges = false;  ///< a stadium (half-round edges), else a rectangle
};

/// A solid flat strip swept along `spine`: at every point P of the spine the section lies in
/// the plane square to the spine's tangent, its wide axis pointing from P to where that plane
/// meets `guide` (a curve beside the spine, e.g. the spine offset by half the width along the
/// wide axis; BRepOffsetAPI_MakePipeShell with an auxiliary spine, no curvilinear equivalence),
/// capped by planar end faces. Throws InvalidInput when the profile is not flat (width less than
/// thickness), the guide starts on the spine or no valid solid results.
TopoDS_Shape MakeFlatStripSolid(const TopoDS_Wire& spine, const TopoDS_Wire& guide,
                                const FlatProfile& profile);

}  // namespace cablefit
