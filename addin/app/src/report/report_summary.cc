#include "cablefit/app/report/report_summary.h"

#include <map>
#include <sstream>

#include "cablefit/formats/atomic_file.h"
#include "cablefit/app/base/provenance.h"
#include "cablefit/app/base/report_html.h"

namespace cablefit::addin {

std::string RunSummaryHtml(const std::vector<SummaryRow>& rows, double total_seconds, int jobs,
                           const nlohmann::json& provenance) {
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
  if (provenance.is_object())
    h << "<section class=\"card\"><h2>Run</h2>" << ProvenanceHtml(provenance) << "</section>\n";

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
       "<th>interval</th><th class=\"num\">clamp</th>"
       "<th class=\"num\">shape: baseline max</th><th class=\"num\">shape: fitted max</th>"
       "<th class=\"num\">force: baseline max</th><th class=\"num\">force: fitted max</th>"
       "<th class=\"num\">time</th></tr></thead><tbody>\n";
  for (const SummaryRow& r : rows) {
    h << "<tr><td>";
    if (!r.link.empty())
      h << "<a href=\"" << HtmlEscape(r.link) << "\">" << HtmlEscape(r.name) << "</a>";
    else
      h << HtmlEscape(r.name);
    h << "</td><td>" << HtmlEscape(r.kind) << "</td>";
    if (!r.error.empty()) {
      h << "<td><span class=\"badge fail\">failed</span></td><td colspan=\"7\" class=\"error\">"
        << HtmlEscape(r.error) << "</td><td class=\"num\" data-value=\"" << r.seconds << "\">"
        << FormatSeconds(r.seconds) << "</td></tr>\n";
      continue;
    }
    h << "<td><span class=\"badge " << EffectBadge(r.effect) << "\">" << HtmlEscape(r.effect)
      << "</span></td><td class=\"num\" data-value=\"" << r.confidence << "\">"
      << FormatNumber(100.0 * r.confidence, 3) << " %</td><td>"
      // Force cases have no place along the cable: their interval and clamp are not shown.
      << (r.interval && r.kind != "force"
              ? FormatLength(r.interval->first) + " \u2013 " + FormatLength(r.interval->second)
              : "\u2013")
      << "</td><td class=\"num\" data-value=\"" << (r.clamp && r.kind != "force" ? *r.clamp : -1)
      << "\">" << (r.clamp && r.kind != "force" ? std::to_string(*r.clamp) : "\u2013") << "</td>";
    // Lengths and forces in columns of their own, so that a column sorts one quantity.
    const bool force = r.kind == "force";
    const std::string empty = "<td class=\"num\">\u2013</td><td class=\"num\">\u2013</td>";
    if (force) h << empty;
    h << "<td class=\"num\" data-value=\"" << r.baseline_max << "\">"
      << HtmlEscape(FormatDeviation(r.baseline_max, r.deviation_unit))
      << "</td><td class=\"num\" data-value=\"" << r.fitted_max << "\">"
      << HtmlEscape(FormatDeviation(r.fitted_max, r.deviation_unit)) << "</td>";
    if (!force) h << empty;
    h << "<td class=\"num\" data-value=\"" << r.seconds << "\">" << FormatSeconds(r.seconds)
      << "</td></tr>\n";
  }
  h << "</tbody></table>\n<p style=\"color:var(--muted);font-size:13px\">Click a column header "
       "to sort. Deviations: max distance between the recording and the nominal (baseline) or "
       "fitted model; force cases in the curve's unit.</p></section>\n</main>\n";
  h << PageTail("cablefit diagnose");
  return h.str();
}

void WriteRunSummary(const std::string& path, const std::vector<SummaryRow>& rows,
                     double total_seconds, int jobs, const nlohmann::json& provenance) {
  WriteFileAtomically(path, RunSummaryHtml(rows, total_seconds, jobs, provenance));
}

nlohmann::json DiagnoseSummaryJson(const std::vector<SummaryRow>& rows,
                                   const std::vector<std::string>& failures, double total_seconds,
                                   const nlohmann::json& provenance) {
  int diagnosed = 0;
  nlohmann::json cases = nlohmann::json::array();
  for (const SummaryRow& r : rows) {
    nlohmann::json c = {{"name", r.name}, {"seconds", r.seconds}};
    if (r.error.empty()) {
      ++diagnosed;
      c["status"] = "diagnosed";
      c["kind"] = r.kind;
      c["effect"] = r.effect;
      c["confidence"] = r.confidence;
      c["report"] = r.link;
    } else {
      c["status"] = "failed";
      c["error"] = r.error;
    }
    cases.push_back(std::move(c));
  }
  return {{"format", "cablefit-diagnose-summary/1"},
          {"command", "diagnose"},
          {"counts",
           {{"cases", rows.size()},
            {"diagnosed", diagnosed},
            {"failed", static_cast<int>(rows.size()) - diagnosed},
            {"failures", failures.size()}}},
          {"cases", std::move(cases)},
          {"failures", failures},
          {"seconds", total_seconds},
          {"provenance", provenance}};
}

}  // namespace cablefit::addin
