#include "drawn_sweeps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cablefit::internal {
namespace {

// How far a sweep's centres may stray from the curve, as a fraction of the sweep's radius:
// neighbouring wires of a bundle are at least a diameter apart, a sweep's own centres are on
// its spine to the tessellation's accuracy.
constexpr double kOnCurveFraction = 0.2;
// A hollow tube alone is a cable's body (a hose) when it covers this much of the curve.
constexpr double kHoseCoverage = 0.9;
// A layer whose bore fits a matched core within this fraction sits on it (insulation).
constexpr double kLayerFit = 0.1;
// Layers covering at least this much of the curve set its diameter (the largest of them):
// an insulated wire stripped at its end is as thick as its insulation.
constexpr double kDiameterCoverage = 0.5;

// Arc length of the nearest route point to `p`, and its distance.
double NearestOnRoute(const Polyline& route, const Eigen::Vector3d& p, double* distance) {
  double best = std::numeric_limits<double>::infinity(), best_s = 0.0;
  for (Eigen::Index i = 0; i + 1 < route.size(); ++i) {
    const Eigen::Vector3d a = route.points.col(i), ab = route.points.col(i + 1) - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const double d = (p - (a + t * ab)).norm();
    if (d < best) {
      best = d;
      best_s = route.s[i] + t * (route.s[i + 1] - route.s[i]);
    }
  }
  *distance = best;
  return best_s;
}

struct Match {
  int tube = 0;
  double coverage = 0.0;  // fraction of the curve's length the tube spans
  bool body = false;
};

// The fraction of `route` that `tube` runs along, or a negative number when it strays.
double Coverage(const Polyline& route, double route_tolerance, const DrawnTube& tube) {
  const double tolerance = kOnCurveFraction * tube.radius + route_tolerance;
  double s_min = std::numeric_limits<double>::infinity(), s_max = -s_min;
  for (Eigen::Index k = 0; k < tube.centres.cols(); ++k) {
    double d = 0.0;
    const double s = NearestOnRoute(route, tube.centres.col(k), &d);
    if (d > tolerance) return -1.0;
    s_min = std::min(s_min, s);
    s_max = std::max(s_max, s);
  }
  const double length = route.s[route.size() - 1];
  return length > 0 ? (s_max - s_min) / length : -1.0;
}

bool BoxesMeet(const Polyline& route, const DrawnTube& tube, double margin) {
  const Eigen::Vector3d lo = route.points.rowwise().minCoeff().array() - margin;
  const Eigen::Vector3d hi = route.points.rowwise().maxCoeff().array() + margin;
  const Eigen::Vector3d tlo = tube.centres.rowwise().minCoeff();
  const Eigen::Vector3d thi = tube.centres.rowwise().maxCoeff();
  return (tlo.array() <= hi.array()).all() && (thi.array() >= lo.array()).all();
}

std::string Mm(double metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g mm", metres * 1e3);
  return buf;
}

}  // namespace

void MergeSweepsIntoCurves(const std::vector<DrawnTube>& tubes, HarnessDrawing* drawing,
                           AbsorbedTubes* shared) {
  std::vector<DrawnCable>& cables = drawing->cables;
  std::vector<char> claimed(tubes.size(), 0);
  AbsorbedTubes own(*drawing);
  AbsorbedTubes& absorbed = shared ? *shared : own;
  for (size_t t = 0; t < tubes.size(); ++t) claimed[t] = absorbed.Marked(tubes[t]) ? 1 : 0;
  // Bare curves first: a conductor tube that is a curve's body goes with its curve, layers and all.
  for (int pass = 0; pass < 2; ++pass)
  for (size_t c = 0; c < cables.size(); ++c) {
    DrawnCable& curve = cables[c];
    // A bare curve takes a body; a solid tube cable (a conductor) only takes layers around it.
    const bool bare = curve.source == CableSourceKind::kCurve && !(curve.diameter > 0);
    const bool core = curve.source == CableSourceKind::kTube && curve.diameter > 0 && !curve.flat &&
                      !(curve.inner_diameter > 0);
    if (!(pass == 0 ? bare : core) || absorbed.CableMarked(c) || curve.centreline.size() < 2) continue;
    const double core_radius = core ? 0.5 * curve.diameter : 0.0;
    std::vector<Match> matches;
    for (size_t t = 0; t < tubes.size(); ++t) {
      const DrawnTube& tube = tubes[t];
      if (claimed[t] || tube.centres.cols() == 0 || (tube.is_cable && tube.index == static_cast<int>(c)))
        continue;
      if (!BoxesMeet(curve.centreline, tube, kOnCurveFraction * tube.radius + curve.fit_error))
        continue;
      const double coverage = Coverage(curve.centreline, curve.fit_error, tube);
      if (coverage >= 0 && (bare || tube.inner_radius > 0))
        matches.push_back({static_cast<int>(t), coverage, tube.inner_radius <= 0});
    }
    for (Match& m : matches) {
      const DrawnTube& layer = tubes[m.tube];
      if (m.body) continue;
      m.body = bare && m.coverage >= kHoseCoverage;
      if (core && std::abs(core_radius - layer.inner_radius) <= kLayerFit * layer.inner_radius)
        m.body = true;
      for (const Match& core : matches) {
        const DrawnTube& inner = tubes[core.tube];
        if (inner.inner_radius <= 0 &&
            std::abs(inner.radius - layer.inner_radius) <= kLayerFit * layer.inner_radius)
          m.body = true;
      }
    }
    const Match* chosen = nullptr;
    for (const Match& m : matches) {
      if (!m.body) continue;
      const bool wide = m.coverage >= kDiameterCoverage;
      if (!chosen) {
        chosen = &m;
        continue;
      }
      const bool chosen_wide = chosen->coverage >= kDiameterCoverage;
      if (wide && !chosen_wide) chosen = &m;
      else if (wide == chosen_wide &&
               (wide ? tubes[m.tube].radius > tubes[chosen->tube].radius
                     : m.coverage > chosen->coverage))
        chosen = &m;
    }
    if (!chosen) continue;
    const DrawnTube& body = tubes[chosen->tube];
    if (bare) {
      curve.diameter = 2 * body.radius;
      const bool has_core = std::any_of(matches.begin(), matches.end(), [&](const Match& m) {
        return m.body && tubes[m.tube].inner_radius <= 0;
      });
      curve.inner_diameter = has_core ? 0.0 : 2 * body.inner_radius;
    } else if (chosen->coverage >= kDiameterCoverage) {
      curve.diameter = std::max(curve.diameter, 2 * body.radius);
    }
    for (const Match& m : matches) {
      if (!m.body) continue;
      const DrawnTube& tube = tubes[m.tube];
      claimed[m.tube] = 1;
      const std::string name = tube.is_cable ? cables[tube.index].name
                                             : drawing->solids[tube.index].name;
      if (!curve.has_color) {
        const bool has = tube.is_cable ? cables[tube.index].has_color
                                       : drawing->solids[tube.index].has_color;
        if (has) {
          curve.has_color = true;
          curve.color = tube.is_cable ? cables[tube.index].color : drawing->solids[tube.index].color;
        }
      }
      char line[200];
      std::snprintf(line, sizeof line, "the %s %s drawn along %s '%s' (%.0f %% of it)",
                    Mm(2 * tube.radius).c_str(), tube.inner_radius > 0 ? "sleeve" : "tube",
                    bare ? "curve" : "cable", curve.name.c_str(), 100 * std::min(1.0, m.coverage));
      const std::string why = "'" + (name.empty() ? std::string("unnamed") : name) + "': " +
                              line + ": part of that cable (" + Mm(curve.diameter) +
                              " across), not a separate part";
      absorbed.Mark(tube, why, drawing, static_cast<int>(c));
    }
  }
  if (!shared) own.RemoveFrom(drawing);
}

void AbsorbedTubes::Mark(const DrawnTube& tube, const std::string& why, HarnessDrawing* drawing,
                         int owner) {
  if (tube.skipped_note >= 0 && tube.skipped_note < static_cast<int>(drawing->skipped.size()))
    drawing->skipped[static_cast<size_t>(tube.skipped_note)] = why;
  else
    drawing->skipped.push_back(why);
  (tube.is_cable ? cable_ : solid_)[static_cast<size_t>(tube.index)] = 1;
  if (!tube.is_cable) solid_owner_[static_cast<size_t>(tube.index)] = owner;
}

void AbsorbedTubes::ReleaseSolidsOf(int owner) {
  for (size_t k = 0; k < solid_.size(); ++k)
    if (solid_owner_[k] == owner && owner >= 0) solid_[k] = 0;
}

void AbsorbedTubes::Drop(const DrawnTube& tube, HarnessDrawing* drawing) {
  if (tube.skipped_note >= 0 && tube.skipped_note < static_cast<int>(drawing->skipped.size()))
    drawing->skipped[static_cast<size_t>(tube.skipped_note)].clear();
  (tube.is_cable ? cable_ : solid_)[static_cast<size_t>(tube.index)] = 1;
}

void AbsorbedTubes::RemoveFrom(HarnessDrawing* drawing) const {
  drawing->skipped.erase(std::remove(drawing->skipped.begin(), drawing->skipped.end(), std::string()),
                         drawing->skipped.end());
  std::vector<DrawnCable> cables;
  for (size_t c = 0; c < drawing->cables.size(); ++c)
    if (c >= cable_.size() || !cable_[c]) cables.push_back(std::move(drawing->cables[c]));
  drawing->cables = std::move(cables);
  std::vector<DrawnSolid> solids;
  for (size_t k = 0; k < drawing->solids.size(); ++k)
    if (k >= solid_.size() || !solid_[k]) solids.push_back(std::move(drawing->solids[k]));
  drawing->solids = std::move(solids);
}

}  // namespace cablefit::internal
