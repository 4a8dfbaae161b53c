#include "cablefit/app/relax_report.h"

#include "cablefit/app/relax_clearance.h"
#include "cablefit/app/relax_file.h"

#include <cctype>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <mutex>
#include <set>
#include <sstream>

#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/deviation_views.h"
#include "cablefit/formats/png_file.h"
#include "cablefit/app/provenance.h"
#include "cablefit/app/report_html.h"

namespace cablefit::addin {
namespace {

std::mutex& RenderMutex() {
  static std::mutex mutex;
  return mutex;
}

SupportMarkerKind MarkerOf(SupportKind kind) {
  switch (kind) {
    case SupportKind::kClamp:
      return SupportMarkerKind::kClamp;
    case SupportKind::kClip:
      return SupportMarkerKind::kClip;
    case SupportKind::kPin:
      return SupportMarkerKind::kPin;
  }
  return SupportMarkerKind::kPin;
}

// Red is outside the deviation colour map (viridis), so a failed cable cannot be read as one
// that deviates.
constexpr Rgb kFailedColour{214, 39, 40};

// All cables of `f`, or only cable `only` (>= 0) for a close-up.
Scene HarnessScene(const RelaxedFile& f, const HarnessConfig& config, int only = -1) {
  Scene scene;
  int failed = 0;
  for (size_t i = 0; i < f.drawing.cables.size(); ++i)
    if ((only < 0 || static_cast<int>(i) == only) && !f.cables[i]) ++failed;
  const std::string head =
      only >= 0 ? f.stem + ": " + f.drawing.cables[static_cast<size_t>(only)].name : f.stem;
  // A cable that failed is shown as drawn, in red, and the title says so: a picture must never
  // present a shape nobody computed as a relaxed one.
  if (only >= 0 && failed > 0)
    scene.title = head + ": FAILED, not relaxed; shown as drawn (red)";
  else if (failed > 0)
    scene.title = head + ": relaxed, colour = distance to the drawn route (grey line); " +
                  std::to_string(failed) + (failed == 1 ? " cable" : " cables") +
                  " FAILED, shown as drawn (red)";
  else
    scene.title = head + ": relaxed, colour = distance to the drawn route (grey line)";
  scene.gravity = config.gravity;
  for (size_t i = 0; i < f.drawing.cables.size(); ++i) {
    if (only >= 0 && static_cast<int>(i) != only) continue;
    const DrawnCable& drawn = f.drawing.cables[i];
    SceneTube tube;
    tube.name = drawn.name;
    tube.radius = 0.5 * OutputDiameter(f, static_cast<int>(i), config);
    SceneGhost ghost;
    ghost.name = "drawn route";  // the legend's label for every grey line
    ghost.points = drawn.centreline.points;
    scene.ghosts.push_back(ghost);
    if (const auto& r = f.cables[i]) {
      tube.centreline = r->relaxed;
      tube.deviation = r->deviation;
      for (const SupportSpec& sp : r->setup.spec.supports) {
        scene.supports.push_back({MarkerOf(sp.kind), sp.position, " "});
      }
    } else {
      tube.centreline = drawn.centreline;
      tube.name = drawn.name + " (failed)";
      tube.flat_colour = kFailedColour;
    }
    scene.tubes.push_back(std::move(tube));
  }
  return scene;
}

std::string Row(const std::string& file, const std::string& cable, const CableRelaxation& r) {
  std::ostringstream h;
  const bool ok = r.result.converged && r.result.solution.summary.stable;
  h << "<tr><td>" << HtmlEscape(file) << "</td><td>" << HtmlEscape(cable) << "</td><td>"
    << FormatLength(r.setup.spec.length) << "</td><td>"
    << FormatLength(r.setup.spec.material.diameter)
    << (r.setup.diameter_defaulted ? " (assumed)" : "") << "</td><td>"
    << (r.setup.material_defaulted ? "default estimate" : HtmlEscape(r.setup.material_source))
    << "</td><td>" << r.setup.spec.supports.size() << "</td><td data-v=\"" << r.max_deviation
    << "\">" << FormatLength(r.max_deviation) << " at s = " << FormatLength(r.max_deviation_s);
  if (r.springback_max && r.sag_max)
    h << "<br><small>springback " << FormatLength(*r.springback_max) << ", sag "
      << FormatLength(*r.sag_max) << "</small>";
  h << "</td><td data-v=\"" << r.rms_deviation << "\">" << FormatLength(r.rms_deviation)
    << "</td><td data-v=\"" << r.min_bend_radius << "\">"
    << (std::isfinite(r.min_bend_radius) ? FormatLength(r.min_bend_radius) : "straight")
    << (r.bend_flag ? " <span class=\"badge fail\">&lt; " + FormatLength(r.bend_limit) + "</span>"
                    : "")
    << "</td><td>" << FormatNumber(r.result.solution.twist_angle * 180 / M_PI) << "°</td><td>"
    << "<span class=\"badge " << (ok ? "ok" : "fail") << "\">"
    << (r.result.converged ? (r.result.solution.summary.stable ? "stable" : "unstable")
                           : "not converged")
    << "</span></td><td>";
  if (!r.setup.junction.empty()) h << "junction " << HtmlEscape(r.setup.junction) << "<br>";
  for (const std::string& n : r.setup.notes) h << HtmlEscape(n) << "<br>";
  h << "</td></tr>\n";
  return h.str();
}

}  // namespace

namespace {

void RenderToPng(const std::string& path, const Scene& scene) {
  RenderOptions options;
  options.width = 1400;
  options.height = 900;
  Image image;
  {
    std::lock_guard lock(RenderMutex());
    image = RenderDeviationViews(scene, options);
  }
  WritePng(path, image);
}

// A file-name-safe version of a cable name ("cable_ä#2" -> "cable___2").
std::string FileSafe(const std::string& name) {
  std::string out;
  for (const unsigned char c : name) out += std::isalnum(c) || c == '-' || c == '_' ? char(c) : '_';
  return out.empty() ? "cable" : out;
}

}  // namespace

void WriteDeviationPicture(const std::string& path, const RelaxedFile& f,
                           const HarnessConfig& config) {
  RenderToPng(path, HarnessScene(f, config));
}

std::vector<std::string> WriteCloseUpPictures(const std::string& dir, const RelaxedFile& f,
                                              const HarnessConfig& config) {
  std::vector<std::string> names;
  std::set<std::string> used;
  for (size_t i = 0; i < f.drawing.cables.size(); ++i) {
    std::string name = f.stem + "-" + FileSafe(f.drawing.cables[i].name);
    if (!used.insert(name).second) name.append("-").append(std::to_string(i + 1));
    used.insert(name);
    name += "-deviation.png";
    RenderToPng((std::filesystem::path(dir) / name).string(),
                HarnessScene(f, config, static_cast<int>(i)));
    names.push_back(name);
  }
  return names;
}

namespace {

// What an engineer asks first: how many cables, how many failed or need a look, and the worst
// deviation; then which tool made the page and when (the JSON leaves the date out on purpose).
std::string VerdictSection(const std::vector<RelaxedFile>& files, double seconds) {
  int cables = 0, failed = 0, unstable = 0, bend = 0, taut = 0, inputs_failed = 0;
  double worst = -1.0;
  std::string worst_at;
  for (const RelaxedFile& f : files) {
    if (!f.error.empty() && f.cables.empty()) ++inputs_failed;
    for (size_t i = 0; i < f.cables.size(); ++i) {
      ++cables;
      const auto& r = f.cables[i];
      if (!r || !r->result.converged) {
        ++failed;
        continue;
      }
      if (!r->result.solution.summary.stable) ++unstable;
      if (r->bend_flag) ++bend;
      if (r->taut) ++taut;
      if (r->max_deviation > worst) {
        worst = r->max_deviation;
        worst_at = f.drawing.cables[i].name + " (" + f.stem + ")";
      }
    }
  }
  std::ostringstream h;
  h << "<section class=\"card\"><h2>Verdict</h2><p><b>" << cables << " cable"
    << (cables == 1 ? "" : "s") << "</b> from " << files.size() << " input"
    << (files.size() == 1 ? "" : "s") << ": " << cables - failed << " relaxed, "
    << "<span class=\"badge " << (failed ? "fail" : "ok") << "\">" << failed << " failed</span>, "
    << bend << " below the bend-radius limit, " << taut << " taut, " << unstable << " unstable";
  if (inputs_failed) h << "; " << inputs_failed << " input(s) could not be read";
  h << ".";
  if (worst >= 0)
    h << " Largest deviation from the drawing: <b>" << FormatLength(worst) << "</b>, "
      << HtmlEscape(worst_at) << ".";
  char date[32] = "";
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  if (gmtime_r(&now, &utc)) std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &utc);
  h << "</p><p><small>" << HtmlEscape(ToolVersion()) << ", " << date << ", "
    << FormatNumber(seconds) << " s.</small></p></section>\n";
  return h.str();
}

}  // namespace

void WriteRelaxReport(const std::string& path, const std::vector<RelaxedFile>& files,
                      const HarnessConfig& config, double seconds) {
  auto any_own_bend_limit = [](const std::vector<RelaxedFile>& fs) {
    for (const RelaxedFile& f : fs)
      for (const auto& c : f.cables)
        if (c && c->setup.min_bend_radius_limit > 0) return true;
    return false;
  };
  std::ostringstream h;
  h << PageHead("cablefit relax");
  h << VerdictSection(files, seconds);
  h << "<section class=\"card\"><h2>Relaxed cables</h2>\n<p>Each cable is solved as a Kirchhoff "
       "rod under gravity from its drawn shape (nearest equilibrium), ends clamped at their drawn "
       "pose unless harness.json says otherwise. Deviation = distance of the relaxed centreline "
       "to the drawn route. Bend radius flagged below "
    << FormatNumber(config.min_bend_radius_factor) << " diameters"
    << (any_own_bend_limit(files) ? ", or below the cable's own limit where its data give one (a KBL "
                                 "file's wire Bend_radius)"
                               : "")
    << ".</p>\n"
    << "<table class=\"sortable\"><thead><tr><th>input</th><th>cable</th><th>length</th>"
       "<th>diameter</th><th>material</th><th>supports</th><th>max deviation</th><th>rms</th>"
       "<th>min bend radius</th><th>twist</th><th>solver</th><th>notes</th></tr></thead><tbody>\n";
  std::vector<std::string> failures;
  for (const RelaxedFile& f : files) {
    if (!f.error.empty()) failures.push_back(f.input + ": " + f.error);
    for (size_t i = 0; i < f.cables.size(); ++i) {
      if (f.cables[i]) {
        h << Row(f.stem, f.drawing.cables[i].name, *f.cables[i]);
      } else {
        h << "<tr><td>" << HtmlEscape(f.stem) << "</td><td>" << HtmlEscape(f.drawing.cables[i].name)
          << "</td><td colspan=\"9\"><span class=\"badge fail\">failed</span> "
          << HtmlEscape(f.cable_errors[i]) << "</td><td></td></tr>\n";
      }
    }
  }
  h << "</tbody></table></section>\n";
  if (!failures.empty()) {
    h << "<section class=\"card\"><h2>Failures</h2><ul class=\"notes\">";
    for (const std::string& e : failures) h << "<li>" << HtmlEscape(e) << "</li>";
    h << "</ul></section>\n";
  }
  h << ClearanceReportSection(files) << MotionReportSection(files) << ToleranceReportSection(files);
  for (const RelaxedFile& f : files) {
    if (f.picture.empty()) continue;
    h << "<section class=\"card\"><h2>" << HtmlEscape(f.stem) << "</h2><figure><a href=\""
      << HtmlEscape(f.picture) << "\"><img src=\"" << HtmlEscape(f.picture) << "\" alt=\""
      << HtmlEscape(f.stem) << "\"></a><figcaption>" << HtmlEscape(f.input)
      << ": relaxed cables coloured by their distance to the drawn route (grey); squares = "
         "clamps, rings = clips, triangles = pins. Outputs: "
      << HtmlEscape(f.stem) << ".step, " << HtmlEscape(f.stem) << ".json.</figcaption></figure>";
    for (size_t i = 0; i < f.close_ups.size(); ++i) {
      h << "<figure><a href=\"" << HtmlEscape(f.close_ups[i]) << "\"><img src=\""
        << HtmlEscape(f.close_ups[i]) << "\" alt=\"" << HtmlEscape(f.drawing.cables[i].name)
        << "\"></a><figcaption>" << HtmlEscape(f.drawing.cables[i].name)
        << " alone</figcaption></figure>";
    }
    h << "</section>\n";
  }
  h << PageTail("cablefit relax, " + FormatSeconds(seconds));
  WriteFileAtomically(path, h.str());
}

}  // namespace cablefit::addin
