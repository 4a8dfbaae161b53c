// `cablefit diagnose PATH... --out DIR [--jobs N] [--timeout S]` (cli-v1.md): every recording case under the
// paths is diagnosed into DIR/<case>/ (diagnosis.json, nominal/fitted curves, report.html), with
// a run summary DIR/report.html. A bad case is reported and skipped; the others still run.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "cablefit/app/batch_pool.h"
#include "cablefit/cli/commands.h"
#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/file_kind.h"
#include "cablefit/app/diagnose_case.h"
#include "cablefit/app/diagnose_output.h"
#include "option_checks.h"
#include "output_folder.h"
#include "progress_bar.h"
#include "cablefit/app/report_case.h"
#include "cablefit/app/report_html.h"
#include "cablefit/app/report_summary.h"
#include "run_summary.h"
#include "terminal_text.h"
#include "cablefit/app/provenance.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {
namespace {

struct DiagnoseArgs {
  std::vector<std::string> paths;
  std::string out_dir;
  int jobs = 0;  // one per core, as relax; a case left alone runs its fits on the idle cores
  double timeout = 0.0;  // [s] per case, 0 = no limit
  bool quiet = false;        // no per-case lines, no progress bar
  std::string summary_json;  // --summary-json FILE, empty = none
};

/// Output folders, one per case, unique after sanitising ("left cable" and "left_cable" would
/// share one) and never the run summary's own file name. Decided before any case runs, in the
/// sorted order of the case files, so they do not depend on which case finishes first.
std::vector<std::string> CaseFolders(const CaseFileList& list) {
  std::vector<std::string> folders;
  for (std::size_t i = 0; i < list.files.size(); ++i) {
    const std::string fallback = std::filesystem::path(list.files[i]).parent_path().filename().string();
    folders.push_back(SafeFileName(list.names[i].empty() ? fallback : list.names[i],
                                   SafeFileName(fallback, "case")));
  }
  return UniqueNames(folders, {"report.html"});
}

/// `line` about `path`, with where the file belongs when it is CAD or a mesh (given to diagnose
/// instead of relax).
std::string WithWhereItBelongs(const std::string& path, const std::string& line) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return line;
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

struct CaseOutcome {
  SummaryRow row;
  bool ok = false;
};

int RunDiagnose(const DiagnoseArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> failures;  // "<file>: <problem>", listed again at the end
  // Paths are expanded one by one so that one bad path does not hide the cases of the others.
  std::vector<std::string> good_paths;
  for (const std::string& p : a.paths) {
    try {
      FindCaseFiles({p});
      good_paths.push_back(p);
    } catch (const FileError& e) {
      failures.push_back(WithWhereItBelongs(p, e.what()));
      std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(failures.back()).c_str());
    }
  }
  CaseFileList list;
  if (!good_paths.empty()) list = FindCaseFiles(good_paths);
  for (const FileError& e : list.errors) {
    failures.push_back(e.what());
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(e.what()).c_str());
  }
  const int n = static_cast<int>(list.files.size());
  if (n == 0) {
    std::fprintf(stderr, "cablefit: diagnose: no recording case could be read\n");
    return kExitUsage;
  }
  const int jobs = ResolveJobs(a.jobs, n);
  // The cores the cases leave idle run the starts of a case's fits (results do not depend on it).
  const int fit_threads =
      std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / std::max(jobs, 1));
  OutputFolder output(a.out_dir, a.paths);
  output.AddInputs(list.files);
  const std::filesystem::path& out_dir = output.path();
  const std::vector<std::string> folders = CaseFolders(list);
  for (const std::string& folder : folders) output.CheckFolder(out_dir / folder);
  output.CheckFile(out_dir / "report.html");
  std::vector<std::string> all_inputs = a.paths;
  all_inputs.insert(all_inputs.end(), list.files.begin(), list.files.end());
  if (!a.summary_json.empty()) CheckSummaryJsonPath(a.summary_json, all_inputs);
  std::vector<CaseOutcome> outcomes(static_cast<std::size_t>(n));
  std::mutex failures_mutex;
  {
    ProgressBar bar(n, a.quiet ? nullptr : stderr);
    const auto errors = RunBatch(n, jobs, [&](int i) {
      const std::string& file = list.files[static_cast<std::size_t>(i)];
      CaseOutcome& o = outcomes[static_cast<std::size_t>(i)];
      o.row.name = file;
      const auto t0 = std::chrono::steady_clock::now();
      try {
        const CancellationScope deadline(a.timeout);  // the solvers check it (core/base/cancellation.h)
        DiagnoseCaseOptions options;
        options.shape.threads = fit_threads;
        const DiagnosedCase d = DiagnoseCase(file, options, [&](double f, const std::string& s) {
          bar.Update(i, f, std::filesystem::path(file).parent_path().filename().string() + ": " + s);
          return true;
        });
        const std::string& folder = folders[static_cast<std::size_t>(i)];
        const std::string dir = (out_dir / folder).string();
        WriteDiagnosisFiles(dir, d);
        WriteCaseReport(dir, d);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        o.row = SummaryRow{d.recording.name, folder + "/report.html", ToString(d.kind), d.effect,
                           d.confidence, d.interval, d.clamp, d.baseline.max, d.fitted.max,
                           d.deviation_unit, seconds, ""};
        o.ok = true;
        char line[512];
        // Confidence in per cent, as the reports give it.
        std::snprintf(line, sizeof line, "%s: %s, confidence %.0f %%, %s", d.recording.name.c_str(),
                      EffectsName(d).c_str(), 100.0 * d.confidence, FormatSeconds(seconds).c_str());
        if (!a.quiet) bar.PrintLine(stdout, line);
      } catch (...) {
        o.row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        o.row.error = ErrorLine(std::current_exception(), file);
        {
          std::lock_guard lock(failures_mutex);
          failures.push_back(o.row.error);
        }
        bar.PrintLine(stderr, "cablefit: " + o.row.error);
      }
      bar.Finish(i);
    });
    (void)errors;  // every exception is handled inside the work item
  }
  std::vector<SummaryRow> rows;
  int diagnosed = 0;
  for (const CaseOutcome& o : outcomes) {
    rows.push_back(o.row);
    diagnosed += o.ok ? 1 : 0;
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<std::pair<std::string, std::string>> sources;
  for (const std::string& f : list.files) sources.emplace_back("case", f);
  const nlohmann::json provenance = ProvenanceJson(sources);
  bool summary_written = true;
  try {
    WriteRunSummary((out_dir / "report.html").string(), rows, total, jobs, provenance);
  } catch (const std::exception& e) {
    summary_written = false;
    failures.push_back(e.what());
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(e.what()).c_str());
  }
  if (!a.summary_json.empty()) {
    try {
      json::WriteJsonFile(a.summary_json, DiagnoseSummaryJson(rows, failures, total, provenance));
    } catch (const std::exception& e) {
      failures.push_back(a.summary_json + ": " + OneLine(e.what()));
      std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(failures.back()).c_str());
    }
  }
  // Names the summary page only when it was written.
  std::printf("diagnose: %d of %d case(s) diagnosed, %d failed; %s%s%s\n", diagnosed, n,
              n - diagnosed, FormatSeconds(total).c_str(), summary_written ? "; summary: " : "",
              summary_written ? TerminalSafe((out_dir / "report.html").string()).c_str() : "");
  std::fflush(stdout);
  PrintFailureList("diagnose", failures);
  if (diagnosed == 0) return kExitUsage;
  return failures.empty() ? kExitOk : kExitSomeFailed;
}

}  // namespace

void RegisterDiagnoseCommand(CLI::App& app, int* exit_code) {
  auto args = std::make_shared<DiagnoseArgs>();
  auto* cmd = app.add_subcommand(
      "diagnose", "Find which effect explains how recorded cables differ from their simulation");
  cmd->add_option("PATH", args->paths,
                  "case.json, a folder holding one, or a folder of case folders")
      ->required();
  cmd->add_option("--out", args->out_dir,
                  "output folder: <case>/diagnosis.json, curves, report.html, and report.html")
      ->required();
  cmd->add_option("--jobs", args->jobs, "cases diagnosed in parallel (0 = one per core)")
      ->check(JobCount())
      ->capture_default_str();
  cmd->add_option("--timeout", args->timeout,
                  "seconds one case may take; a case that takes longer is reported as failed "
                  "and the others go on (0 = no limit)")
      ->check(TimeoutSeconds());
  cmd->add_flag("--quiet", args->quiet,
                "no per-case lines or progress bar; the final summary line and errors are still "
                "printed");
  cmd->add_option("--summary-json", args->summary_json,
                  "also write the run summary (per case: status, effect, confidence, error; "
                  "counts, seconds, provenance) as JSON to this file");
  cmd->callback([args, exit_code] { *exit_code = RunDiagnose(*args); });
}

}  // namespace cablefit::addin
