#include "cablefit/app/pipeline/diagnose_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cablefit/app/base/batch_pool.h"
#include "cablefit/app/diagnose/diagnose_output.h"
#include "cablefit/app/diagnose/harness_case.h"
#include "cablefit/app/output/output_folder.h"
#include "cablefit/app/base/provenance.h"
#include "cablefit/app/report/report_case.h"
#include "cablefit/app/base/report_html.h"
#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/file_kind.h"
#include "cablefit/formats/harness_case_reader.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Output folders, one per case, unique after sanitising ("left cable" and "left_cable" would
/// share one) and never the run summary's own file name. Decided before any case runs, in the
/// sorted order of the case files, so they do not depend on which case finishes first.
std::vector<std::string> CaseFolders(const CaseFileList& list) {
  std::vector<std::string> folders;
  for (std::size_t i = 0; i < list.files.size(); ++i) {
    const std::string fallback = fs::path(list.files[i]).parent_path().filename().string();
    folders.push_back(SafeFileName(list.names[i].empty() ? fallback : list.names[i],
                                   SafeFileName(fallback, "case")));
  }
  return UniqueNames(folders, {"report.html"});
}

/// `line` about `path`, with where the file belongs when it is CAD or a mesh (given to diagnose
/// instead of relax).
std::string WithWhereItBelongs(const std::string& path, const std::string& line) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return line;
  switch (SniffFileKind(path)) {
    case FileKind::kStep:
    case FileKind::kIges:
    case FileKind::kStl:
    case FileKind::kObj:
    case FileKind::kPlyMesh:
    case FileKind::kKbl: return line + "; CAD, KBL files and meshes go to 'cablefit relax'";
    default: return line;
  }
}

/// One line "<file>: <problem>" for any exception from one case.
std::string ErrorLine(const std::exception_ptr& error, const std::string& file) {
  try {
    std::rethrow_exception(error);
  } catch (const FileError& e) {
    return WithWhereItBelongs(file, e.what());
  } catch (...) {
    return file + ": " + ErrorText(std::current_exception());
  }
}

}  // namespace

DiagnosePipeline::DiagnosePipeline(DiagnoseOptions options, RunObserver* observer)
    : options_(std::move(options)), observer_(observer) {}

void DiagnosePipeline::Say(RunMessage kind, const std::string& text) const {
  if (observer_) observer_->Message(kind, text);
}

void DiagnosePipeline::WriteCase(const std::string& dir, const DiagnosedCase& d) {
  WriteDiagnosisFiles(dir, d);
  WriteCaseReport(dir, d);
}

DiagnosedCase DiagnosePipeline::DiagnoseAndWrite(const std::string& case_file,
                                                 const DiagnoseCaseOptions& options,
                                                 const std::string& dir,
                                                 const ProgressCallback& progress) {
  DiagnosedCase d = DiagnoseCase(case_file, options, progress);
  if (!dir.empty()) WriteCase(dir, d);
  return d;
}

DiagnosePipeline::CaseOutcome DiagnosePipeline::RunCase(int i, int fit_threads) {
  const std::string& file = files_[static_cast<std::size_t>(i)];
  CaseOutcome o;
  o.row.name = file;
  const auto t0 = Clock::now();
  try {
    const CancellationScope deadline(options_.timeout);  // the solvers check it
    // A recording of a whole harness (harness-recording/1) is diagnosed as one network.
    if (CaseFormatOf(file) == kHarnessRecordingFormat) {
      const DiagnosedHarness d = DiagnoseHarnessCase(file, fit_threads);
      o.diagnose_seconds = Since(t0);
      const auto t1 = Clock::now();
      const std::string& folder = folders_[static_cast<std::size_t>(i)];
      WriteHarnessCase((fs::path(options_.out_dir) / folder).string(), d);
      o.write_seconds = Since(t1);
      const double seconds = Since(t0);
      const std::string effect = !d.diagnosis.explained ? "not explained"
                                 : d.diagnosis.effects.empty() ? "none"
                                                               : ToString(d.diagnosis.effects.front().effect);
      o.row = SummaryRow{d.recording.name, folder + "/report.html", "harness", effect,
                         d.diagnosis.confidence, std::nullopt, std::nullopt, d.diagnosis.baseline_max,
                         d.diagnosis.fitted_max, "m", seconds, ""};
      o.ok = true;
      Say(RunMessage::kDetail, d.recording.name + ": " + HarnessEffectsName(d) + ", confidence " +
                                   std::to_string(static_cast<int>(std::lround(100.0 * d.diagnosis.confidence))) +
                                   " %, " + FormatSeconds(seconds));
      if (observer_) observer_->Finished(i);
      return o;
    }
    DiagnoseCaseOptions options;
    options.shape.threads = fit_threads;
    const std::string label = fs::path(file).parent_path().filename().string() + ": ";
    const DiagnosedCase d = DiagnoseCase(file, options, [&](double f, const std::string& s) {
      if (observer_) observer_->Progress(i, f, label + s);
      return true;
    });
    o.diagnose_seconds = Since(t0);
    const auto t1 = Clock::now();
    const std::string& folder = folders_[static_cast<std::size_t>(i)];
    WriteCase((fs::path(options_.out_dir) / folder).string(), d);
    o.write_seconds = Since(t1);
    const double seconds = Since(t0);
    o.row = SummaryRow{d.recording.name, folder + "/report.html", ToString(d.kind), d.effect,
                       d.confidence, d.interval, d.clamp, d.baseline.max, d.fitted.max,
                       d.deviation_unit, seconds, ""};
    o.ok = true;
    char line[512];
    // Confidence in per cent, as the reports give it.
    std::snprintf(line, sizeof line, "%s: %s, confidence %.0f %%, %s", d.recording.name.c_str(),
                  EffectsName(d).c_str(), 100.0 * d.confidence, FormatSeconds(seconds).c_str());
    Say(RunMessage::kDetail, line);
  } catch (...) {
    o.row.seconds = Since(t0);
    o.row.error = ErrorLine(std::current_exception(), file);
    Say(RunMessage::kProblem, o.row.error);
  }
  if (observer_) observer_->Finished(i);
  return o;
}

void DiagnosePipeline::WriteRunSummaries(const std::vector<CaseOutcome>& outcomes, int jobs,
                                         DiagnoseSummary* summary) {
  const auto t0 = Clock::now();
  std::vector<SummaryRow> rows;
  for (const CaseOutcome& o : outcomes) rows.push_back(o.row);
  std::vector<std::pair<std::string, std::string>> sources;
  for (const std::string& f : files_) sources.emplace_back("case", f);
  const nlohmann::json provenance = ProvenanceJson(sources);
  const std::string report = (fs::path(options_.out_dir) / "report.html").string();
  try {
    WriteRunSummary(report, rows, summary->seconds.total, jobs, provenance);
    summary->report = report;
  } catch (const std::exception& e) {
    failures_.push_back(e.what());
    Say(RunMessage::kProblem, e.what());
  }
  if (!options_.summary_json.empty()) {
    try {
      nlohmann::json j = DiagnoseSummaryJson(rows, failures_, summary->seconds.total, provenance);
      j["stage_seconds"] = {{"diagnose", summary->seconds.diagnose},
                            {"write", summary->seconds.write}};
      json::WriteJsonFile(options_.summary_json, j);
    } catch (const std::exception& e) {
      failures_.push_back(options_.summary_json + ": " + OneLine(e.what()));
      Say(RunMessage::kProblem, failures_.back());
    }
  }
  summary->seconds.summary = Since(t0);
}

DiagnoseSummary DiagnosePipeline::Run(const std::vector<std::string>& paths) {
  const auto start = Clock::now();
  DiagnoseSummary summary;
  // Paths are expanded one by one so that one bad path does not hide the cases of the others.
  std::vector<std::string> good_paths;
  for (const std::string& p : paths) {
    try {
      FindCaseFiles({p});
      good_paths.push_back(p);
    } catch (const FileError& e) {
      failures_.push_back(WithWhereItBelongs(p, e.what()));
      Say(RunMessage::kProblem, failures_.back());
    }
  }
  CaseFileList list;
  if (!good_paths.empty()) list = FindCaseFiles(good_paths);
  for (const FileError& e : list.errors) {
    failures_.push_back(e.what());
    Say(RunMessage::kProblem, e.what());
  }
  files_ = list.files;
  const int n = static_cast<int>(files_.size());
  summary.cases = n;
  if (n == 0) {
    summary.failures = failures_;
    return summary;
  }
  const int jobs = ResolveJobs(options_.jobs, n);
  // The cores the cases leave idle run the starts of a case's fits (results do not depend on it).
  const int fit_threads = std::max(1, UsableCores() / std::max(jobs, 1));
  // Nothing is written over an input, checked before any case runs.
  OutputFolder output(options_.out_dir, paths);
  output.AddInputs(files_);
  folders_ = CaseFolders(list);
  for (const std::string& folder : folders_) output.CheckFolder(output.path() / folder);
  output.CheckFile(output.path() / "report.html");
  std::vector<std::string> all_inputs = paths;
  all_inputs.insert(all_inputs.end(), files_.begin(), files_.end());
  if (!options_.summary_json.empty()) CheckSummaryJsonPath(options_.summary_json, all_inputs);

  std::vector<CaseOutcome> outcomes(static_cast<std::size_t>(n));
  if (observer_) observer_->Started(n);
  RunBatch(n, jobs, [&](int i) { outcomes[static_cast<std::size_t>(i)] = RunCase(i, fit_threads); });
  if (observer_) observer_->Stopped();
  // Failures in the order of the cases, whichever finished first.
  for (const CaseOutcome& o : outcomes) {
    if (o.ok) ++summary.diagnosed;
    else failures_.push_back(o.row.error);
    summary.seconds.diagnose += o.diagnose_seconds;
    summary.seconds.write += o.write_seconds;
  }
  summary.seconds.total = Since(start);
  WriteRunSummaries(outcomes, jobs, &summary);
  summary.failures = failures_;
  return summary;
}

}  // namespace cablefit::addin
