#include "cablefit/app/diagnose/diagnose_output.h"

#include <filesystem>
#include <map>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/force_curve_csv.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/app/base/provenance.h"

namespace cablefit::addin {
namespace {

nlohmann::json DeviationJson(const Deviation& d) {
  return {{"max_deviation", json::NumberOrNull(d.max)},
          {"rms_deviation", json::NumberOrNull(d.rms)}};
}

nlohmann::json IntervalJson(const std::optional<std::pair<double, double>>& interval) {
  return interval ? nlohmann::json::array({interval->first, interval->second})
                  : nlohmann::json(nullptr);
}

nlohmann::json ParametersJson(const std::map<std::string, double>& values,
                              const std::map<std::string, Vec3>& vectors) {
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [name, value] : values) parameters[name] = json::NumberOrNull(value);
  for (const auto& [name, v] : vectors) parameters[name] = json::ToJson(v);
  return parameters;
}

// A shape candidate's own fit, beyond the format's effect and score: its criterion, deviations
// (thinned points, the fits' accuracy), where and how it acts, and whether its fit converged.
void AddFitDetails(const EffectCandidate& e, nlohmann::json* c) {
  nlohmann::json parameters = ParametersJson(e.parameters, e.vectors);
  (*c)["bic"] = json::NumberOrNull(e.bic);
  (*c)["parameter_count"] = e.parameter_count;
  (*c)["max_deviation"] = json::NumberOrNull(e.max_deviation);
  (*c)["rms_deviation"] = json::NumberOrNull(e.rms_deviation);
  (*c)["interval"] = IntervalJson(e.interval);
  (*c)["clamp"] = e.clamp ? nlohmann::json(*e.clamp) : nlohmann::json(nullptr);
  (*c)["parameters"] = std::move(parameters);
  (*c)["converged"] = e.converged;
}

// Every effect found, dominant first: `[]` for none.
nlohmann::json EffectsJson(const DiagnosedCase& d) {
  nlohmann::json effects = nlohmann::json::array();
  for (const FoundEffectSummary& f : d.effects)
    effects.push_back({{"effect", f.effect},
                       {"clamp", f.clamp ? nlohmann::json(*f.clamp) : nlohmann::json(nullptr)},
                       {"interval", IntervalJson(f.interval)},
                       {"parameters", ParametersJson(f.parameters, f.vectors)},
                       {"share", json::NumberOrNull(f.share)}});
  return effects;
}

// The pairs of effects the selection weighed, best first, with their joint fits.
nlohmann::json CombinationsJson(const ShapeDiagnosis& s) {
  nlohmann::json out = nlohmann::json::array();
  for (const CombinationCandidate& c : s.combinations) {
    nlohmann::json effects = nlohmann::json::array(), clamps = nlohmann::json::array();
    for (size_t i = 0; i < c.effects.size(); ++i) {
      effects.push_back(ToString(c.effects[i]));
      clamps.push_back(c.clamps[i] ? nlohmann::json(*c.clamps[i]) : nlohmann::json(nullptr));
    }
    out.push_back({{"effects", std::move(effects)},
                   {"clamps", std::move(clamps)},
                   {"score", json::NumberOrNull(c.score)},
                   {"bic", json::NumberOrNull(c.bic)},
                   {"parameter_count", c.parameter_count},
                   {"max_deviation", json::NumberOrNull(c.max_deviation)},
                   {"rms_deviation", json::NumberOrNull(c.rms_deviation)},
                   {"converged", c.converged}});
  }
  return out;
}

}  // namespace

nlohmann::json DiagnosisToJson(const DiagnosedCase& d) {
  nlohmann::json parameters = ParametersJson(d.parameters, d.vectors);
  nlohmann::json candidates = nlohmann::json::array();
  for (const auto& [effect, score] : d.candidates) {
    nlohmann::json c = {{"effect", effect}, {"score", json::NumberOrNull(score)}};
    if (d.shape)
      for (const EffectCandidate& e : d.shape->candidates)
        if (ToString(e.effect) == effect) AddFitDetails(e, &c);
    candidates.push_back(std::move(c));
  }
  nlohmann::json j;
  j["format"] = kDiagnosisFormat;
  j["case"] = d.recording.name;
  j["effect"] = d.effect;
  j["confidence"] = json::NumberOrNull(d.confidence);
  j["interval"] = IntervalJson(d.interval);
  j["clamp"] = d.clamp ? nlohmann::json(*d.clamp) : nlohmann::json(nullptr);
  j["parameters"] = std::move(parameters);
  j["baseline"] = DeviationJson(d.baseline);
  j["fitted"] = DeviationJson(d.fitted);
  j["explained"] = d.explained;
  j["explanation"] = d.explanation;
  j["candidates"] = std::move(candidates);
  j["effects"] = EffectsJson(d);
  if (d.shape) j["combinations"] = CombinationsJson(*d.shape);
  if (d.shape) {
    // The test behind `explained`, so a reader can judge it.
    const ShapeAdequacy& a = d.shape->adequacy;
    j["adequacy"] = {{"test",
                      "chi-square of the best fit's offsets against noise_allowance times the "
                      "noise; explained when it is within the 99.9 % quantile"},
                     {"best_effect", ToString(a.best_effect)},
                     {"noise_sigma", json::NumberOrNull(a.noise_sigma)},
                     {"noise_allowance", json::NumberOrNull(a.noise_allowance)},
                     {"points", a.points},
                     {"degrees_of_freedom", a.degrees_of_freedom},
                     {"chi_square", json::NumberOrNull(a.chi_square)},
                     {"limit_999", json::NumberOrNull(a.limit)}};
  }
  if (d.kind == CaseKind::kForce) {
    nlohmann::json curves = nlohmann::json::array();
    for (const DiagnosedCurve& c : d.curves) {
      const ForceDiagnosis::Adequacy& a = c.diagnosis.adequacy;
      curves.push_back({{"curve", c.file},
                        {"runs", a.runs},
                        {"expected_runs", json::NumberOrNull(a.expected_runs)},
                        {"z", json::NumberOrNull(a.z)},
                        {"rms_fraction_of_peak", json::NumberOrNull(a.rms_fraction)},
                        {"passed", a.passed}});
    }
    j["adequacy"] = {{"test",
                      "runs test of the best fit's residual signs in recording order; explained "
                      "unless z < -3.09 (one-sided 99.9 %) with a residual above 0.5 % of the "
                      "peak response"},
                     {"curves", std::move(curves)}};
  }
  if (!d.notes.empty()) j["notes"] = d.notes;
  std::vector<std::pair<std::string, std::string>> inputs = {{"case", d.recording.case_file}};
  for (const RecordingRef& r : d.recording.recordings) inputs.emplace_back(ToString(r.kind), r.path);
  j["provenance"] = ProvenanceJson(inputs);
  return j;
}

std::vector<ModelCurveFile> ModelCurveFiles(const DiagnosedCase& d) {
  std::vector<ModelCurveFile> files;
  if (d.kind == CaseKind::kShape || d.curves.size() == 1) {
    const std::string rec = d.kind == CaseKind::kForce ? d.curves.front().file : "";
    files.push_back({"nominal.csv", "nominal", rec});
    files.push_back({"fitted.csv", "fitted", rec});
    return files;
  }
  // Two recordings a/bending.csv and b/bending.csv must not share one output pair: a leaf name
  // that repeats is replaced by the whole relative path with its separators as '-'.
  std::map<std::string, int> leaf_count;
  for (const DiagnosedCurve& c : d.curves) ++leaf_count[std::filesystem::path(c.file).filename().string()];
  for (const DiagnosedCurve& c : d.curves) {
    std::string leaf = std::filesystem::path(c.file).filename().string();
    if (leaf_count[leaf] > 1) {
      leaf = std::filesystem::path(c.file).lexically_normal().generic_string();
      for (char& ch : leaf) ch = ch == '/' ? '-' : ch;
    }
    files.push_back({"nominal-" + leaf, "nominal", c.file});
    files.push_back({"fitted-" + leaf, "fitted", c.file});
  }
  return files;
}

void WriteDiagnosisFiles(const std::string& dir, const DiagnosedCase& d) {
  const std::filesystem::path folder(dir);
  json::WriteJsonFile((folder / "diagnosis.json").string(), DiagnosisToJson(d));
  if (d.kind == CaseKind::kShape) {
    const Eigen::VectorXd s = UniformArcLengths(d.recording.nominal.length, kCenterlineRows);
    WriteCenterlineCsv((folder / "nominal.csv").string(),
                       SampleCenterline(d.shape->nominal_solution.centerline, s));
    WriteCenterlineCsv((folder / "fitted.csv").string(),
                       SampleCenterline(d.shape->fitted_solution.centerline, s));
    return;
  }
  for (const ModelCurveFile& f : ModelCurveFiles(d)) {
    for (const DiagnosedCurve& c : d.curves) {
      if (c.file != f.recording) continue;
      WriteForceCurveCsv((folder / f.name).string(), f.model == "nominal" ? c.nominal : c.fitted);
    }
  }
}

}  // namespace cablefit::addin
