// KBL (VDA 4964 "Harness Description List", XML) harness files in, in neutral types: the
// segments as a HarnessDrawing (one cable per Segment, named by its id) and, per segment, what
// the file says about its physics (the wires routed through it, fixings, connectors at its end
// nodes). The addin layer turns the latter into relax settings. Lengths in metres, masses in
// kilograms, whatever units the file declares. Format and mapping: docs/kbl.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cablefit/formats/harness_drawing.h"

namespace cablefit {

/// One wire (or multi-core cable) routed through a segment, with its part's data.
struct KblWire {
  std::string id;                          ///< the wire occurrence's XML id
  std::string part;                        ///< the General_wire's XML id
  std::optional<double> outside_diameter;  ///< [m]
  std::optional<double> conductor_area;    ///< [m^2] Cross_section_area of the part
  std::optional<double> linear_density;    ///< [kg/m] from Mass_information per length
  std::optional<double> min_bend_radius;   ///< [m] Bend_radius of the part
};

/// A Fixing_assignment: a clip (or other fixing) on the segment.
struct KblFixing {
  std::string id;         ///< the Fixing_occurrence's XML id
  std::string name;       ///< its <Id>
  std::string type;       ///< the Fixing part's Fixing_type ("" when not given)
  double location = 0.0;  ///< 0..1 along the segment from its start node
};

/// A Protection_area (tape, tube) over part of a segment.
struct KblProtection {
  std::string id;                 ///< the Wire_protection_occurrence's XML id
  std::string type;               ///< the part's Protection_type ("" when not given)
  double start = 0.0, end = 1.0;  ///< 0..1 along the segment
  /// [kg/m] the part's Mass_information when it is per length (unset for a plain mass).
  std::optional<double> linear_density;
};

/// One end of a segment: the node and what sits there.
struct KblSegmentEnd {
  std::string node;       ///< the Node's XML id
  std::string node_name;  ///< its <Id>
  /// The node's Referenced_components that are connectors or terminals (their <Id> or XML id);
  /// empty when nothing is placed there.
  std::vector<std::string> connectors;
  int segments_at_node = 0;  ///< segments that start or end at this node (this one included)
};

/// What the file says about one segment; same order as the drawing's cables.
struct KblSegment {
  std::string id;    ///< XML id (the drawing's cable name)
  std::string name;  ///< its <Id> (a CAD path, often long)
  KblSegmentEnd start, end;
  std::optional<double> virtual_length;      ///< [m]
  std::optional<double> cross_section_area;  ///< [m^2] of Cross_section_area_information
  double drawn_length = 0.0;                 ///< [m] of the evaluated centre curve(s)
  /// How far an end of the file's curve was from its node when it had to be drawn onto it
  /// [m]; 0 when the curve reaches its nodes (or runs on past one and is cut there).
  double node_miss = 0.0;
  /// An end of the centre curve was drawn onto its node (the file's curve does not reach it):
  /// drawn_length is then no longer the file's, and Virtual_length is the segment's length.
  bool end_drawn_to_node = false;
  std::vector<KblWire> wires;  ///< routed through this segment, each occurrence once
  std::vector<KblFixing> fixings;
  std::vector<KblProtection> protections;
};

struct KblHarness {
  std::string version;     ///< the container's version_id, e.g. "2.3 SR-1"
  HarnessDrawing drawing;  ///< cables = segments (name = XML id, diameter 0), junctions by node
  std::vector<KblSegment> segments;
  /// Findings that do not stop the reading, one line each naming the element id.
  std::vector<std::string> notes;
};

/// Options of ReadKblFile.
struct KblReadOptions {
  /// A curve end farther than this from its node (the node's own point, or where the other
  /// segments' curves meet) misses it and is cut or drawn onto it, with a note [m]. Curves of
  /// the samples land within 1e-5 m; a design tool's tolerance is about 1 mm.
  double node_tolerance = 1e-3;
  /// Curve samples per knot span: the samples' degree-6 curves are one span each, and 256
  /// chords measure the gearbox's 625.09 mm within 5 um (24 chords: 0.5 mm short).
  int samples_per_span = 256;
};

/// Reads a KBL 2.x file. Throws FileError naming the file and the element id for: not XML, a
/// root other than KBL_container in a KBL 2.x namespace, a missing or unknown unit, a dangling
/// id reference, a segment without centre curve. Curves that miss their nodes are made to
/// reach them (see PlaceNodes in kbl_reader.cc, docs/kbl.md), each with a note.
KblHarness ReadKblFile(const std::string& path, const KblReadOptions& options = {});

/// Maximum size of a KBL file [bytes]: real harnesses are a few MB.
inline constexpr unsigned long long kMaxKblInputBytes = 256ull << 20;

}  // namespace cablefit
