#include "cablefit/app/report_summary.h"

#include <map>
#include <sstream>

#include "cablefit/formats/atomic_file.h"
#include "cablefit/app/report_html.h"

namespace cablefit::addin {

std::string RunSummaryHtml(const std::vector<SummaryRow>& rows, double total_seconds, int jobs) {
  int failed = 0;
  std::map<std::string, int> by_effect;
  for (const SummaryRow& r : rows) {
    if (!r.error.empty()) ++failed;
    else ++by_effect[r.effect];
  }
  std::ostringstream h;
  h << PageHead("cablefit diagnose \u2013 run summary");
  h << "<header class=\"top\"><h1>cablefit diagnose \u2013 run summary</h1><div class=\"sub\">"
    << rows.size() << " case(s), " << rows.size() - static_cast<std::size_t>(failed)
    << " diagnosed, " << failed << " failed \u00b7 " << FormatSeconds(total_seconds)
    << " wall time \u00b7 " << jobs << " job(s)</div></header>\n<main>\n";

  h << "<section class=\"card\"><h2>Effects found</h2><div class=\"facts\">\n";
  for (const auto& [effect, count] : by_effect)
    h << "<div class=\"fact\"><div class=\"k\">" << HtmlEscape(effect)
      << "</div><div class=\"v\">" << count << "</div></div>\n";
  if (failed)
    h << "<div class=\"fact\"><div class=\"k\">failed</div><div class=\"v error\">" << failed
      << "</div></div>\n";
  h << "</div></section>\n";

  h << "<section class=\"card\"><h2>Cases</h2>\n<table class=\"sortable\"><thead><tr>"
       "<th>case</th><th>kind</th><th>effect</th><th class=\"num\">confidence</th>"
       "<th>interval [m]</th><th class=\"num\">clamp</th><th class=\"num\">baseline max</th>"
       "<th class=\"num\">fitted max</th><th class=\"num\">time</th></tr></thead><tbody>\n";
  for (const SummaryRow& r : rows) {
    h << "<tr><td>";
    if (!r.link.empty())
      h << "<a href=\"" << HtmlEscape(r.link) << "\">" << HtmlEscape(r.name) << "</a>";
    else
      h << HtmlEscape(r.name);
    h << "</td><td>" << HtmlEscape(r.kind) << "</td>";
    if (!r.error.empty()) {
      h << "<td><span class=\"badge fail\">failed</span></td><td colspan=\"5\" class=\"error\">"
        << HtmlEscape(r.error) << "</td><td class=\"num\" data-value=\"" << r.seconds << "\">"
        << FormatSeconds(r.seconds) << "</td></tr>\n";
      continue;
    }
    h << "<td><span class=\"badge " << EffectBadge(r.effect) << "\">" << HtmlEscape(r.effect)
      << "</span></td><td class=\"num\" data-value=\"" << r.confidence << "\">"
      << FormatNumber(100.0 * r.confidence, 3) << " %</td><td>"
      << (r.interval ? FormatInterval(*r.interval) : "\u2013")
      << "</td><td class=\"num\" data-value=\"" << (r.clamp ? *r.clamp : -1) << "\">"
      << (r.clamp ? std::to_string(*r.clamp) : "\u2013") << "</td><td class=\"num\" data-value=\""
      << r.baseline_max << "\">" << HtmlEscape(FormatDeviation(r.baseline_max, r.deviation_unit))
      << "</td><td class=\"num\" data-value=\"" << r.fitted_max << "\">"
      << HtmlEscape(FormatDeviation(r.fitted_max, r.deviation_unit))
      << "</td><td class=\"num\" data-value=\"" << r.seconds << "\">" << FormatSeconds(r.seconds)
      << "</td></tr>\n";
  }
  h << "</tbody></table>\n<p style=\"color:var(--muted);font-size:13px\">Click a column header "
       "to sort. Deviations: max distance between the recording and the nominal (baseline) or "
       "fitted model; force cases in the curve's unit.</p></section>\n</main>\n";
  h << PageTail("cablefit diagnose");
  return h.str();
}

void WriteRunSummary(const std::string& path, const std::vector<SummaryRow>& rows,
                     double total_seconds, int jobs) {
  WriteFileAtomically(path, RunSummaryHtml(rows, total_seconds, jobs));
}

}  // namespace cablefit::addin
