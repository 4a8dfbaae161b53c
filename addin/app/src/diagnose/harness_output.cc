// diagnosis.json (harness-diagnosis/1), the centrelines and the report of a diagnosed harness.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <sstream>

#include "cablefit/app/base/provenance.h"
#include "cablefit/app/base/report_html.h"
#include "cablefit/app/diagnose/harness_case.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/deviation_views.h"
#include "cablefit/formats/png_file.h"
#include "base/render_lock.h"

namespace cablefit::addin {
namespace {

namespace fs = std::filesystem;
using json::Json;

// A branch name as part of a file name: letters, digits, '-', '_' and '.' kept, the rest '_'
// (a name must not reach outside the output folder).
std::string FileStem(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return out.empty() ? "branch" : out;
}

std::string BranchName(const DiagnosedHarness& d, int b) {
  return b >= 0 ? d.recording.nominal.branches[static_cast<size_t>(b)].name : "";
}

// Where an effect acts, in words: "on trunk_1", "at breakout", "at support 1 of trunk_2".
std::string Place(const DiagnosedHarness& d, const HarnessFoundEffect& f) {
  if (f.junction >= 0) return "at " + d.recording.nominal.junctions[static_cast<size_t>(f.junction)].name;
  if (f.support >= 0) return "at support " + std::to_string(f.support) + " of " + BranchName(d, f.branch);
  return "on " + BranchName(d, f.branch);
}

Json EffectJson(const DiagnosedHarness& d, const HarnessFoundEffect& f) {
  Json j = {{"effect", ToString(f.effect)},
            {"branch", f.branch >= 0 ? Json(BranchName(d, f.branch)) : Json(nullptr)},
            {"junction", f.junction >= 0 ? Json(d.recording.nominal.junctions[static_cast<size_t>(f.junction)].name)
                                         : Json(nullptr)},
            {"support", f.support >= 0 ? Json(f.support) : Json(nullptr)},
            {"interval", f.interval ? Json::array({f.interval->first, f.interval->second}) : Json(nullptr)},
            {"share", f.share}};
  Json params = Json::object();
  for (const auto& [k, v] : f.parameters) params[k] = json::NumberOrNull(v);
  j["parameters"] = params;
  j["units"] = f.units;
  return j;
}

// Per centreline vertex, the offset of the recorded point nearest in arc length (NaN-free: a
// tube needs a value everywhere; unseen stretches take their nearest seen one).
Eigen::VectorXd VertexDeviation(const Polyline& c, const Eigen::VectorXd& s, const Eigen::VectorXd& v) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(c.size());
  if (s.size() == 0) return out;
  for (int i = 0; i < c.size(); ++i) {
    Eigen::Index best = 0;
    (s.array() - c.s[i]).abs().minCoeff(&best);
    out[i] = v[best];
  }
  return out;
}

Scene HarnessScene(const DiagnosedHarness& d, bool fitted, const std::string& title) {
  Scene scene;
  scene.title = title;
  const NetworkSpec& spec = d.recording.nominal;
  const HarnessDiagnosis& g = d.diagnosis;
  const std::vector<Polyline>& shapes = fitted ? g.fitted : g.nominal;
  scene.gravity = spec.gravity;
  for (size_t b = 0; b < spec.branches.size(); ++b) {
    SceneTube t;
    t.name = spec.branches[b].name;
    t.centreline = shapes[b];
    t.radius = 0.5 * spec.branches[b].material.diameter;
    const HarnessBranchDeviation& dev = g.branches[b];
    const Eigen::VectorXd& v = fitted ? dev.fitted_offset : dev.nominal_offset;
    if (v.size() > 0) t.deviation = VertexDeviation(t.centreline, dev.s, v);
    scene.tubes.push_back(t);
    const ShapeObservation& o = d.observation.branches[b];
    if (o.points.cols() > 1) scene.ghosts.push_back({spec.branches[b].name + " recorded", o.points, {110, 110, 110}});
    for (const SupportSpec& sp : spec.branches[b].supports) scene.supports.push_back({MarkerOf(sp.kind), sp.position, " "});
    if (dev.points > 0) {
      Eigen::Index top = 0;
      (fitted ? dev.fitted_offset : dev.nominal_offset).maxCoeff(&top);
      scene.labels.push_back({SampleCenterline(shapes[b], Eigen::VectorXd::Constant(1, dev.s[top])).points.col(0),
                              spec.branches[b].name});
    }
  }
  for (const ObstacleSpec& o : spec.obstacles) scene.solids.push_back({o.name, o.mesh});
  if (fitted)
    for (const HarnessFoundEffect& f : g.effects)
      if (f.branch >= 0 && f.interval)
        scene.highlights.push_back({f.branch, f.interval->first, std::max(f.interval->second, f.interval->first + 1e-3)});
  scene.highlight_label = "where the effect acts";
  scene.scan_points = d.shown_points;
  return scene;
}

void WritePicture(const fs::path& dir, const DiagnosedHarness& d) {
  const Scene nominal = HarnessScene(
      d, false, "nominal harness: max deviation " + FormatLength(d.diagnosis.baseline_max));
  const Scene fitted = HarnessScene(d, true, "fitted harness (" + HarnessEffectsName(d) +
                                                 "): max deviation " + FormatLength(d.diagnosis.fitted_max));
  RenderOptions ro;
  ro.width = 1600;
  ro.height = 1150;
  ro.show_scan_points = d.shown_points.cols() > 0;
  Image views;
  {
    std::lock_guard lock(RenderMutex());
    views = RenderSideBySide(nominal, fitted, ro);
  }
  WritePng((dir / "deviation-views.png").string(), views);
}

std::string Report(const DiagnosedHarness& d, const Json& j) {
  const HarnessDiagnosis& g = d.diagnosis;
  std::ostringstream h;
  h << PageHead("cablefit harness diagnosis: " + d.recording.name);
  h << "<h1>" << HtmlEscape(d.recording.name) << "</h1>";
  h << "<section class=\"card\"><h2>Verdict</h2><p>" << EffectBadge(HarnessEffectsName(d)) << " ";
  if (!g.explained) {
    h << "Not explained: " << HtmlEscape(g.reason) << ".";
  } else if (g.effects.empty()) {
    h << "The recorded harness matches its nominal set-up within the recording's noise.";
  } else {
    h << "confidence " << FormatNumber(100 * g.confidence, 3) << " %.";
  }
  h << " Largest deviation " << FormatLength(g.baseline_max) << " (nominal), "
    << FormatLength(g.fitted_max) << " (fitted).</p>";
  if (!g.effects.empty()) {
    h << "<ul class=\"notes\">";
    for (const HarnessFoundEffect& f : g.effects) {
      h << "<li><b>" << ToString(f.effect) << "</b> " << HtmlEscape(Place(d, f));
      if (f.interval) h << ", s " << FormatInterval(*f.interval);
      for (const auto& [k, v] : f.parameters) {
        const auto u = f.units.find(k);
        h << ", " << HtmlEscape(k) << " " << FormatParameter(v, u == f.units.end() ? "" : u->second);
      }
      h << " (share " << FormatNumber(100 * f.share, 3) << " %)</li>";
    }
    h << "</ul>";
  }
  h << "</section>";
  h << "<section class=\"card\"><h2>Branches</h2><table><tr><th>branch</th><th>points</th>"
       "<th>nominal max</th><th>where</th><th>fitted max</th></tr>";
  for (size_t b = 0; b < g.branches.size(); ++b) {
    const HarnessBranchDeviation& dev = g.branches[b];
    h << "<tr><td>" << HtmlEscape(BranchName(d, static_cast<int>(b))) << "</td><td>" << dev.points << "</td><td>"
      << FormatLength(dev.nominal_max) << "</td><td>"
      << (dev.mismatch ? "s " + FormatInterval(*dev.mismatch) : std::string("-")) << "</td><td>"
      << FormatLength(dev.fitted_max) << "</td></tr>";
  }
  h << "</table></section>";
  h << "<section class=\"card\"><h2>Deviation</h2><img src=\"deviation-views.png\" "
       "style=\"max-width:100%\" alt=\"deviation views\"><p>Each branch coloured by the deviation "
       "of the recording from it, nominal harness (top) and fitted harness (bottom); dark line: "
       "the recorded centre line; red halo: where the effect acts.</p></section>";
  if (!d.notes.empty()) {
    h << "<section class=\"card\"><h2>Notes</h2><ul class=\"notes\">";
    for (const std::string& n : d.notes) h << "<li>" << HtmlEscape(n) << "</li>";
    h << "</ul></section>";
  }
  h << PageTail(ProvenanceHtml(j.at("provenance")));
  return h.str();
}

}  // namespace

std::string HarnessEffectsName(const DiagnosedHarness& d) {
  const HarnessDiagnosis& g = d.diagnosis;
  if (!g.explained) return "not explained";
  if (g.effects.empty()) return "none";
  std::string out;
  for (const HarnessFoundEffect& f : g.effects)
    out += (out.empty() ? "" : " + ") + std::string(ToString(f.effect)) + " " + Place(d, f);
  return out;
}

Json HarnessDiagnosisToJson(const DiagnosedHarness& d) {
  const HarnessDiagnosis& g = d.diagnosis;
  Json j;
  j["format"] = "harness-diagnosis/1";
  j["case"] = d.recording.name;
  j["verdict"] = !g.explained ? "not explained" : g.effects.empty() ? "none" : "explained";
  j["explained"] = g.explained;
  if (!g.explained) j["reason"] = g.reason;
  j["effect"] = g.explained && !g.effects.empty() ? ToString(g.effects.front().effect) : (g.explained ? "none" : "not_explained");
  j["confidence"] = g.confidence;
  Json effects = Json::array();
  for (const HarnessFoundEffect& f : g.effects) effects.push_back(EffectJson(d, f));
  j["effects"] = effects;
  Json branches = Json::array();
  for (size_t b = 0; b < g.branches.size(); ++b) {
    const HarnessBranchDeviation& dev = g.branches[b];
    branches.push_back(
        {{"name", BranchName(d, static_cast<int>(b))},
         {"points", dev.points},
         {"scan_points", b < d.split_points.size() ? Json(d.split_points[b]) : Json(nullptr)},
         {"deviation",
          {{"nominal", {{"max", dev.nominal_max}, {"rms", dev.nominal_rms}, {"max_s", dev.nominal_max_s}}},
           {"fitted", {{"max", dev.fitted_max}, {"rms", dev.fitted_rms}}}}},
         {"mismatch", dev.mismatch ? Json::array({dev.mismatch->first, dev.mismatch->second}) : Json(nullptr)}});
  }
  j["branches"] = branches;
  j["baseline"] = {{"max", g.baseline_max}};
  j["fitted"] = {{"max", g.fitted_max}};
  j["improvement"] = g.fitted_max > 0 ? g.baseline_max / g.fitted_max : 0.0;
  j["noise_sigma"] = g.noise_sigma;
  j["model_error"] = g.model_error;
  j["element_length"] = g.element_length;
  j["adequacy"] = {{"chi_square", g.chi_square}, {"limit", g.limit}};
  Json candidates = Json::array();
  for (size_t k = 0; k < g.candidates.size() && k < 12; ++k) {
    const HarnessCandidate& c = g.candidates[k];
    Json names = Json::array();
    for (const HarnessFoundEffect& f : c.effects) names.push_back(std::string(ToString(f.effect)) + " " + Place(d, f));
    candidates.push_back({{"effects", names}, {"bic", c.bic}, {"rms", c.rms}, {"max_deviation", c.max_deviation}});
  }
  j["candidates"] = candidates;
  j["observation"] = {{"source", d.observation_source}, {"scan_points", d.scan_points}};
  j["notes"] = d.notes;
  j["forward_solves"] = g.forward_solves;
  j["seconds"] = d.seconds;
  j["provenance"] = ProvenanceJson({{"case", d.recording.case_file}});
  return j;
}

void WriteHarnessCase(const std::string& dir, const DiagnosedHarness& d) {
  const fs::path out(dir);
  const Json j = HarnessDiagnosisToJson(d);
  json::WriteJsonFile((out / "diagnosis.json").string(), j);
  const NetworkSpec& spec = d.recording.nominal;
  for (size_t b = 0; b < spec.branches.size(); ++b) {
    for (bool fitted : {false, true}) {
      const Polyline& c = fitted ? d.diagnosis.fitted[b] : d.diagnosis.nominal[b];
      const double length = c.s[c.size() - 1];
      const Polyline sampled = SampleCenterline(c, UniformArcLengths(length, 201));
      WriteCenterlineCsv((out / ((fitted ? "fitted-" : "nominal-") + FileStem(spec.branches[b].name) + ".csv")).string(),
                         sampled);
    }
  }
  WritePicture(out, d);
  WriteFileAtomically((out / "report.html").string(), Report(d, j));
}

}  // namespace cablefit::addin
