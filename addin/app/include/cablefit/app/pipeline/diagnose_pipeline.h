// The diagnose run as one object (Options in, Summary out), as the relax run: find the recording
// cases under the paths -> diagnose each (in parallel, each within its time limit) -> write its
// diagnosis.json, model curves and report.html -> the run's report.html (and --summary-json).
// `cablefit diagnose` calls Run(); the FreeCAD module diagnoses one case with DiagnoseAndWrite,
// the same per-case work.
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/diagnose/diagnose_case.h"
#include "cablefit/app/pipeline/run_observer.h"
#include "cablefit/app/report/report_summary.h"

namespace cablefit::addin {

struct DiagnoseOptions {
  std::string out_dir;       ///< output folder: <case>/... and report.html
  int jobs = 0;              ///< cases diagnosed in parallel, 0 = one per core
  double timeout = 0.0;      ///< [s] per case, 0 = no limit
  std::string summary_json;  ///< also write the run summary as JSON here, empty = none
};

/// Wall time per stage [s]; the per-case stages are summed over cases (they run in parallel).
struct DiagnoseStageSeconds {
  double diagnose = 0, write = 0, summary = 0, total = 0;
};

struct DiagnoseSummary {
  int cases = 0;      ///< cases found; 0: nothing could be read (a usage error)
  int diagnosed = 0;  ///< cases diagnosed and written
  std::vector<std::string> failures;  ///< "<file>: <problem>"
  std::string report;                 ///< the run's report.html, empty when it was not written
  DiagnoseStageSeconds seconds;
};

class DiagnosePipeline {
 public:
  /// `observer` may be null and must outlive the pipeline.
  explicit DiagnosePipeline(DiagnoseOptions options, RunObserver* observer = nullptr);

  /// Diagnoses every case under `paths` (case.json files, folders holding one, folders of case
  /// folders). A bad path or case fails alone; output folder and --summary-json problems throw
  /// InvalidInput before any case runs.
  DiagnoseSummary Run(const std::vector<std::string>& paths);

  /// One case: DiagnoseCase, then, when `dir` is not empty, its diagnosis.json, curves and
  /// report.html written there. Throws FileError naming the file at fault.
  static DiagnosedCase DiagnoseAndWrite(const std::string& case_file,
                                        const DiagnoseCaseOptions& options, const std::string& dir,
                                        const ProgressCallback& progress);
  /// What is written per case into `dir`: diagnosis.json, the model curves, report.html.
  static void WriteCase(const std::string& dir, const DiagnosedCase& d);

 private:
  struct CaseOutcome {
    SummaryRow row;
    bool ok = false;
    double diagnose_seconds = 0.0, write_seconds = 0.0;
  };
  CaseOutcome RunCase(int i, int fit_threads);
  void WriteRunSummaries(const std::vector<CaseOutcome>& outcomes, int jobs,
                         DiagnoseSummary* summary);
  void Say(RunMessage kind, const std::string& text) const;

  DiagnoseOptions options_;
  RunObserver* observer_;
  std::vector<std::string> files_;    // case.json per case, sorted
  std::vector<std::string> folders_;  // output folder per case
  std::vector<std::string> failures_;
};

}  // namespace cablefit::addin
