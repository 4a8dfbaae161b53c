#include "cablefit/app/report/report_case.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "cablefit/formats/atomic_file.h"
#include "cablefit/app/diagnose/diagnose_output.h"
#include "cablefit/app/base/provenance.h"
#include "cablefit/app/base/report_html.h"

namespace cablefit::addin {
namespace {

std::string Fact(const std::string& key, const std::string& value_html) {
  return "<div class=\"fact\"><div class=\"k\">" + HtmlEscape(key) + "</div><div class=\"v\">" +
         value_html + "</div></div>\n";
}

std::string CurveUnit(const DiagnosedCase& d, bool x) {
  if (d.curves.empty()) return "";
  return x ? d.curves.front().diagnosis.x_unit : d.curves.front().diagnosis.y_unit;
}

std::string ParametersTable(const DiagnosedCase& d) {
  std::ostringstream h;
  if (d.parameters.empty() && d.vectors.empty()) {
    h << "<p>No parameters: the nominal model needs no change.</p>\n";
    return h.str();
  }
  h << "<table><thead><tr><th>parameter</th><th class=\"num\">value</th><th>unit</th></tr>"
       "</thead><tbody>\n";
  const std::string xu = CurveUnit(d, true), yu = CurveUnit(d, false);
  // A shape diagnosis states its parameters' units; a force diagnosis's follow the curve's.
  auto unit_of = [&](const std::string& name) {
    if (d.shape) {
      const auto it = d.shape->units.find(name);
      if (it != d.shape->units.end()) return it->second == "-" ? std::string("\u2013") : it->second;
    }
    return ParameterUnit(name, xu, yu);
  };
  for (const auto& [name, value] : d.parameters) {
    const std::string unit = unit_of(name);
    // The unit has its own column: the value cell carries only the number (and degrees for an
    // angle, which people read better than radians).
    std::string text = FormatNumber(value, 4);
    if (unit == "rad") {
      const std::string with_degrees = FormatParameter(value, unit);
      text += with_degrees.substr(with_degrees.find(" rad") + 4);
    }
    const std::string meaning = ParameterMeaning(name);
    h << "<tr><td><code>" << HtmlEscape(name) << "</code>"
      << (meaning.empty() ? "" : "<br><small>" + HtmlEscape(meaning) + "</small>")
      << "</td><td class=\"num\">" << HtmlEscape(text) << "</td><td>" << HtmlEscape(unit)
      << "</td></tr>\n";
  }
  for (const auto& [name, v] : d.vectors) {
    const std::string unit = unit_of(name);
    h << "<tr><td><code>" << HtmlEscape(name) << "</code></td><td class=\"num\">["
      << FormatNumber(v.x(), 4) << ", " << FormatNumber(v.y(), 4) << ", " << FormatNumber(v.z(), 4)
      << "]</td><td>" << HtmlEscape(unit) << " (world x, y, z)</td></tr>\n";
  }
  h << "</tbody></table>\n";
  return h.str();
}

// Every effect found with where it acts and its share of the mismatch (a pair's parts each).
std::string EffectsTable(const DiagnosedCase& d) {
  std::ostringstream h;
  h << "<table><thead><tr><th>#</th><th>effect</th><th>clamp</th><th>interval</th>"
       "<th class=\"num\">share</th><th>of the mismatch</th><th>parameters</th></tr></thead>"
       "<tbody>\n";
  for (std::size_t i = 0; i < d.effects.size(); ++i) {
    const FoundEffectSummary& f = d.effects[i];
    std::string parameters;
    for (const auto& [name, value] : f.parameters)
      parameters += (parameters.empty() ? "" : ", ") + name + " " + FormatNumber(value, 4);
    h << "<tr><td>" << i + 1 << "</td><td>" << HtmlEscape(f.effect) << "</td><td>"
      << (f.clamp ? std::to_string(*f.clamp) : "\u2013") << "</td><td>"
      << (f.interval ? HtmlEscape(FormatLength(f.interval->first) + " \u2013 " +
                                  FormatLength(f.interval->second))
                     : "\u2013")
      << "</td><td class=\"num\">" << FormatNumber(100.0 * f.share, 3)
      << " %</td><td><div class=\"bar\"><span style=\"width:"
      << std::max(0.0, std::min(100.0, 100.0 * f.share)) << "%\"></span></div></td><td>"
      << HtmlEscape(parameters) << "</td></tr>\n";
  }
  h << "</tbody></table>\n<p style=\"color:var(--muted);font-size:13px\">Share: the part of "
       "the nominal model's mismatch (sum of squared offsets) each effect removes in the joint "
       "fit, which is shared in proportion to the mismatch that comes back when the effect is "
       "left out.</p>\n";
  return h.str();
}

std::string CandidatesTable(const DiagnosedCase& d) {
  // Shape fits also carry each candidate's BIC (shown relative to the best, so the margin to the
  // runner-up is readable), its deviations, clamp, interval and whether its fit converged.
  std::vector<const EffectCandidate*> shape;
  bool deviations = false;
  double best_bic = 0.0;
  for (const auto& [effect, score] : d.candidates) {
    const EffectCandidate* c = nullptr;
    if (d.shape)
      for (const EffectCandidate& e : d.shape->candidates)
        if (ToString(e.effect) == effect) c = &e;
    shape.push_back(c);
    if (c) deviations = deviations || c->max_deviation > 0.0;
  }
  const bool has_bic = d.shape && !d.shape->candidates.empty();
  if (has_bic) best_bic = d.shape->candidates.front().bic;
  std::ostringstream h;
  h << "<table class=\"sortable\"><thead><tr><th>effect</th><th class=\"num\">score</th>"
       "<th>posterior weight</th>";
  if (has_bic) h << "<th class=\"num\">\u0394BIC</th><th class=\"num\">parameters</th>";
  if (deviations) h << "<th class=\"num\">max deviation</th><th class=\"num\">rms deviation</th>";
  if (has_bic) h << "<th>clamp</th><th>interval</th><th>fit</th>";
  h << "</tr></thead><tbody>\n";
  for (std::size_t i = 0; i < d.candidates.size(); ++i) {
    const auto& [effect, score] = d.candidates[i];
    h << "<tr" << (i == 0 ? " class=\"best\"" : "") << "><td>" << HtmlEscape(effect)
      // In per cent, as the verdict's confidence (the chosen effect's score) is given.
      << "</td><td class=\"num\" data-value=\"" << score << "\">" << FormatNumber(100.0 * score, 3)
      << " %"
      << "</td><td data-value=\"" << score << "\"><div class=\"bar\"><span style=\"width:"
      << std::max(0.0, std::min(100.0, 100.0 * score)) << "%\"></span></div></td>";
    const EffectCandidate* c = shape[i];
    if (has_bic) {
      if (c)
        h << "<td class=\"num\" data-value=\"" << c->bic - best_bic << "\">"
          << FormatNumber(c->bic - best_bic, 3) << "</td><td class=\"num\">" << c->parameter_count
          << "</td>";
      else
        h << "<td></td><td></td>";
    }
    if (deviations) {
      if (c)
        h << "<td class=\"num\" data-value=\"" << c->max_deviation << "\">"
          << FormatLength(c->max_deviation) << "</td><td class=\"num\" data-value=\""
          << c->rms_deviation << "\">" << FormatLength(c->rms_deviation) << "</td>";
      else
        h << "<td></td><td></td>";
    }
    if (has_bic) {
      if (c)
        h << "<td>" << (c->clamp ? std::to_string(*c->clamp) : "\u2013") << "</td><td>"
          << (c->interval ? FormatLength(c->interval->first) + " \u2013 " + FormatLength(c->interval->second)
                        : "\u2013") << "</td><td>"
          << (c->converged ? "converged" : "iteration limit") << "</td>";
      else
        h << "<td></td><td></td><td></td>";
    }
    h << "</tr>\n";
  }
  h << "</tbody></table>\n";
  return h.str();
}

std::string FilesList(const DiagnosedCase& d, const std::vector<CasePicture>& pictures) {
  std::ostringstream h;
  h << "<ul>\n<li><a href=\"diagnosis.json\">diagnosis.json</a> \u2013 the cable-diagnosis/1 "
       "result</li>\n";
  for (const ModelCurveFile& f : ModelCurveFiles(d)) {
    h << "<li><a href=\"" << HtmlEscape(f.name) << "\">" << HtmlEscape(f.name) << "</a> \u2013 "
      << f.model << " model"
      << (d.kind == CaseKind::kShape ? ", centre line s,x,y,z"
                                     : " on the rows of " + HtmlEscape(f.recording))
      << "</li>\n";
  }
  for (const CasePicture& p : pictures)
    h << "<li><a href=\"" << HtmlEscape(p.file) << "\">" << HtmlEscape(p.file) << "</a></li>\n";
  h << "</ul>\n";
  return h.str();
}

}  // namespace

// The case report top to bottom: long because HTML is written in reading order.
std::string CaseReportHtml(const DiagnosedCase& d, const std::vector<CasePicture>& pictures) {
  const RecordingCase& rc = d.recording;
  std::ostringstream h;
  h << PageHead(rc.name + " \u2013 cablefit diagnosis");
  h << "<header class=\"top\"><h1>" << HtmlEscape(rc.name) << " &nbsp;<span class=\"badge "
    << EffectBadge(d.effect) << "\">" << HtmlEscape(d.effect) << "</span></h1>"
    << "<div class=\"sub\">cablefit diagnose \u00b7 " << ToString(d.kind) << " recording \u00b7 "
    << HtmlEscape(rc.case_file) << " \u00b7 <a href=\"../report.html\">run summary</a></div>"
    << "</header>\n<main>\n";

  h << "<section class=\"card\"><h2>Verdict</h2><div class=\"facts\">\n"
    << Fact(d.effects.size() > 1 ? "dominant effect" : "effect", HtmlEscape(d.effect))
    << Fact("confidence", FormatNumber(100.0 * d.confidence, 3) + " %")
    ;
  // A force test has no place along the cable and no clamp to blame: those facts are shape's.
  if (d.kind == CaseKind::kShape) {
    h << Fact("interval", d.interval ? HtmlEscape(FormatLength(d.interval->first) + " \u2013 " +
                                                  FormatLength(d.interval->second))
                                     : "\u2013")
      << Fact("clamp", d.clamp ? std::to_string(*d.clamp) : "\u2013");
  }
  h
    << Fact("baseline max / rms", HtmlEscape(FormatDeviation(d.baseline.max, d.deviation_unit) +
                                             " / " +
                                             FormatDeviation(d.baseline.rms, d.deviation_unit)))
    << Fact("fitted max / rms", HtmlEscape(FormatDeviation(d.fitted.max, d.deviation_unit) + " / " +
                                           FormatDeviation(d.fitted.rms, d.deviation_unit)))
    << Fact("diagnosis time", FormatSeconds(d.seconds) + " (without writing the outputs)");
  if (d.kind == CaseKind::kShape) {
    h << Fact("fitted to", HtmlEscape(d.observation_source) + " (" +
                               std::to_string(d.observation.points.cols()) + " points)")
      << Fact("centre-point noise", HtmlEscape(FormatLength(d.observation.noise_sigma)));
    if (d.shape) {
      const ShapeAdequacy& a = d.shape->adequacy;
      h << Fact("explained",
                std::string(d.explained ? "yes" : "no") + " (best fit " +
                    HtmlEscape(ToString(a.best_effect)) + ": chi-square " + FormatNumber(a.chi_square, 3) +
                    " for " + std::to_string(a.degrees_of_freedom) + " d.o.f., 99.9 % limit " +
                    FormatNumber(a.limit, 3) + ")");
    }
  }
  if (d.kind == CaseKind::kForce && !d.curves.empty()) {
    // The worst curve's runs test: the one that decides `explained`.
    const DiagnosedCurve* worst = &d.curves.front();
    for (const DiagnosedCurve& c : d.curves)
      if (c.diagnosis.adequacy.z < worst->diagnosis.adequacy.z) worst = &c;
    const ForceDiagnosis::Adequacy& a = worst->diagnosis.adequacy;
    h << Fact("explained", std::string(d.explained ? "yes" : "no") + " (" +
                               HtmlEscape(worst->file) + ": " + std::to_string(a.runs) +
                               " residual sign runs, about " + FormatNumber(a.expected_runs, 3) +
                               " expected from noise, z " + FormatNumber(a.z, 3) + ")");
  }
  h << "</div>\n<p class=\"explanation\">" << HtmlEscape(d.explanation) << "</p>\n";
  if (d.effects.size() > 1) h << "<h3>Effects found</h3>\n" << EffectsTable(d);
  if (!d.notes.empty()) {
    h << "<ul class=\"notes\">\n";
    for (const std::string& n : d.notes) h << "<li>" << HtmlEscape(n) << "</li>\n";
    h << "</ul>\n";
  }
  h << "</section>\n";

  h << "<section class=\"card\"><h2>Pictures</h2>\n";
  for (const CasePicture& p : pictures) {
    h << "<figure><a href=\"" << HtmlEscape(p.file) << "\"><img src=\"" << HtmlEscape(p.file)
      << "\" alt=\"" << HtmlEscape(p.caption) << "\"></a><figcaption>" << HtmlEscape(p.caption)
      << "</figcaption></figure>\n";
  }
  h << "</section>\n";

  h << "<div class=\"grid2\"><section class=\"card\"><h2>Fitted parameters</h2>\n"
    << ParametersTable(d) << "</section>\n"
    << "<section class=\"card\"><h2>Candidates</h2>\n" << CandidatesTable(d)
    << "<p style=\"color:var(--muted);font-size:13px\">Score: posterior weight of each effect "
       "in per cent (the verdict's confidence is the chosen effect's, capped at 10 % when nothing "
       "explains the recording) from the Bayesian information criterion (\u0394BIC: difference to the best; above 10 is very "
       "strong evidence against); the best is listed first.</p></section></div>\n";

  h << "<section class=\"card\"><h2>Nominal set-up</h2><div class=\"facts\">\n"
    << Fact("length", HtmlEscape(FormatLength(rc.nominal.length)))
    << Fact("diameter", HtmlEscape(FormatLength(rc.nominal.material.diameter)))
    << Fact("bending stiffness EI",
            FormatNumber(rc.nominal.material.bending_stiffness, 4) + " N m\u00b2")
    << Fact("torsional stiffness GJ",
            FormatNumber(rc.nominal.material.torsional_stiffness, 4) + " N m\u00b2")
    << Fact("linear density", FormatNumber(rc.nominal.material.linear_density, 4) + " kg/m")
    << Fact("supports", std::to_string(rc.nominal.supports.size()))
    << "</div></section>\n";

  h << "<section class=\"card\"><h2>Files</h2>\n" << FilesList(d, pictures);
  {
    // The same facts as diagnosis.json's provenance: what this page was made from, by what.
    std::vector<std::pair<std::string, std::string>> sources = {{"case", d.recording.case_file}};
    for (const RecordingRef& r : d.recording.recordings) sources.emplace_back(ToString(r.kind), r.path);
    h << ProvenanceHtml(ProvenanceJson(sources));
  }
  h << "</section>\n";
  h << "</main>\n";
  h << PageTail("cablefit diagnose \u00b7 " + HtmlEscape(rc.name) + " \u00b7 " +
                FormatSeconds(d.seconds));
  return h.str();
}

void WriteCaseReport(const std::string& dir, const DiagnosedCase& d) {
  const std::vector<CasePicture> pictures = WriteCasePictures(dir, d);
  WriteFileAtomically((std::filesystem::path(dir) / "report.html").string(),
                      CaseReportHtml(d, pictures));
}

}  // namespace cablefit::addin
