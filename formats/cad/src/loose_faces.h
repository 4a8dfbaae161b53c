// Faces that bound no shell (IGES surface models, where each body is a set of trimmed surfaces)
// made into the bodies they were drawn as.
#pragma once

#include <TopoDS_Shape.hxx>
#include <vector>

namespace cablefit::internal {

/// Loose faces the file keeps together (an IGES group, entity 402, read as a compound of its
/// faces; a face on its own), with the style of the label they came from (an index the caller
/// keeps).
struct LooseFaceGroup {
  std::vector<TopoDS_Shape> faces;
  int style = 0;
};

/// Appends the groups of loose faces (faces in no shell) of `shape`.
void CollectLooseFaces(const TopoDS_Shape& shape, int style, std::vector<LooseFaceGroup>* groups);

/// A body drawn as loose faces.
struct LooseBody {
  TopoDS_Shape shape;  // a shell, a face, or a compound of a tube's faces
  int style = 0;
};

/// The bodies the loose faces of a file draw. Each group is sewn into shells (tolerance 0.01 mm:
/// the precision CAD exporters write surfaces to, far below the size of any cable, so only edges
/// drawn as one are joined). A shell made only of tube walls and their end caps is no body as
/// sewn: files write the walls of a tube as loose faces in any grouping (its halves, its pieces
/// along, its bore, each a group or a root entity of its own, or every face of a multi-core
/// cable in one group, where a conductor's surface and its insulation's bore coincide and sew
/// into one). Those walls are regrouped by geometry: walls of one radius that repeat one another
/// (halves) or continue one another where no third wall ends, walls of two radii over the same
/// stretch (a bore), and the planar caps centred on their ends are one tube's faces, whatever
/// group or label they came from; the body takes the style of its largest wall.
std::vector<LooseBody> LooseFaceBodies(const std::vector<LooseFaceGroup>& groups);

}  // namespace cablefit::internal
