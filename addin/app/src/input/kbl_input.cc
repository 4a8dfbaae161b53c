#include "cablefit/app/input/kbl_input.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>

#include "cablefit/app/relax/relax_cable.h"

namespace cablefit::addin {
namespace {

json::Json OptionalNumber(const std::optional<double>& v) {
  return v ? json::Json(*v) : json::Json();
}

}  // namespace

KblBundle BundleOf(const std::vector<KblWire>& wires) {
  KblBundle b;
  double sum_d2 = 0.0, largest = 0.0, mass = 0.0;
  int with_mass = 0;
  for (const KblWire& w : wires) {
    if (w.outside_diameter && *w.outside_diameter > 0) {
      sum_d2 += *w.outside_diameter * *w.outside_diameter;
      largest = std::max(largest, *w.outside_diameter);
      ++b.wires_with_diameter;
    }
    if (w.linear_density && *w.linear_density > 0) {
      mass += *w.linear_density;
      ++with_mass;
    }
    if (w.min_bend_radius) b.min_bend_radius = std::max(b.min_bend_radius, *w.min_bend_radius);
  }
  // One wire is its own bundle; several fill a disc at the packing fraction (always wider than
  // the thickest of them, since the fraction is below 1).
  if (b.wires_with_diameter == 1) b.diameter = largest;
  if (b.wires_with_diameter > 1) b.diameter = std::sqrt(sum_d2 / kBundlePackingFraction);
  if (!wires.empty() && with_mass == static_cast<int>(wires.size())) b.linear_density = mass;
  return b;
}

std::string Upper(std::string t) {
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::toupper(c); });
  return t;
}
bool Contains(const std::string& text, const char* part) { return text.find(part) != std::string::npos; }

// An annulus of wall `wall` and modulus `modulus` around a bundle of diameter d over the
// protection's share: EI = E pi/64 ((d + 2 wall)^4 - d^4), GJ = EI / 1.3 as for the bundle.
SleeveConfig AnnulusSleeve(const KblProtection& p, double d, double wall, double modulus) {
  SleeveConfig s;
  s.from = std::clamp(p.start, 0.0, 1.0);
  s.to = std::clamp(p.end, 0.0, 1.0);
  s.bending_stiffness = modulus * M_PI / 64 * (std::pow(d + 2 * wall, 4) - std::pow(d, 4));
  s.torsional_stiffness = s.bending_stiffness / 1.3;
  return s;
}

std::string ProtectionKind(const std::string& type) {
  const std::string t = Upper(type);
  if (Contains(t, "TAPE") || Contains(t, "BAND")) return "tape";
  if (Contains(t, "CORRUG") || Contains(t, "WELL") || Contains(t, "CONVOLUT")) return "corrugated tube";
  return "";
}

namespace {

// The segment's diameter and material from its wires (else from its cross-section area, else
// the defaults): sets `drawn`'s diameter and `cc`'s material; true when the stiffness is the
// estimate over the bundle's diameter.
bool BundleSettings(const KblSegment& seg, const KblBundle& bundle, double area_diameter,
                    DrawnCable* drawn, CableConfig* cc, std::vector<std::string>* assumed,
                    std::string* diameter_source) {
  if (bundle.diameter > 0) {
    drawn->diameter = bundle.diameter;
    *diameter_source = bundle.wires_with_diameter == 1 ? "the wire's outside diameter"
                                                       : "wires packed at 75 % of a disc";
    // Stiffness from the bundle's diameter as for any drawn cable (assumed modulus), the mass
    // from the wires' own data where every wire gives it.
    MaterialSpec m = DefaultBundleMaterial(bundle.diameter);
    std::string source = "KBL: bundle of " + std::to_string(seg.wires.size()) +
                         " wire(s), stiffness estimated from its diameter (assumed E_eff 75 MPa)";
    if (bundle.linear_density > 0) {
      m.linear_density = bundle.linear_density;
      source += ", mass from the wires";
    } else {
      assumed->push_back("mass per length estimated from the diameter (not every wire gives one)");
    }
    cc->material = m;
    cc->material_source = source;
    return true;
  }
  if (area_diameter > 0) {
    drawn->diameter = area_diameter;
    *diameter_source = "the segment's cross-section area (no wire diameter known)";
    assumed->push_back("no wire data: default bundle material over the file's cross-section area");
  } else {
    *diameter_source = "default";
    assumed->push_back("no wire data and no cross-section area: default diameter and material");
  }
  return false;
}

// Protections are sleeves over their share of the segment: their own mass per length where the
// file gives it, and a tape's or corrugated tube's stiffness (assumed); other types' stiffness is
// unknown. Returns per protection whether its stiffness was added.
std::vector<char> ProtectionSleeves(const KblSegment& seg, double diameter, CableConfig* cc,
                                    std::vector<std::string>* assumed) {
  std::vector<char> stiffness_added(seg.protections.size(), 0);
  std::set<std::string> kinds_added;
  for (size_t k = 0; k < seg.protections.size(); ++k) {
    const KblProtection& p = seg.protections[k];
    if (!(p.end > p.start)) continue;
    SleeveConfig sl;
    const std::string kind = ProtectionKind(p.type);
    if (!kind.empty() && diameter > 0) {
      sl = kind == "tape" ? AnnulusSleeve(p, diameter, kTapeWrapThickness, kTapeModulus)
                          : AnnulusSleeve(p, diameter, kCorrugatedWall, kCorrugatedModulus);
      stiffness_added[k] = 1;
      kinds_added.insert(kind);
    } else {
      sl.from = std::clamp(p.start, 0.0, 1.0);
      sl.to = std::clamp(p.end, 0.0, 1.0);
      assumed->push_back("protection " + p.id + " (" + (p.type.empty() ? "no type" : p.type) +
                         "): stiffness unknown, not added");
    }
    if (p.linear_density) sl.linear_density = *p.linear_density;
    if (sl.to > sl.from && (sl.bending_stiffness > 0 || sl.linear_density > 0))
      cc->sleeves.push_back(sl);
  }
  if (kinds_added.count("tape"))
    assumed->push_back("tape stiffness assumed (two layers of 0.13 mm PVC tape, E 40 MPa)");
  if (kinds_added.count("corrugated tube"))
    assumed->push_back("corrugated tube stiffness assumed (a 1.5 mm annulus, effective E 40 MPa)");
  return stiffness_added;
}

// Fixings hold the bundle where they sit: clips at their share of the drawn `length`. Returns
// the fixings' JSON.
json::Json FixingClips(const KblSegment& seg, double length, CableConfig* cc) {
  json::Json fixings = json::Json::array();
  for (const KblFixing& f : seg.fixings) {
    ExtraSupportConfig clip;
    clip.kind = SupportKind::kClip;
    clip.s = f.location * length;
    cc->supports.push_back(clip);
    fixings.push_back({{"id", f.id},
                       {"name", f.name},
                       {"type", f.type},
                       {"location", f.location},
                       {"s", *clip.s}});
  }
  return fixings;
}

json::Json WiresJson(const KblSegment& seg) {
  json::Json wires = json::Json::array();
  for (const KblWire& w : seg.wires) {
    wires.push_back({{"id", w.id},
                     {"part", w.part},
                     {"outside_diameter", OptionalNumber(w.outside_diameter)},
                     {"conductor_area", OptionalNumber(w.conductor_area)},
                     {"linear_density", OptionalNumber(w.linear_density)},
                     {"min_bend_radius", OptionalNumber(w.min_bend_radius)}});
  }
  return wires;
}

json::Json ProtectionsJson(const KblSegment& seg, const std::vector<char>& stiffness_added) {
  json::Json protections = json::Json::array();
  for (size_t k = 0; k < seg.protections.size(); ++k) {
    const KblProtection& p = seg.protections[k];
    protections.push_back(
        {{"id", p.id},
         {"type", p.type},
         {"start", p.start},
         {"end", p.end},
         {"linear_density", OptionalNumber(p.linear_density)},
         {"mass_added", p.linear_density.has_value() && p.end > p.start},
         {"stiffness_added", stiffness_added[k] != 0}});
  }
  return protections;
}

json::Json EndJson(const KblSegmentEnd& e) {
  return json::Json{{"node", e.node},
                    {"node_id", e.node_name},
                    {"connectors", e.connectors},
                    {"segments_at_node", e.segments_at_node}};
}

// What the file says about one segment: its "kbl" object in the relax JSON.
struct SegmentFacts {
  KblBundle bundle;
  double area_diameter = 0.0;  // [m] from the file's cross-section area, 0 = none
  std::string diameter_source;
  json::Json fixings;
  std::vector<char> stiffness_added;  // per protection
  std::vector<std::string> assumed;
};

json::Json SegmentJson(const KblSegment& seg, const DrawnCable& drawn, const SegmentFacts& s) {
  const KblBundle& bundle = s.bundle;
  return json::Json(
      {{"segment", seg.id},
       {"id", seg.name},
       {"start", EndJson(seg.start)},
       {"end", EndJson(seg.end)},
       {"virtual_length", OptionalNumber(seg.virtual_length)},
       {"drawn_length", seg.drawn_length},
       {"node_miss", seg.node_miss},
       {"end_drawn_to_node", seg.end_drawn_to_node},
       {"bundle_diameter", bundle.diameter > 0 ? json::Json(bundle.diameter) : json::Json()},
       {"diameter", drawn.diameter > 0 ? json::Json(drawn.diameter) : json::Json()},
       {"diameter_source", s.diameter_source},
       {"cross_section_area", OptionalNumber(seg.cross_section_area)},
       {"diameter_from_area", s.area_diameter > 0 ? json::Json(s.area_diameter) : json::Json()},
       {"wires_linear_density",
        bundle.linear_density > 0 ? json::Json(bundle.linear_density) : json::Json()},
       {"wires_min_bend_radius",
        bundle.min_bend_radius > 0 ? json::Json(bundle.min_bend_radius) : json::Json()},
       {"wires", WiresJson(seg)},
       {"fixings", s.fixings},
       {"protections", ProtectionsJson(seg, s.stiffness_added)},
       {"assumed", s.assumed}});
}

}  // namespace

KblInput ReadKblInput(const std::string& path, const HarnessConfig& user) {
  KblHarness h = ReadKblFile(path);
  KblInput in;
  in.notes = h.notes;
  in.config = user;
  int stiffness_estimated = 0;  // segments whose EI, GJ, EA come from the bundle diameter
  for (size_t i = 0; i < h.segments.size(); ++i) {
    const KblSegment& seg = h.segments[i];
    DrawnCable& drawn = h.drawing.cables[i];
    SegmentFacts facts;
    facts.bundle = BundleOf(seg.wires);
    facts.area_diameter =
        seg.cross_section_area ? std::sqrt(4.0 * *seg.cross_section_area / M_PI) : 0.0;
    CableConfig cc;
    if (BundleSettings(seg, facts.bundle, facts.area_diameter, &drawn, &cc, &facts.assumed,
                       &facts.diameter_source))
      ++stiffness_estimated;
    facts.stiffness_added = ProtectionSleeves(seg, drawn.diameter, &cc, &facts.assumed);
    if (facts.bundle.min_bend_radius > 0) {
      cc.min_bend_radius = facts.bundle.min_bend_radius;
      cc.min_bend_radius_source = "KBL: tightest Bend_radius of the segment's wires";
    }
    facts.fixings = FixingClips(seg, drawn.centreline.s[drawn.centreline.size() - 1], &cc);
    // A curve drawn onto its node (the file's own did not reach it) is no measure of the
    // segment's length: Virtual_length, the length the harness is made to, is.
    if (seg.end_drawn_to_node && seg.virtual_length) {
      cc.length = CableLength{CableLength::Kind::kMetres, *seg.virtual_length};
      facts.assumed.push_back("built at its Virtual_length: its centre curve was drawn onto its node");
    }
    const auto own = user.cables.find(seg.id);
    in.config.cables[seg.id] = own == user.cables.end() ? cc : Overlaid(cc, own->second);
    if (!facts.assumed.empty()) {
      std::string line = "segment " + seg.id + ": ";
      for (size_t k = 0; k < facts.assumed.size(); ++k) line += (k ? "; " : "") + facts.assumed[k];
      in.notes.push_back(line);
    }
    in.cable_json[seg.id] = SegmentJson(seg, drawn, facts);
  }
  // Said once, not per segment: every bundle's stiffness is this estimate (the JSON's material
  // source says it per cable).
  if (stiffness_estimated > 0) {
    in.notes.push_back(std::to_string(stiffness_estimated) + " of " +
                       std::to_string(h.segments.size()) +
                       " segments: stiffness estimated from the bundle diameter (PVC-copper "
                       "bundle, E_eff 75 MPa assumed); diameter from the wires packed at 75 %");
  }
  in.drawing = std::move(h.drawing);
  return in;
}

}  // namespace cablefit::addin
