#include "cablefit/app/report/relax_report_sections.h"

#include <sstream>

#include "cablefit/app/base/report_html.h"

namespace cablefit::addin {

std::string ClearanceReportSection(const std::vector<RelaxedFile>& files) {
  std::ostringstream h;
  size_t measured = 0, violations = 0;
  for (const RelaxedFile& f : files) {
    measured += f.clearances.size();
    for (const ClearancePair& p : f.clearances) violations += p.violation() ? 1 : 0;
  }
  h << "<section class=\"card\"><h2>Clearance</h2><p>" << measured
    << " cable-solid and cable-cable pairs measured (surface to surface, where least; a cable "
       "is not checked against a solid it rests on or is held by); "
    << violations << " closer than the min_clearance asked in harness.json.</p>";
  if (violations > 0) {
    h << "<ul class=\"notes\">";
    for (const RelaxedFile& f : files)
      for (const ClearancePair& p : f.clearances)
        if (p.violation())
          h << "<li><span class=\"badge fail\">too close</span> " << HtmlEscape(f.stem) << ": "
            << HtmlEscape(ClearanceViolationText(p)) << "</li>";
    h << "</ul>";
  }
  h << "</section>\n";
  return h.str();
}

std::string MotionReportSection(const std::vector<RelaxedFile>& files) {
  std::ostringstream h;
  bool any = false;
  for (const RelaxedFile& f : files) {
    if (!f.motion) continue;
    if (!any) h << "<section class=\"card\"><h2>Motion</h2><ul class=\"notes\">";
    any = true;
    for (const std::string& line : MotionLines(*f.motion))
      h << "<li>" << HtmlEscape(f.stem) << ": " << HtmlEscape(line) << "</li>";
  }
  if (!any) return "";
  h << "</ul><p>Per pose figures in the JSON's per-cable <code>motion</code>.</p>";
  int figure = 0;
  for (const RelaxedFile& f : files) {
    const MotionPictures& pictures = f.motion_pictures;
    if (pictures.animation.empty()) continue;
    const std::string id = "motion" + std::to_string(figure++);  // also a JavaScript name
    h << "<figure><a href=\"" << HtmlEscape(pictures.animation) << "\"><img src=\""
      << HtmlEscape(pictures.animation) << "\" alt=\"" << HtmlEscape(f.stem)
      << " motion\"></a><figcaption>" << HtmlEscape(f.stem)
      << ": the motion, every pose (animated PNG); colour = distance from pose 0, grey line = "
         "pose 0.</figcaption></figure>";
    if (pictures.frames.empty()) continue;
    // The still frames under a slider: pick a pose and look at it.
    h << "<figure><img id=\"" << id << "\" src=\"" << HtmlEscape(pictures.frames[0])
      << "\" alt=\"" << HtmlEscape(f.stem) << " pose\"><figcaption><input type=\"range\" min=\"0\" "
      << "max=\"" << pictures.frames.size() - 1 << "\" value=\"0\" style=\"width:60%\" "
      << "aria-label=\"pose\" oninput=\"var f=" << id << "_frames[this.value];document."
      << "getElementById('" << id << "').src=f[0];document.getElementById('" << id
      << "-caption').textContent=f[1];\"> <span id=\"" << id << "-caption\">"
      << HtmlEscape(pictures.captions[0]) << "</span></figcaption></figure><script>var " << id
      << "_frames=[";
    for (size_t k = 0; k < pictures.frames.size(); ++k) {
      // JSON strings are valid JavaScript literals; '<' escaped so no "</script>" can appear.
      std::string pair = json::Json::array({pictures.frames[k], pictures.captions[k]})
                             .dump(-1, ' ', false, json::Json::error_handler_t::replace);
      std::string safe;
      for (char c : pair) safe += c == '<' ? std::string("\\u003c") : std::string(1, c);
      h << (k ? "," : "") << safe;
    }
    h << "];</script>";
  }
  h << "</section>\n";
  return h.str();
}

std::string ToleranceReportSection(const std::vector<RelaxedFile>& files) {
  std::ostringstream h;
  bool any = false;
  for (const RelaxedFile& f : files) {
    if (!f.tolerance) continue;
    if (!any) h << "<section class=\"card\"><h2>Tolerance envelope</h2><ul class=\"notes\">";
    any = true;
    for (const std::string& line : ToleranceLines(*f.tolerance))
      h << "<li>" << HtmlEscape(f.stem) << ": " << HtmlEscape(line) << "</li>";
  }
  if (!any) return "";
  h << "</ul><p>Per corner figures in the JSON's per-cable <code>tolerance</code>.</p></section>\n";
  return h.str();
}

}  // namespace cablefit::addin
