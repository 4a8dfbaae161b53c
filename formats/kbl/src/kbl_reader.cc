// Reading a KBL container: segments -> drawn cables, nodes -> junctions, routings -> the wires
// of each segment, fixing assignments and protection areas. See docs/kbl.md for the mapping.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <set>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/input_file.h"
#include "cablefit/formats/kbl_center_curve.h"
#include "cablefit/formats/kbl_file.h"
#include "kbl_units.h"
#include "kbl_xml.h"

namespace cablefit {
namespace {

using kbl::Attribute;
using kbl::Child;
using kbl::Children;
using kbl::ChildText;
using kbl::Name;
using kbl::Quantity;
using kbl::Text;
using kbl::Tokens;
using IdIndex = std::unordered_map<std::string, const xmlNode*>;

// KBL 2.x, as its schemas name the namespace ("KBL2.3", "KBL2.4", ...).
constexpr const char* kNamespacePrefix = "http://www.prostep.org/Car_electric_container/KBL2.";
constexpr const char* kNamespaceSuffix = "/KBLSchema";
// KBL's Cartesian_point carries no unit: the format fixes coordinates in millimetres. Each
// segment's drawn length is cross-checked against its Virtual_length, which does carry a unit.
constexpr double kCoordinateUnit = 1e-3;  // [m]
// A curve no longer than this between its nodes (cut at both, or drawn onto nodes that
// coincide) has nothing left to relax [m].
constexpr double kNoLength = 1e-6;

const xmlNode* Resolve(const IdIndex& ids, const std::string& ref, const std::string& from,
                       const char* expected = nullptr) {
  const auto it = ids.find(ref);
  if (it == ids.end()) throw InvalidInput(from + ": reference '" + ref + "' names no element");
  if (expected && Name(it->second) != expected) {
    throw InvalidInput(from + ": reference '" + ref + "' is a " + Name(it->second) +
                       ", expected a " + expected);
  }
  return it->second;
}

void CheckContainer(const xmlNode* root, std::string* version) {
  if (!root || Name(root) != "KBL_container") {
    throw InvalidInput("root element is <" + Name(root) + ">, not a KBL_container");
  }
  const std::string ns =
      root->ns && root->ns->href ? reinterpret_cast<const char*>(root->ns->href) : "";
  const std::string prefix = kNamespacePrefix, suffix = kNamespaceSuffix;
  const bool ok = ns.size() > prefix.size() + suffix.size() && ns.rfind(prefix, 0) == 0 &&
                  ns.compare(ns.size() - suffix.size(), suffix.size(), suffix) == 0;
  if (!ok) {
    throw InvalidInput("KBL_container in namespace '" + ns + "': only KBL 2.x (" + prefix +
                       "<minor>" + suffix + ") is read");
  }
  *version = Attribute(root, "version_id");
}

Vec3 PointOf(const xmlNode* cp) {
  const std::vector<const xmlNode*> c = Children(cp, "Coordinates");
  const std::string what = "Cartesian_point " + Attribute(cp, "id");
  if (c.size() != 3) {
    throw InvalidInput(what + ": " + std::to_string(c.size()) + " coordinates (expected 3)");
  }
  Vec3 p;
  for (int i = 0; i < 3; ++i)
    p[i] = kCoordinateUnit * kbl::ParseNumber(Text(c[static_cast<size_t>(i)]), what);
  return p;
}

// The chained centre curves of a segment, in metres, from the first curve's start.
Polyline SegmentCurve(const xmlNode* seg, const std::string& seg_id, const IdIndex& ids,
                      const KblReadOptions& options) {
  const std::vector<const xmlNode*> curves = Children(seg, "Center_curve");
  if (curves.empty()) throw InvalidInput("Segment " + seg_id + ": no Center_curve");
  std::vector<Polyline> pieces;
  for (const xmlNode* cc : curves) {
    const std::string what = "Center_curve " + Attribute(cc, "id") + " of Segment " + seg_id;
    const std::vector<std::string> refs = Tokens(ChildText(cc, "Control_points"));
    Eigen::Matrix3Xd control(3, static_cast<Eigen::Index>(refs.size()));
    for (size_t i = 0; i < refs.size(); ++i)
      control.col(static_cast<Eigen::Index>(i)) =
          PointOf(Resolve(ids, refs[i], what, "Cartesian_point"));
    const double degree = kbl::ParseNumber(ChildText(cc, "Degree"), what + ": Degree");
    if (degree != std::floor(degree) || degree < 1 || degree > 32) {
      throw InvalidInput(what + ": Degree " + ChildText(cc, "Degree") + " (expected 1 to 32)");
    }
    try {
      pieces.push_back(
          SampleUniformBSpline(control, static_cast<int>(degree), options.samples_per_span));
    } catch (const InvalidInput& e) {
      throw InvalidInput(what + ": " + e.what());
    }
  }
  // Several curves of one segment are pieces of one route: each next piece is joined at the end
  // nearest the route so far (the first piece turned round if the second meets its start).
  auto first = [](const Polyline& p) -> Vec3 { return p.points.col(0); };
  auto last = [](const Polyline& p) -> Vec3 { return p.points.col(p.size() - 1); };
  auto reversed = [](Polyline p) {
    p.points = p.points.rowwise().reverse().eval();
    return p;
  };
  Polyline route = pieces[0];
  for (size_t k = 1; k < pieces.size(); ++k) {
    Polyline next = pieces[k];
    if (k == 1) {
      const double d_ee =
          std::min((last(route) - first(next)).norm(), (last(route) - last(next)).norm());
      const double d_se =
          std::min((first(route) - first(next)).norm(), (first(route) - last(next)).norm());
      if (d_se < d_ee) route = reversed(route);
    }
    if ((last(route) - last(next)).norm() < (last(route) - first(next)).norm())
      next = reversed(next);
    const double gap = (last(route) - first(next)).norm();
    if (gap > options.node_tolerance) {
      throw InvalidInput("Segment " + seg_id + ": Center_curve " + Attribute(curves[k], "id") +
                         " is " + std::to_string(1e3 * gap) + " mm from the curve before it");
    }
    Eigen::Matrix3Xd joined(3, route.size() + next.size() - 1);
    joined << route.points, next.points.rightCols(next.size() - 1);
    route.points = joined;
  }
  route.ParameteriseByChords();
  return route;
}

// A centre curve that runs on past its node but passes through it (a segment split in the
// design tool whose curve kept the old extent: movo's Segment_6 covers Segment_18 too) is cut at
// the node. Returns false when the curve does not pass within `tolerance` of `node`.
bool TrimAtNode(Polyline* route, bool at_start, const Vec3& node, double tolerance) {
  const Eigen::Matrix3Xd& p = route->points;
  double best = std::numeric_limits<double>::infinity(), best_u = 0.0;
  Eigen::Index best_i = 0;
  for (Eigen::Index i = 0; i + 1 < p.cols(); ++i) {
    const Vec3 d = p.col(i + 1) - p.col(i);
    const double u = d.squaredNorm() > 0
                         ? std::clamp((node - p.col(i)).dot(d) / d.squaredNorm(), 0.0, 1.0)
                         : 0.0;
    const double dist = (p.col(i) + u * d - node).norm();
    if (dist < best) {
      best = dist;
      best_i = i;
      best_u = u;
    }
  }
  if (best > tolerance) return false;
  const Vec3 cut = p.col(best_i) + best_u * (p.col(best_i + 1) - p.col(best_i));
  Eigen::Matrix3Xd kept;
  if (at_start) {
    const Eigen::Index rest = p.cols() - best_i - 1;
    kept.resize(3, rest + 1);
    kept << cut, p.rightCols(rest);
  } else {
    kept.resize(3, best_i + 2);
    kept << p.leftCols(best_i + 1), cut;
  }
  if (kept.cols() < 2) return false;
  route->points = kept;
  route->ParameteriseByChords();
  return route->s[route->size() - 1] > tolerance;
}

// A wire or cable routed through segments: the occurrence and its General_wire part.
const xmlNode* WireOccurrence(const IdIndex& ids, const std::string& ref, const std::string& from) {
  const xmlNode* n = Resolve(ids, ref, from);
  // A Routing names a Connection (KBL 2.3) or the wire / core occurrence itself.
  if (Name(n) == "Connection") {
    const std::string wire = ChildText(n, "Wire");
    if (wire.empty()) throw InvalidInput(from + ": Connection " + ref + " has no Wire");
    n = Resolve(ids, wire, "Connection " + ref);
  }
  // A core of a multi-core cable runs inside its cable: the cable is what fills the segment.
  if (Name(n) == "Core_occurrence" && n->parent && n->parent->type == XML_ELEMENT_NODE)
    n = n->parent;
  const std::string name = Name(n);
  if (name != "General_wire_occurrence" && name != "Wire_occurrence" &&
      name != "Special_wire_occurrence") {
    throw InvalidInput(from + ": '" + ref + "' is a " + name + ", not a wire");
  }
  return n;
}

// A part's Mass_information when it is per length (wires, tapes, tubes); a plain mass (a part's
// weight) says nothing about the bundle's density and gives none. A broken unit is an error.
std::optional<double> LinearDensityOf(const xmlNode* part, const IdIndex& ids) {
  const xmlNode* v = Child(part, "Mass_information");
  if (!v) return std::nullopt;
  try {
    return kbl::SiValue(v, Quantity::kLinearDensity, ids);
  } catch (const InvalidInput&) {
    kbl::SiValue(v, Quantity::kMass, ids);
    return std::nullopt;
  }
}

KblWire ReadWire(const xmlNode* occ, const IdIndex& ids) {
  KblWire w;
  w.id = Attribute(occ, "id");
  const std::string from = Name(occ) + " " + w.id;
  w.part = ChildText(occ, "Part");
  const xmlNode* part = Resolve(ids, w.part, from, "General_wire");
  if (const xmlNode* v = Child(part, "Outside_diameter"))
    w.outside_diameter = kbl::SiValue(v, Quantity::kLength, ids);
  if (const xmlNode* v = Child(part, "Cross_section_area"))
    w.conductor_area = kbl::SiValue(v, Quantity::kArea, ids);
  if (const xmlNode* v = Child(part, "Bend_radius"))
    w.min_bend_radius = kbl::SiValue(v, Quantity::kLength, ids);
  if (const xmlNode* v = Child(part, "Min_bend_radius_static")) {
    w.min_bend_radius =
        std::max(w.min_bend_radius.value_or(0.0), kbl::SiValue(v, Quantity::kLength, ids));
  }
  w.linear_density = LinearDensityOf(part, ids);
  return w;
}

bool IsConnectorLike(const std::string& element) {
  return element == "Connector_occurrence" || element == "Special_terminal_occurrence" ||
         element == "Terminal_occurrence";
}

// A Node: its name, the connectors placed there, its own point if any, and (filled later) the
// segment ends at it.
struct NodeInfo {
  std::string name;
  std::vector<std::string> connectors;
  std::optional<Vec3> point;
  std::vector<CableJunction::End> ends;  // segment index (into KblHarness::segments), which end
};
using NodeMap = std::map<std::string, NodeInfo>;

NodeMap ReadNodes(const xmlNode* root, const IdIndex& ids) {
  NodeMap nodes;
  for (const xmlNode* n : Children(root, "Node")) {
    const std::string id = Attribute(n, "id");
    NodeInfo info;
    info.name = ChildText(n, "Id");
    for (const std::string& ref : Tokens(ChildText(n, "Referenced_components"))) {
      const xmlNode* c = Resolve(ids, ref, "Node " + id);
      if (IsConnectorLike(Name(c))) {
        const std::string cid = ChildText(c, "Id");
        info.connectors.push_back(cid.empty() ? ref : cid);
      }
    }
    const std::string cp = ChildText(n, "Cartesian_point");
    if (!cp.empty()) info.point = PointOf(Resolve(ids, cp, "Node " + id, "Cartesian_point"));
    nodes[id] = std::move(info);
  }

  return nodes;
}

// A Segment's own data (its curve is read by SegmentCurve).
KblSegment ReadSegment(const xmlNode* sn, const NodeMap& nodes, const IdIndex& ids) {
  KblSegment seg;
  seg.id = Attribute(sn, "id");
  if (seg.id.empty()) throw InvalidInput("a Segment without id");
  const std::string what = "Segment " + seg.id;
  seg.name = ChildText(sn, "Id");
  for (auto [end, tag] : {std::pair{&seg.start, "Start_node"}, std::pair{&seg.end, "End_node"}}) {
    end->node = ChildText(sn, tag);
    if (end->node.empty()) throw InvalidInput(what + ": no " + tag);
    Resolve(ids, end->node, what, "Node");
    if (const auto it = nodes.find(end->node); it != nodes.end()) {
      end->node_name = it->second.name;
      end->connectors = it->second.connectors;
    }
  }
  if (const xmlNode* v = Child(sn, "Virtual_length"))
    seg.virtual_length = kbl::SiValue(v, Quantity::kLength, ids);
  if (const xmlNode* info = Child(sn, "Cross_section_area_information")) {
    if (const xmlNode* a = Child(info, "Area"))
      seg.cross_section_area = kbl::SiValue(a, Quantity::kArea, ids);
  }
  for (const xmlNode* fa : Children(sn, "Fixing_assignment")) {
    KblFixing f;
    const std::string fwhat = "Fixing_assignment " + Attribute(fa, "id") + " of " + what;
    f.location = kbl::ParseNumber(ChildText(fa, "Location"), fwhat + ": Location");
    if (f.location < 0 || f.location > 1) throw InvalidInput(fwhat + ": Location outside 0..1");
    f.id = ChildText(fa, "Fixing");
    const xmlNode* occ = Resolve(ids, f.id, fwhat, "Fixing_occurrence");
    f.name = ChildText(occ, "Id");
    const std::string part = ChildText(occ, "Part");
    if (!part.empty())
      f.type = ChildText(Resolve(ids, part, "Fixing_occurrence " + f.id), "Fixing_type");
    seg.fixings.push_back(std::move(f));
  }
  for (const xmlNode* pa : Children(sn, "Protection_area")) {
    KblProtection p;
    const std::string pwhat = "Protection_area " + Attribute(pa, "id") + " of " + what;
    p.start = kbl::ParseNumber(ChildText(pa, "Start_location"), pwhat + ": Start_location");
    p.end = kbl::ParseNumber(ChildText(pa, "End_location"), pwhat + ": End_location");
    if (!(0 <= p.start && p.start <= 1 && 0 <= p.end && p.end <= 1)) {
      throw InvalidInput(pwhat + ": Start_location or End_location outside 0..1");
    }
    // Nothing in KBL orders them: an area given from its far end is the same interval.
    if (p.start > p.end) std::swap(p.start, p.end);
    p.id = ChildText(pa, "Associated_protection");
    const xmlNode* occ = Resolve(ids, p.id, pwhat);
    const std::string part_id = ChildText(occ, "Part");
    if (!part_id.empty()) {
      const xmlNode* part = Resolve(ids, part_id, Name(occ) + " " + p.id);
      p.type = ChildText(part, "Protection_type");
      p.linear_density = LinearDensityOf(part, ids);
    }
    seg.protections.push_back(std::move(p));
  }
  return seg;
}

// Each Routing puts its wire into the segments it lists.
void AddRoutings(const xmlNode* root, const IdIndex& ids,
                 const std::map<std::string, int>& seg_index, KblHarness* out) {
  KblHarness& h = *out;
  for (const xmlNode* r : Children(root, "Routing")) {
    const std::string what = "Routing " + Attribute(r, "id");
    const xmlNode* occ = WireOccurrence(ids, ChildText(r, "Routed_wire"), what);
    const KblWire wire = ReadWire(occ, ids);
    const std::vector<std::string> route = Tokens(ChildText(r, "Segments"));
    // A wire is one piece: its segments must form one connected path through their nodes. The
    // physics does not depend on it, so a gap is a note, not an error.
    std::set<std::string> reached;
    std::vector<bool> joined(route.size(), false);
    for (bool grew = true; grew && !route.empty();) {
      grew = false;
      for (size_t k = 0; k < route.size(); ++k) {
        const auto it = seg_index.find(route[k]);
        if (joined[k] || it == seg_index.end()) continue;
        const KblSegment& s = h.segments[static_cast<size_t>(it->second)];
        if (k == 0 || reached.count(s.start.node) || reached.count(s.end.node)) {
          joined[k] = grew = true;
          reached.insert(s.start.node);
          reached.insert(s.end.node);
        }
      }
    }
    for (size_t k = 0; k < route.size(); ++k) {
      if (!joined[k] && seg_index.count(route[k])) {
        h.notes.push_back(what + ": its segments are not connected (" + route[k] +
                          " shares no node with the others)");
        break;
      }
    }
    for (const std::string& sref : route) {
      const auto it = seg_index.find(sref);
      if (it == seg_index.end()) throw InvalidInput(what + ": '" + sref + "' names no Segment");
      std::vector<KblWire>& wires = h.segments[static_cast<size_t>(it->second)].wires;
      if (std::none_of(wires.begin(), wires.end(),
                       [&](const KblWire& w) { return w.id == wire.id; }))
        wires.push_back(wire);
    }
  }
}

// Moves the curve's end (`at_start` or its last point) onto `node`, the move fading linearly in
// arc length to nothing at the other end: the drawn shape as far as a curve that must reach
// both its nodes can keep it, the other end where it was.
void DrawEndTo(Polyline* route, bool at_start, const Vec3& node) {
  Eigen::Matrix3Xd& p = route->points;
  const Eigen::Index n = p.cols();
  const double s0 = route->s[0], length = route->s[n - 1] - s0;
  const Vec3 delta = node - Vec3(p.col(at_start ? 0 : n - 1));
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = length > 0 ? (route->s[i] - s0) / length : 0.5;
    p.col(i) += (at_start ? 1.0 - w : w) * delta;
  }
  p.col(at_start ? 0 : n - 1) = node;  // exactly, whatever the rounding above
  route->ParameteriseByChords();
}

std::string LengthText(const std::optional<double>& metres) {
  if (!metres) return "not given";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f mm", 1e3 * *metres);
  return buf;
}

// Whether cutting the curve at its node (it runs on past it) gives the segment's length: the
// cut when the cut curve is at least as close to Virtual_length as the whole one (always when
// the file gives none). A curve that only happens to pass near the node is not cut short.
bool CutsToItsLength(const Polyline& route, bool at_start, const Vec3& node,
                     const std::optional<double>& virtual_length, double tolerance) {
  Polyline cut = route;
  if (!TrimAtNode(&cut, at_start, node, tolerance)) return false;
  if (!virtual_length) return true;
  const double whole = route.s[route.size() - 1], part = cut.s[cut.size() - 1];
  return std::abs(part - *virtual_length) <= std::abs(whole - *virtual_length);
}

// Where most of the ends agree (within the tolerance; the first in file order on a tie), and
// how many ends agree there.
std::pair<Vec3, int> Meeting(const std::vector<CableJunction::End>& ends,
                             const std::function<Vec3(const CableJunction::End&)>& end_point,
                             double tolerance) {
  Vec3 where = end_point(ends.front());
  int best = 0;
  for (const CableJunction::End& a : ends) {
    int agree = 0;
    for (const CableJunction::End& e : ends)
      agree += (end_point(e) - end_point(a)).norm() <= tolerance;
    if (agree > best) {
      best = agree;
      where = end_point(a);
    }
  }
  return {where, best};
}

// Positions the nodes and makes every segment reach its nodes, recording the junctions; returns
// per segment whether it has to be left out. The harness is built from one consistent choice:
// - a node's own point where a curve ends there (or runs through it, below);
// - else where its segments' curves meet each other (two or more ending together), or the end
//   of its only segment's curve: the node's point is off (one note per node);
// - a curve that runs on past its node is cut there when that brings it to its Virtual_length
//   (a segment split in the design tool whose curve kept the old extent);
// - any other curve end away from its node is drawn onto the node (DrawEndTo; one note per end)
//   instead of cut short: the segment keeps its drawn length as nearly as it can, and
//   KblSegment::end_drawn_to_node says the file's geometry was changed.
std::vector<bool> PlaceNodes(NodeMap* node_map, const KblReadOptions& options, KblHarness* out) {
  KblHarness& h = *out;
  NodeMap& nodes = *node_map;
  for (size_t i = 0; i < h.segments.size(); ++i) {
    nodes[h.segments[i].start.node].ends.push_back({static_cast<int>(i), true});
    nodes[h.segments[i].end.node].ends.push_back({static_cast<int>(i), false});
  }
  auto route_of = [&](const CableJunction::End& e) -> Polyline& {
    return h.drawing.cables[static_cast<size_t>(e.cable)].centreline;
  };
  const std::function<Vec3(const CableJunction::End&)> end_point = [&](const CableJunction::End& e) {
    const Polyline& c = route_of(e);
    return Vec3(c.points.col(e.at_start ? 0 : c.size() - 1));
  };
  const double tol = options.node_tolerance;
  std::vector<bool> refused(h.segments.size(), false);
  for (auto& [node_id, info] : nodes) {
    if (info.ends.empty()) continue;
    const auto [meet, agreeing] = Meeting(info.ends, end_point, tol);
    Vec3 ref = meet;
    if (info.point) {
      ref = *info.point;
      bool lands = false;  // some curve ends at the node's point or is cut there
      for (const CableJunction::End& e : info.ends) {
        const KblSegment& seg = h.segments[static_cast<size_t>(e.cable)];
        lands = lands || (end_point(e) - ref).norm() <= tol ||
                CutsToItsLength(route_of(e), e.at_start, ref, seg.virtual_length, tol);
      }
      if (!lands && (agreeing >= 2 || info.ends.size() == 1)) {
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "Node %s: its Cartesian_point is %.2f mm from where %s: placed there",
                      node_id.c_str(), 1e3 * (meet - ref).norm(),
                      info.ends.size() == 1 ? "its only segment's centre curve ends"
                                            : "its segments' centre curves meet");
        h.notes.push_back(buf);
        ref = meet;
      }
    }
    CableJunction j;
    j.position = ref;
    j.joined = true;
    j.name = node_id;
    for (const CableJunction::End& e : info.ends) {
      KblSegment& seg = h.segments[static_cast<size_t>(e.cable)];
      (e.at_start ? seg.start : seg.end).segments_at_node = static_cast<int>(info.ends.size());
      Polyline& route = route_of(e);
      const double miss = (end_point(e) - ref).norm();
      const double before = route.s[route.size() - 1];
      const char* which = e.at_start ? "Start_node" : "End_node";
      char buf[400];
      if (miss <= tol) {
        // Lands on its node.
      } else if (CutsToItsLength(route, e.at_start, ref, seg.virtual_length, tol)) {
        TrimAtNode(&route, e.at_start, ref, tol);
        std::snprintf(buf, sizeof buf,
                      "Segment %s: centre curve runs %.2f mm past its %s %s: trimmed there",
                      seg.id.c_str(), 1e3 * (before - route.s[route.size() - 1]), which,
                      node_id.c_str());
        h.notes.push_back(buf);
      } else {
        DrawEndTo(&route, e.at_start, ref);
        seg.node_miss = std::max(seg.node_miss, miss);
        seg.end_drawn_to_node = true;
        std::snprintf(buf, sizeof buf,
                      "Segment %s: centre curve ends %.2f mm from its %s %s: its end drawn onto "
                      "the node (%.2f mm long, was %.2f mm; Virtual_length %s)",
                      seg.id.c_str(), 1e3 * miss, which, node_id.c_str(),
                      1e3 * route.s[route.size() - 1], 1e3 * before,
                      LengthText(seg.virtual_length).c_str());
        h.notes.push_back(buf);
      }
      seg.drawn_length = route.s[route.size() - 1];
      if (seg.drawn_length <= kNoLength) {
        refused[static_cast<size_t>(e.cable)] = true;
      } else {
        j.ends.push_back(e);
      }
    }
    if (j.ends.size() >= 2) h.drawing.junctions.push_back(j);
  }

  return refused;
}

// `h` without the refused segments (each named in `skipped`), junction indices renumbered.
KblHarness WithoutRefused(KblHarness h, const std::vector<bool>& refused) {
  // A segment whose curve has no length left once it reaches its nodes cannot be relaxed: it is
  // left out (named in `skipped`), the others are relaxed. Its index is removed from the
  // junctions too.
  std::vector<int> new_index(h.segments.size(), -1);
  KblHarness kept;
  kept.version = h.version;
  kept.notes = h.notes;
  kept.drawing.source_path = h.drawing.source_path;
  kept.drawing.length_unit = h.drawing.length_unit;
  for (size_t i = 0; i < h.segments.size(); ++i) {
    if (refused[i]) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "Segment %s: its centre curve has no length between its nodes: left out",
                    h.segments[i].id.c_str());
      kept.drawing.skipped.push_back(buf);
      continue;
    }
    new_index[i] = static_cast<int>(kept.segments.size());
    kept.segments.push_back(std::move(h.segments[i]));
    kept.drawing.cables.push_back(std::move(h.drawing.cables[i]));
  }
  if (kept.segments.empty()) {
    throw InvalidInput(kept.drawing.skipped.empty() ? "no segment" : kept.drawing.skipped.front());
  }
  for (CableJunction j : h.drawing.junctions) {
    std::vector<CableJunction::End> ends;
    for (CableJunction::End e : j.ends) {
      if (new_index[static_cast<size_t>(e.cable)] < 0) continue;
      e.cable = new_index[static_cast<size_t>(e.cable)];
      ends.push_back(e);
    }
    j.ends = ends;
    if (j.ends.size() >= 2) kept.drawing.junctions.push_back(j);
  }

  return kept;
}

// Findings that do not stop the reading: lengths against Virtual_length, segments without wires.
void AddLengthNotes(KblHarness* h) {
  for (const KblSegment& seg : h->segments) {
    if (seg.virtual_length &&
        std::abs(seg.drawn_length - *seg.virtual_length) > 0.01 * *seg.virtual_length + 1e-3) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "Segment %s: centre curve %.2f mm long, Virtual_length %.2f mm", seg.id.c_str(),
                    1e3 * seg.drawn_length, 1e3 * *seg.virtual_length);
      h->notes.push_back(buf);
    }
    if (seg.wires.empty()) h->notes.push_back("Segment " + seg.id + ": no wire routed through it");
  }
}

KblHarness ReadContainer(const xmlNode* root, const std::string& path,
                         const KblReadOptions& options) {
  KblHarness h;
  CheckContainer(root, &h.version);
  const IdIndex ids = kbl::IndexIds(root);
  h.drawing.source_path = path;
  h.drawing.length_unit = "mm";
  NodeMap nodes = ReadNodes(root, ids);
  // Segments.
  std::vector<const xmlNode*> seg_nodes = Children(root, "Segment");
  if (seg_nodes.empty()) throw InvalidInput("KBL_container holds no Segment");
  std::map<std::string, int> seg_index;
  for (const xmlNode* sn : seg_nodes) {
    KblSegment seg = ReadSegment(sn, nodes, ids);
    DrawnCable cable;
    cable.name = seg.id;
    cable.source = CableSourceKind::kCurve;
    cable.centreline = SegmentCurve(sn, seg.id, ids, options);
    seg.drawn_length = cable.centreline.s[cable.centreline.size() - 1];
    seg_index[seg.id] = static_cast<int>(h.segments.size());
    h.segments.push_back(std::move(seg));
    h.drawing.cables.push_back(std::move(cable));
  }

  AddRoutings(root, ids, seg_index, &h);
  const std::vector<bool> refused = PlaceNodes(&nodes, options, &h);
  KblHarness kept = WithoutRefused(std::move(h), refused);
  AddLengthNotes(&kept);
  return kept;
}

}  // namespace

KblHarness ReadKblFile(const std::string& path, const KblReadOptions& options) {
  const std::string bytes = ReadInputFile(path, kMaxKblInputBytes, "KBL");
  try {
    const kbl::XmlDoc doc = kbl::ParseXml(bytes);
    return ReadContainer(xmlDocGetRootElement(doc.get()), path, options);
  } catch (const FileError&) {
    throw;
  } catch (const InvalidInput& e) {
    throw FileError(path, e.what());
  }
}

}  // namespace cablefit
