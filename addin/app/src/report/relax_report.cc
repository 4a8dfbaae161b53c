#include "cablefit/app/report/relax_report.h"
#include "cablefit/app/report/relax_report_sections.h"

#include "cablefit/app/clearance/relax_clearance.h"
#include "cablefit/app/output/relax_file.h"

#include <cctype>
#include <algorithm>
#include <cmath>
#include <limits>
#include <ctime>
#include <filesystem>
#include <mutex>
#include <set>
#include <sstream>
#if defined(__linux__)
#include <sys/resource.h>
#include <unistd.h>
#endif

#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/deviation_views.h"
#include "cablefit/formats/png_file.h"
#include "cablefit/app/base/provenance.h"
#include "cablefit/app/report/relax_summary.h"
#include "cablefit/app/base/report_html.h"
#include "base/render_lock.h"

namespace cablefit::addin {

namespace {

// The smallest top of the deviation colour scale [mm]: below a millimetre a drawing and a
// relaxed cable agree for a harness engineer, so such cables stay dark.
constexpr double kColourScaleFloorMm = 1.0;

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
      // The cable's name where it moved most, with how far: which tube is which, and the
      // point the report's table gives.
      if (r->deviation.size() == r->relaxed.size() && r->deviation.size() > 0) {
        Eigen::Index at = 0;
        r->deviation.maxCoeff(&at);
        scene.labels.push_back({r->relaxed.points.col(at),
                                drawn.name + ": " + FormatLength(r->deviation[at])});
      }
      for (const SupportSpec& sp : r->setup.spec.supports) {
        scene.supports.push_back({MarkerOf(sp.kind), sp.position, " "});
      }
    } else {
      tube.centreline = drawn.centreline;
      tube.name = drawn.name + " (failed)";
      tube.flat_colour = kFailedColour;
      if (drawn.centreline.size() > 0)
        scene.labels.push_back({drawn.centreline.points.col(drawn.centreline.size() / 2),
                                drawn.name + ": FAILED"});
    }
    scene.tubes.push_back(std::move(tube));
  }
  // The parts around the cables (clips, brackets, ducts), for context; a close-up shows only
  // the ones near its cable (the views frame the cables, not the parts).
  if (only < 0)
    for (const DrawnSolid& solid : f.drawing.solids) scene.solids.push_back({solid.name, solid.mesh});
  // A floor under the colour scale: a cable that moved by micrometres is not a hot spot.
  double largest = 0.0;
  for (const SceneTube& t : scene.tubes)
    if (t.deviation.size() > 0) largest = std::max(largest, t.deviation.maxCoeff());
  ColourScale scale;
  scale.min = 0.0;
  scale.max = std::max(1e3 * largest, kColourScaleFloorMm);
  scene.colour_scale = scale;
  return scene;
}

// A material source as the table shows it: a file by its name only (the full path is in the
// cell's tooltip and the JSON), anything else as it is.
std::string MaterialCell(const CableSetup& setup) {
  if (setup.material_defaulted) return "default estimate";
  const std::filesystem::path p(setup.material_source);
  if (p.has_parent_path() && p.has_extension() && p.extension().string().size() <= 5)
    return "<span title=\"" + HtmlEscape(setup.material_source) + "\">" +
           HtmlEscape(p.filename().string()) + "</span>";
  return HtmlEscape(setup.material_source);
}

// A sortable numeric cell: the script sorts by data-value, the reader sees `text`.
std::string NumberCell(double value, const std::string& text) {
  std::ostringstream h;
  h << "<td class=\"num\"";
  if (std::isfinite(value)) h << " data-value=\"" << value << "\"";
  h << ">" << text << "</td>";
  return h.str();
}

// How many supports, and what each one carries: the force (and moment, for a clamp) it exerts
// on the cable, which is what a clip or connector has to hold.
std::string SupportsText(const CableRelaxation& r) {
  std::string text = std::to_string(r.setup.spec.supports.size());
  const auto& reactions = r.result.solution.reactions;
  for (size_t k = 0; k < r.setup.spec.supports.size() && k < reactions.size(); ++k) {
    text += "<br><small>" + std::string(ToString(r.setup.spec.supports[k].kind)) + " " +
            FormatNumber(reactions[k].force.norm()) + " N";
    if (r.setup.spec.supports[k].kind == SupportKind::kClamp)
      text += ", " + FormatNumber(reactions[k].moment.norm()) + " N m";
    text += "</small>";
  }
  return text;
}

// A name that may break after '_', '-' and '#' (long input and cable names would otherwise
// widen the table past the window).
std::string BreakableName(const std::string& name) {
  std::string out;
  for (const char c : name) {
    out += HtmlEscape(std::string(1, c));  // per character: an entity is never cut
    if (c == '_' || c == '-' || c == '#') out += "<wbr>";
  }
  return out;
}

std::string Row(const std::string& file, const std::string& cable, const CableRelaxation& r) {
  std::ostringstream h;
  const bool ok = r.result.converged && r.result.solution.summary.stable;
  double least_slack = std::numeric_limits<double>::infinity();
  for (const CableRelaxation::Stretch& st : r.stretches) least_slack = std::min(least_slack, st.slack);
  const double relaxed_length = r.relaxed.size() > 1 ? r.relaxed.ChordLength() : r.setup.spec.length;
  // Twelve columns fit a 1400 px window: related figures share a cell, the second one small.
  h << "<tr><td>" << BreakableName(file) << "</td><td>" << BreakableName(cable) << "</td>"
    << NumberCell(r.setup.drawn_length, FormatLength(r.setup.drawn_length) +
                                            "<br><small>relaxed " + FormatLength(relaxed_length) +
                                            "</small>")
    << NumberCell(least_slack, std::isfinite(least_slack)
                                   ? FormatNumber(100 * least_slack) + " %" +
                                         (r.taut ? " <span class=\"badge fail\">taut</span>" : "")
                                   : "\u2013")
    << NumberCell(r.max_tension, std::isfinite(r.max_tension) ? FormatNumber(r.max_tension) + " N"
                                                             : "\u2013")
    << NumberCell(r.setup.spec.material.diameter,
                  FormatLength(r.setup.spec.material.diameter) +
                      (r.setup.diameter_defaulted ? " (assumed)" : "") + "<br><small>" +
                      MaterialCell(r.setup) + "</small>")
    << NumberCell(static_cast<double>(r.setup.spec.supports.size()), SupportsText(r));
  std::string deviation = FormatLength(r.max_deviation) + "<br><small>at s = " +
                          FormatLength(r.max_deviation_s) + "</small>";
  if (r.springback_max && r.sag_max)
    deviation += "<br><small>springback " + FormatLength(*r.springback_max) + ", sag " +
                 FormatLength(*r.sag_max) + "</small>";
  h << NumberCell(r.max_deviation, deviation)
    << NumberCell(r.rms_deviation, FormatLength(r.rms_deviation));
  std::string bend = std::isfinite(r.min_bend_radius) ? FormatLength(r.min_bend_radius) : "straight";
  bend += "<br><small>limit " + FormatLength(r.bend_limit) + "</small>";
  if (r.bend_flag) bend += " <span class=\"badge fail\">too tight</span>";
  h << NumberCell(r.min_bend_radius, bend)
    << "<td><span class=\"badge " << (ok ? "ok" : "fail") << "\">"
    << (r.result.converged ? (r.result.solution.summary.stable ? "stable" : "unstable")
                           : "not converged")
    << "</span>"
    << (std::isfinite(r.result.solution.twist_angle)
            ? "<br><small>twist " + FormatNumber(r.result.solution.twist_angle * 180 / M_PI) +
                  "\u00b0</small>"
            : std::string())
    << "</td>"
    << "<td class=\"notes\"><small>";
  if (!r.setup.junction.empty()) h << "junction " << HtmlEscape(r.setup.junction) << "<br>";
  // The default-material note is said once above the table.
  for (const std::string& n : r.setup.notes)
    if (n != kDefaultMaterialNote) h << HtmlEscape(n) << "<br>";
  h << "</small></td></tr>\n";
  return h.str();
}

}  // namespace

namespace {

constexpr int kWarmUpNice = 10;

RenderOptions PictureOptions() {
  RenderOptions options;
  options.width = 1400;
  options.height = 900;
  return options;
}

void RenderToPng(const std::string& path, const Scene& scene) {
  const RenderOptions options = PictureOptions();
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

void WarmUpDeviationPictures() noexcept {
#if defined(__linux__)
  // Behind the relax on a busy core: this thread and the rasteriser threads it starts (they
  // inherit its nice value) take what the solver leaves.
  ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), kWarmUpNice);
#endif
  try {
    std::lock_guard lock(RenderMutex());
    WarmUpRenderer(PictureOptions());
  } catch (...) {  // NOLINT(bugprone-empty-catch): the picture reports what fails
  }
}

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
// deviation and where; then which tool made the page, when, from which files.
std::string VerdictSection(const std::vector<RelaxedFile>& files, const HarnessConfig& config,
                           double seconds) {
  const RelaxCounts c = CountRelaxation(files);
  std::ostringstream h;
  h << "<section class=\"card\"><h2>Verdict</h2><p><b>" << c.cables << " cable"
    << (c.cables == 1 ? "" : "s") << "</b> from " << files.size() << " input"
    << (files.size() == 1 ? "" : "s") << ": " << c.relaxed << " relaxed, "
    << "<span class=\"badge " << (c.failed ? "fail" : "ok") << "\">" << c.failed
    << " failed</span>, "
    << "<span class=\"badge " << (c.bend ? "fail" : "ok") << "\">" << c.bend
    << " below the bend-radius limit</span>, "
    << "<span class=\"badge " << (c.taut ? "fail" : "ok") << "\">" << c.taut << " taut</span>, "
    << c.unstable << " unstable";
  if (c.inputs_failed) h << "; " << c.inputs_failed << " input(s) failed";
  h << ".";
  if (c.worst >= 0)
    h << " Largest deviation from the drawing: <b>" << FormatLength(c.worst) << "</b>, "
      << HtmlEscape(c.worst_cable) << " at s = " << FormatLength(c.worst_s) << ".";
  h << "</p>";
  std::vector<std::pair<std::string, std::string>> sources;
  for (const RelaxedFile& f : files) sources.emplace_back("input", f.input);
  sources.emplace_back("config", config.path);
  h << ProvenanceHtml(ProvenanceJson(sources)) << "</section>\n";
  (void)seconds;
  return h.str();
}

}  // namespace

// The page top to bottom (header, verdict, cards, tables, pictures): long because HTML is
// written in reading order.
void WriteRelaxReport(const std::string& path, const std::vector<RelaxedFile>& files,
                      const HarnessConfig& config, double seconds) {
  auto any_own_bend_limit = [](const std::vector<RelaxedFile>& fs) {
    for (const RelaxedFile& f : fs)
      for (const auto& c : f.cables)
        if (c && c->setup.min_bend_radius_limit > 0) return true;
    return false;
  };
  bool any_default_material = false;
  for (const RelaxedFile& f : files)
    for (const auto& c : f.cables) any_default_material = any_default_material || (c && c->setup.material_defaulted);
  std::ostringstream h;
  h << PageHead("cablefit relax");
  h << "<header class=\"top\"><h1>cablefit relax</h1><div class=\"sub\">" << files.size()
    << " input" << (files.size() == 1 ? "" : "s") << " &middot; " << HtmlEscape(UtcNow())
    << " &middot; " << FormatSeconds(seconds) << " wall time"
    << (config.path.empty() ? "" : " &middot; config " + HtmlEscape(std::filesystem::path(config.path).filename().string()))
    << "</div></header>\n<main>\n";
  h << VerdictSection(files, config, seconds);
  h << "<section class=\"card\"><h2>Relaxed cables</h2>\n<p>Each cable is solved as a Kirchhoff "
       "rod under gravity from its drawn shape (nearest equilibrium), ends clamped at their drawn "
       "pose unless harness.json says otherwise. Deviation = distance of the relaxed centreline "
       "to the drawn route; s = arc length from the cable's start. Slack = (length - support "
       "distance) / support distance of the tightest stretch between two supports. All lengths "
       "in mm. Bend radius flagged below "
    << FormatNumber(config.min_bend_radius_factor) << " diameters"
    << (any_own_bend_limit(files) ? ", or below the cable's own limit where its data give one (a KBL "
                                 "file's wire Bend_radius)"
                               : "")
    << ".</p>\n";
  if (any_default_material)
    h << "<p><b>Default material:</b> cables marked \"default estimate\" have no material in "
      << (config.path.empty() ? "a harness.json (give one with --config)" : "the harness.json")
      << "; " << HtmlEscape(kDefaultMaterialNote) << ".</p>\n";
  h << "<div class=\"table-wrap\"><table class=\"sortable dense\"><thead><tr><th>input</th>"
       "<th>cable</th><th class=\"num\">length<br>drawn, relaxed</th>"
       "<th class=\"num\">slack</th><th class=\"num\">max<br>tension</th>"
       "<th class=\"num\">diameter<br>material</th><th class=\"num\">supports<br>reactions</th>"
       "<th class=\"num\">max deviation<br>where</th><th class=\"num\">rms</th>"
       "<th class=\"num\">min bend radius<br>limit</th><th>solver</th>"
       "<th>notes</th></tr></thead><tbody>\n";
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
  h << "</tbody></table></div></section>\n";
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
  h << "</main>\n";
  h << PageTail(HtmlEscape(ToolVersion()) + " &middot; relax &middot; " + FormatSeconds(seconds));
  WriteFileAtomically(path, h.str());
}

}  // namespace cablefit::addin
