// The tolerance envelope in the relax outputs: the JSON's per-cable `tolerance`, the stdout
// lines and the report's card.
#include <cmath>
#include <cstdio>

#include "cablefit/app/tolerance/relax_tolerance.h"

namespace cablefit::addin {
namespace {

json::Json CaseJson(const ToleranceCase& c) {
  json::Json j = {{"length", c.length},
          {"bending_stiffness", c.bending_stiffness},
          {"linear_density", c.linear_density},
          {"clip_shift", c.clip_shift},
          {"converged", c.converged},
          {"buildable", c.buildable},
          {"excursion", c.excursion},
          {"s", c.s},
          {"point", json::ToJson(c.point)}};
  j["problem"] = c.converged ? json::Json(nullptr) : json::Json(c.why);
  return j;
}

json::Json NumberOrNull(double x) { return std::isfinite(x) ? json::Json(x) : json::Json(nullptr); }

}  // namespace

json::Json CableToleranceToJson(const CableTolerance& t) {
  json::Json corners = json::Json::array(), interior = json::Json::array(),
             clips = json::Json::array();
  for (const ToleranceCase& c : t.corners) corners.push_back(CaseJson(c));
  for (const ToleranceCase& c : t.interior) interior.push_back(CaseJson(c));
  for (size_t i = 0; i < t.clip_s.size(); ++i)
    clips.push_back({{"s", t.clip_s[i]},
                     {"shift_min", t.clip_range[i][0]},
                     {"shift_max", t.clip_range[i][1]},
                     {"origin", t.clip_origin[i]}});
  json::Json j = {
      {"corners", corners},
      {"interior_checks", interior},
      {"interior_within_corners", t.interior_within},
      {"clip_positions", clips},
      {"quantities", t.quantities},
      {"corner_selection", t.all_corners ? "all" : "sensitivity"},
      {"sensitivity_solves", t.sensitivity_solves},
      {"network", t.network.empty() ? json::Json(nullptr) : json::Json(t.network)},
      {"elements", t.elements},
      {"resolution_error", NumberOrNull(t.resolution_error)},
      {"seconds", t.seconds},
      {"meaning",
       "the cable solved at the corners of its tolerance box from the nominal shape: signed "
       "fractions of length, bending stiffness (EI and GJ) and linear density, and clip_shift "
       "[m], where on the cable each support of clip_positions holds it (+ = further along, "
       "within [shift_min, shift_max]: the tolerance, less where the cable to a neighbour is "
       "short or nearly taut); buildable false = the set-up cannot exist (a stretch shorter "
       "than its supports' distance), not a gap in the envelope; "
       "corner_selection 'all' = every corner, 'sensitivity' = the worst corners of the "
       "linearised shape (more than 6 quantities); a network (its cables listed in 'network') "
       "varies as one, solved at 'elements' elements, 'resolution_error' [m] from its refined "
       "relax; excursion [m] = the largest distance of the varied cable from the nominal one "
       "(as curves), s on the nominal cable, point on the varied one; interior_checks: "
       "pseudo-random points inside the box, to show the corners bound it "
       "(interior_within_corners)"}};
  if (t.worst_corner >= 0) {
    const ToleranceCase& w = t.corners[static_cast<size_t>(t.worst_corner)];
    j["max_excursion"] = {{"excursion", w.excursion},
                          {"s", w.s},
                          {"point", json::ToJson(w.point)},
                          {"corner", t.worst_corner}};
  } else {
    j["max_excursion"] = nullptr;
  }
  return j;
}

std::vector<std::string> ToleranceLines(const FileTolerance& t) {
  std::vector<std::string> lines;
  for (const CableTolerance& c : t.cables) {
    char buf[1400];
    if (c.worst_corner < 0) {
      std::snprintf(buf, sizeof buf, "tolerance: %s: no corner could be solved (first: %s)",
                    c.name.c_str(), c.corners.empty() ? "none" : c.corners[0].why.c_str());
      lines.push_back(buf);
      continue;
    }
    const ToleranceCase& w = c.corners[static_cast<size_t>(c.worst_corner)];
    std::string clips;
    for (double d : w.clip_shift) {
      char one[32];
      std::snprintf(one, sizeof one, "%s%+.1f", clips.empty() ? "" : "/", 1e3 * d);
      clips += one;
    }
    if (!clips.empty()) clips = ", clips " + clips + " mm";
    std::string how = c.all_corners
                          ? std::to_string(c.corners.size()) + " corners"
                          : std::to_string(c.corners.size()) + " worst corners of 2^" +
                                std::to_string(c.quantities) + " by sensitivity";
    if (!c.network.empty()) how += " of its network";
    // A set-up that could not be solved leaves the envelope open on its side; one that cannot
    // be built is no harness at all. Both said, with the first reason.
    int unsolved = 0, unbuildable = 0;
    std::string unsolved_why, unbuildable_why;
    for (const auto* list : {&c.corners, &c.interior})
      for (const ToleranceCase& k : *list) {
        if (k.converged) continue;
        if (!k.buildable && unbuildable++ == 0) unbuildable_why = k.why;
        if (k.buildable && unsolved++ == 0) unsolved_why = k.why;
      }
    if (unbuildable > 0)
      how += ", " + std::to_string(unbuildable) + " set-ups cannot be built (first: " +
             unbuildable_why + ")";
    if (unsolved > 0)
      how += ", " + std::to_string(unsolved) + " set-ups NOT SOLVED (the envelope may be larger; " +
             "first: " + unsolved_why + ")";
    std::snprintf(buf, sizeof buf,
                  "tolerance: %s: max excursion %.2f mm at s=%.0f mm (length %+.3g%%, EI %+.3g%%, "
                  "density %+.3g%%%s), %s, %zu interior checks %s, %.3f s",
                  c.name.c_str(), 1e3 * w.excursion, 1e3 * w.s, 100 * w.length,
                  100 * w.bending_stiffness, 100 * w.linear_density, clips.c_str(), how.c_str(),
                  c.interior.size(), c.interior_within ? "within" : "BEYOND THE CORNERS",
                  c.seconds);
    lines.push_back(buf);
  }
  for (const std::string& p : t.problems) lines.push_back(p);
  return lines;
}

}  // namespace cablefit::addin
