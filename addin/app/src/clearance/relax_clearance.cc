#include "cablefit/app/clearance/relax_clearance.h"

#include <algorithm>
#include <cstdio>

#include "cablefit/app/base/batch_pool.h"
#include "cablefit/core/base/parallel_for.h"


namespace cablefit::addin {

namespace {

// The arc length to leave out at each end of `a` for its pair with `b`: near an end that meets
// one of b's ends (a junction or splice).
TubeSkip JunctionSkip(const ClearanceCable& a, const ClearanceCable& b) {
  TubeSkip skip;
  const Polyline& pa = *a.centreline;
  const Polyline& pb = *b.centreline;
  const double touch = a.radius + b.radius, length = kJunctionSkipFactor * touch;
  const Vec3 b0 = pb.points.col(0), b1 = pb.points.col(pb.size() - 1);
  auto meets = [&](const Vec3& p) { return (p - b0).norm() <= touch || (p - b1).norm() <= touch; };
  if (meets(pa.points.col(0))) skip.start = length;
  if (meets(pa.points.col(pa.size() - 1))) skip.end = length;
  return skip;
}

}  // namespace

std::vector<ClearancePair> MeasureClearances(const std::vector<ClearanceCable>& cables,
                                             const std::vector<ClearanceSolid>& solids) {
  // Cable pairs: each cable's nearest other cable, and every pair close enough to break the
  // min_clearance asked of it; pairs far apart are never measured (TubeClearanceIndex).
  std::vector<TubeClearanceIndex::Tube> tubes;
  std::vector<int> tube_of(cables.size(), -1), cable_of;
  double widest_asked = 0.0;
  for (size_t i = 0; i < cables.size(); ++i) {
    if (cables[i].centreline == nullptr || cables[i].centreline->size() < 2) continue;
    tube_of[i] = static_cast<int>(tubes.size());
    cable_of.push_back(static_cast<int>(i));
    tubes.push_back({cables[i].centreline, cables[i].radius});
    widest_asked = std::max(widest_asked, cables[i].min_clearance);
  }
  const TubeClearanceIndex index(tubes);
  const auto skip = [&](int a, int b) {
    return JunctionSkip(cables[static_cast<size_t>(cable_of[static_cast<size_t>(a)])],
                        cables[static_cast<size_t>(cable_of[static_cast<size_t>(b)])]);
  };
  // Each tube's queries on every core, each into its own slot.
  const int nt = static_cast<int>(tubes.size());
  std::vector<int> nearest(tubes.size(), -1);
  std::vector<std::vector<int>> within(tubes.size());
  ParallelFor(nt, UsableCores(), [&](int t) {
    nearest[static_cast<size_t>(t)] = index.Nearest(t, skip);
    if (widest_asked > 0) within[static_cast<size_t>(t)] = index.Within(t, widest_asked);
  });
  std::vector<std::vector<int>> partners(cables.size());  // j > i measured with cable i
  for (size_t t = 0; t < tubes.size(); ++t) {
    const int i = cable_of[t];
    if (nearest[t] >= 0) {
      const int j = cable_of[static_cast<size_t>(nearest[t])];
      partners[static_cast<size_t>(std::min(i, j))].push_back(std::max(i, j));
    }
    for (int other : within[t]) {
      const int j = cable_of[static_cast<size_t>(other)];
      const double asked = std::max(cables[static_cast<size_t>(i)].min_clearance,
                                    cables[static_cast<size_t>(j)].min_clearance);
      if (j > i && asked > 0) partners[static_cast<size_t>(i)].push_back(j);
    }
  }
  // Every cable's pairs, measured on every core and listed in cable order.
  std::vector<std::vector<ClearancePair>> per_cable(cables.size());
  ParallelFor(static_cast<int>(cables.size()), UsableCores(), [&](int ci) {
    const size_t i = static_cast<size_t>(ci);
    const ClearanceCable& c = cables[i];
    if (tube_of[i] < 0) return;
    std::vector<ClearancePair>& pairs = per_cable[i];
    for (const ClearanceSolid& s : solids) {
      if (s.geometry == nullptr || s.geometry->empty()) continue;
      ClearancePair p;
      p.cable = c.name;
      p.other = s.name;
      p.hit = s.geometry->ToTube(*c.centreline, c.radius);
      p.required = std::max(c.min_clearance, s.min_clearance);
      p.rests_on =
          std::find(c.clipped_to.begin(), c.clipped_to.end(), s.name) != c.clipped_to.end() ||
          p.hit.clearance <= kRestingFraction * c.radius;
      pairs.push_back(p);
    }
    std::vector<int>& with = partners[i];  // this cable's own slot
    std::sort(with.begin(), with.end());
    with.erase(std::unique(with.begin(), with.end()), with.end());
    for (int j : with) {
      const ClearanceCable& d = cables[static_cast<size_t>(j)];
      ClearancePair p;
      p.cable = c.name;
      p.other = d.name;
      p.other_is_solid = false;
      p.hit = TubeToTubeClearance(*c.centreline, c.radius, JunctionSkip(c, d), *d.centreline,
                                  d.radius, JunctionSkip(d, c));
      p.required = std::max(c.min_clearance, d.min_clearance);
      if (p.hit.found()) pairs.push_back(p);
    }
  });
  std::vector<ClearancePair> pairs;
  for (std::vector<ClearancePair>& some : per_cable)
    for (ClearancePair& p : some) pairs.push_back(std::move(p));
  return pairs;
}

json::Json ClearancePairToJson(const ClearancePair& p) {
  json::Json j = {{"cable", p.cable},
                  {p.other_is_solid ? "solid" : "other_cable", p.other},
                  {"clearance", json::NumberOrNull(p.hit.clearance)},
                  {"s", p.hit.s},
                  {"point", json::ToJson(p.hit.point)},
                  {"nearest_point", json::ToJson(p.hit.other)},
                  {"required", p.required},
                  {"violation", p.violation()}};
  if (p.other_is_solid) j["rests_on"] = p.rests_on;
  if (!p.other_is_solid) j["other_s"] = p.hit.other_s;
  return j;
}

std::string ClearanceViolationText(const ClearancePair& p) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s to %s '%s': %.1f mm, less than the %.1f mm asked, at s=%.0f mm (%.1f, %.1f, "
                "%.1f) mm",
                p.cable.c_str(), p.other_is_solid ? "solid" : "cable", p.other.c_str(),
                1e3 * p.hit.clearance, 1e3 * p.required, 1e3 * p.hit.s, 1e3 * p.hit.point.x(),
                1e3 * p.hit.point.y(), 1e3 * p.hit.point.z());
  return buf;
}

std::vector<OrientedBox> ClearanceBoxes(const HarnessDrawing& drawing) {
  std::vector<OrientedBox> boxes;
  for (const DrawnSolid& s : drawing.solids)
    boxes.push_back(s.mesh.vertices.cols() > 0 ? BoundingBoxOf(s.mesh) : OrientedBox{});
  return boxes;
}

ClearanceCable ClearanceCableOf(const CableRelaxation& r, const Polyline* centreline,
                                const HarnessDrawing& drawing,
                                const std::vector<OrientedBox>& boxes,
                                const HarnessConfig& config) {
  ClearanceCable c;
  c.name = r.setup.name;
  c.centreline = centreline;
  c.radius = 0.5 * r.setup.spec.material.diameter;
  c.min_clearance = config.For(c.name).min_clearance.value_or(0.0);
  // A solid holds the cable when one of its supports lies in the solid's box: a clip found on
  // it, or an end held in a connector or ring (the way SetUpCable finds clips).
  for (size_t k = 0; k < boxes.size() && k < drawing.solids.size(); ++k) {
    for (const SupportSpec& sp : r.setup.spec.supports)
      if (boxes[k].half_extent.prod() > 0 && boxes[k].Contains(sp.position)) {
        c.clipped_to.push_back(drawing.solids[k].name);
        break;
      }
  }
  return c;
}

std::vector<ClearancePair> MeasureHarnessClearances(const HarnessConfig& config,
                                                    const RelaxedHarness& h) {
  std::vector<SolidClearance> geometry;
  geometry.reserve(h.drawing.solids.size());
  std::vector<ClearanceSolid> solids;
  for (const DrawnSolid& s : h.drawing.solids) geometry.emplace_back(s.mesh);
  for (size_t k = 0; k < h.drawing.solids.size(); ++k)
    solids.push_back({h.drawing.solids[k].name, &geometry[k],
                      config.SolidMinClearance(h.drawing.solids[k].name)});
  const std::vector<OrientedBox> boxes = ClearanceBoxes(h.drawing);
  std::vector<ClearanceCable> cables;
  for (size_t i = 0; i < h.cables.size(); ++i)
    if (h.cables[i])
      cables.push_back(
          ClearanceCableOf(*h.cables[i], &h.cables[i]->relaxed, h.drawing, boxes, config));
  return MeasureClearances(cables, solids);
}

}  // namespace cablefit::addin
