#include "pipeline/relax_lines.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>


namespace cablefit::addin {

std::string CableLine(const RelaxedFile& f, const CableRelaxation& r) {
  // A bend radius a thousand times the cable's length is a straight cable drawn with round-off.
  char bend[160];
  if (!std::isfinite(r.min_bend_radius) || r.min_bend_radius > 1e3 * r.setup.spec.length) {
    std::snprintf(bend, sizeof bend, "straight");
  } else if (r.bend_flag && r.setup.min_bend_radius_limit > 0) {
    // A cable's own limit (a KBL file's wires) is not the run's factor: say which and where.
    std::snprintf(bend, sizeof bend, "%.1f mm (TOO TIGHT: the cable's limit %.1f mm, at s=%.0f mm)",
                  1e3 * r.min_bend_radius, 1e3 * r.bend_limit, 1e3 * r.min_bend_radius_s);
  } else {
    std::snprintf(bend, sizeof bend, "%.1f mm%s", 1e3 * r.min_bend_radius,
                  r.bend_flag ? " (TOO TIGHT)" : "");
  }
  double least_slack = std::numeric_limits<double>::infinity();
  for (const CableRelaxation::Stretch& st : r.stretches) least_slack = std::min(least_slack, st.slack);
  char taut[96] = "";
  if (r.taut) {
    std::snprintf(taut, sizeof taut, ", TAUT (slack %.3f %% between supports)", 100 * least_slack);
  }
  char tension[48] = "not computed";
  if (std::isfinite(r.max_tension)) std::snprintf(tension, sizeof tension, "%.3g N", r.max_tension);
  char flat[64] = "";
  if (r.setup.flat_width > 0)
    std::snprintf(flat, sizeof flat, ", flat %.3g x %.3g mm", 1e3 * r.setup.flat_width,
                  1e3 * r.setup.flat_thickness);
  char buf[704];
  std::snprintf(buf, sizeof buf,
                "%s: %s: L=%.0f mm%s, max deviation %.2f mm at s=%.0f mm (rms %.2f mm), min bend "
                "radius %s, max tension %s, %d supports, %s%s%s, %.1f ms",
                f.stem.c_str(), r.setup.name.c_str(), 1e3 * r.setup.spec.length, flat,
                1e3 * r.max_deviation, 1e3 * r.max_deviation_s, 1e3 * r.rms_deviation, bend, tension,
                static_cast<int>(r.setup.spec.supports.size()),
                r.result.solution.summary.stable ? "stable" : "UNSTABLE", taut,
                r.setup.material_defaulted ? ", default material" : "", 1e3 * r.seconds);
  return buf;
}

std::string InputLine(const RelaxedFile& f) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s: %zu cables, %zu solids; seconds: read %.3f, relax %.3f, STEP %.3f, "
                "JSON %.3f, picture %.3f",
                f.stem.c_str(), f.drawing.cables.size(), f.drawing.solids.size(), f.times.read,
                f.times.relax, f.times.step, f.times.json, f.times.picture);
  return buf;
}

}  // namespace cablefit::addin
