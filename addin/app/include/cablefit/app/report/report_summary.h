// The run summary of `cablefit diagnose` (DIR/report.html): one sortable row per case with its
// verdict and a link to the case report, failed inputs with their error.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace cablefit::addin {

struct SummaryRow {
  std::string name;        // case name, or the input file when it could not be read
  std::string link;        // relative link to the case report; empty when it failed
  std::string kind;        // "shape" / "force"
  std::string effect;      // empty when it failed
  double confidence = 0.0;
  std::optional<std::pair<double, double>> interval;  // [m]
  std::optional<int> clamp;
  double baseline_max = 0.0, fitted_max = 0.0;
  std::string deviation_unit = "m";
  double seconds = 0.0;
  std::string error;       // one-line problem when it failed
};

/// The whole summary page; `total_seconds` is the wall time of the run; `provenance` (a
/// ProvenanceJson object, may be null) is shown under the header.
std::string RunSummaryHtml(const std::vector<SummaryRow>& rows, double total_seconds, int jobs,
                           const nlohmann::json& provenance = nullptr);

/// Writes the summary to `path` atomically.
void WriteRunSummary(const std::string& path, const std::vector<SummaryRow>& rows,
                     double total_seconds, int jobs, const nlohmann::json& provenance = nullptr);

/// The `cablefit-diagnose-summary/1` object of --summary-json: counts, per case its status,
/// effect, confidence, output folder, seconds and error, every failure line, the run's seconds
/// and `provenance`. `failures` are the run's "<file>: <problem>" lines (also the paths that
/// held no case, which have no row).
nlohmann::json DiagnoseSummaryJson(const std::vector<SummaryRow>& rows,
                                   const std::vector<std::string>& failures, double total_seconds,
                                   const nlohmann::json& provenance);

}  // namespace cablefit::addin
