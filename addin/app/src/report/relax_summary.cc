#include "cablefit/app/report/relax_summary.h"

#include <cstdio>

#include "cablefit/app/base/provenance.h"
#include "cablefit/app/base/report_html.h"

namespace cablefit::addin {

RelaxCounts CountRelaxation(const std::vector<RelaxedFile>& files) {
  RelaxCounts c;
  c.inputs = static_cast<int>(files.size());
  for (const RelaxedFile& f : files) {
    if (!f.error.empty()) ++c.inputs_failed;
    for (size_t i = 0; i < f.cables.size(); ++i) {
      ++c.cables;
      const auto& r = f.cables[i];
      if (!r || !r->result.converged) {
        ++c.failed;
        continue;
      }
      ++c.relaxed;
      if (!r->result.solution.summary.stable) ++c.unstable;
      if (r->bend_flag) ++c.bend;
      if (r->taut) ++c.taut;
      if (r->max_deviation > c.worst) {
        c.worst = r->max_deviation;
        c.worst_cable = f.drawing.cables[i].name + " (" + f.stem + ")";
        c.worst_s = r->max_deviation_s;
      }
    }
  }
  return c;
}

std::string RelaxSummaryLine(const RelaxCounts& c, double seconds) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "relax: %d cable%s from %d input%s: %d relaxed, %d failed, %d below the "
                "bend-radius limit, %d taut, %d unstable",
                c.cables, c.cables == 1 ? "" : "s", c.inputs, c.inputs == 1 ? "" : "s", c.relaxed,
                c.failed, c.bend, c.taut, c.unstable);
  std::string line = buf;
  if (c.inputs_failed > 0) line += "; " + std::to_string(c.inputs_failed) + " input(s) failed";
  if (c.worst >= 0) {
    line += "; largest deviation " + FormatLength(c.worst) + " (" + c.worst_cable + " at s = " +
            FormatLength(c.worst_s) + ")";
  }
  return line + "; " + FormatSeconds(seconds);
}

nlohmann::json RelaxSummaryJson(const std::vector<RelaxedFile>& files,
                                const std::vector<std::string>& failures,
                                const std::string& config_path, double seconds) {
  const RelaxCounts c = CountRelaxation(files);
  nlohmann::json inputs = nlohmann::json::array();
  std::vector<std::pair<std::string, std::string>> sources;
  for (const RelaxedFile& f : files) {
    sources.emplace_back("input", f.input);
    nlohmann::json cables = nlohmann::json::array();
    for (size_t i = 0; i < f.cables.size(); ++i) {
      const auto& r = f.cables[i];
      nlohmann::json cable = {{"name", f.drawing.cables[i].name}};
      if (r && r->result.converged) {
        cable["status"] = "relaxed";
        cable["stable"] = r->result.solution.summary.stable;
        cable["bend_radius_too_tight"] = r->bend_flag;
        cable["taut"] = r->taut;
        cable["max_deviation"] = r->max_deviation;  // [m]
      } else {
        cable["status"] = "failed";
        cable["error"] = i < f.cable_errors.size() ? f.cable_errors[i] : std::string();
      }
      cables.push_back(std::move(cable));
    }
    nlohmann::json in = {{"path", f.input},
                         {"stem", f.stem},
                         {"status", !f.read_ok ? "unread" : f.error.empty() ? "ok" : "failed"},
                         {"cables", std::move(cables)}};
    if (!f.error.empty()) in["error"] = f.error;
    if (f.read_ok) {
      in["outputs"] = {f.stem + ".json", f.stem + ".step"};
      if (!f.picture.empty()) in["outputs"].push_back(f.picture);
    }
    inputs.push_back(std::move(in));
  }
  sources.emplace_back("config", config_path);
  return {{"format", "cablefit-relax-summary/1"},
          {"command", "relax"},
          {"counts",
           {{"inputs", c.inputs},
            {"inputs_failed", c.inputs_failed},
            {"cables", c.cables},
            {"relaxed", c.relaxed},
            {"failed", c.failed},
            {"unstable", c.unstable},
            {"bend_radius_too_tight", c.bend},
            {"taut", c.taut}}},
          {"inputs", std::move(inputs)},
          {"failures", failures},
          {"seconds", seconds},
          {"provenance", ProvenanceJson(sources)}};
}

}  // namespace cablefit::addin
