// A tube drawn as several bodies end to end, joined into one.
#pragma once

#include <TopoDS_Shape.hxx>
#include <optional>
#include <vector>

#include "tube_recovery.h"

namespace cablefit::internal {

/// A body of a product and the tube it is, if it is one.
struct TubePiece {
  TopoDS_Shape shape;
  std::optional<RecoveredTube> tube;  // [OCCT unit]
  int style = 0;                      // the caller's index of the body's name and colour
};

/// A tube drawn as several bodies of one product, end to end, is one tube: cablefit's STEP
/// writers split stubs shorter than their diameter (a segment between two close nodes of a
/// harness network) into two halves as if they were closed loops, drawing tools split a sweep
/// where its path's edges meet. Pieces whose tubes have one outer and one inner radius (within
/// 1 %) and whose ends meet (within 5 % of the radius) where no third piece ends are joined in
/// chains: one shape (a compound of theirs), one route, the first piece's style. A chain that
/// closes is left as its pieces.
void JoinTubePieces(std::vector<TubePiece>* pieces);

}  // namespace cablefit::internal
