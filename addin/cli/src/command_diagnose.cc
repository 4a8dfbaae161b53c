// `cablefit diagnose PATH... --out DIR [--jobs N] [--timeout S]` (cli-v1.md): every recording case under the
// paths is diagnosed into DIR/<case>/ (diagnosis.json, nominal/fitted curves, report.html), with
// a run summary DIR/report.html. A bad case is reported and skipped; the others still run.
// The run itself is the application layer's DiagnosePipeline (addin/app/pipeline); this file
// parses the command line, prints what the run says and its summary line.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cablefit/app/pipeline/diagnose_pipeline.h"
#include "cablefit/app/base/report_html.h"
#include "cablefit/cli/commands.h"
#include "option_checks.h"
#include "run_printer.h"
#include "run_summary.h"
#include "terminal_text.h"

namespace cablefit::addin {
namespace {

struct DiagnoseArgs {
  std::vector<std::string> paths;
  DiagnoseOptions options;  // jobs 0: one per core, as relax; a case left alone runs its fits
                            // on the idle cores
  bool quiet = false;       // no per-case lines, no progress bar
};

int RunDiagnose(const DiagnoseArgs& a) {
  RunPrinter printer(a.quiet);
  DiagnosePipeline pipeline(a.options, &printer);
  const DiagnoseSummary s = pipeline.Run(a.paths);
  if (s.cases == 0) {
    std::fprintf(stderr, "cablefit: diagnose: no recording case could be read\n");
    return kExitUsage;
  }
  // Names the summary page only when it was written.
  std::printf("diagnose: %d of %d case(s) diagnosed, %d failed; %s%s%s\n", s.diagnosed, s.cases,
              s.cases - s.diagnosed, FormatSeconds(s.seconds.total).c_str(),
              s.report.empty() ? "" : "; summary: ", TerminalSafe(s.report).c_str());
  std::fflush(stdout);
  PrintFailureList("diagnose", s.failures);
  if (s.diagnosed == 0) return kExitUsage;
  return s.failures.empty() ? kExitOk : kExitSomeFailed;
}

}  // namespace

void RegisterDiagnoseCommand(CLI::App& app, int* exit_code) {
  auto args = std::make_shared<DiagnoseArgs>();
  auto* cmd = app.add_subcommand(
      "diagnose", "Find which effect explains how recorded cables differ from their simulation");
  cmd->add_option("PATH", args->paths,
                  "case.json, a folder holding one, or a folder of case folders")
      ->required();
  cmd->add_option("--out", args->options.out_dir,
                  "output folder: <case>/diagnosis.json, curves, report.html, and report.html")
      ->required();
  cmd->add_option("--jobs", args->options.jobs, "cases diagnosed in parallel (0 = one per core)")
      ->check(JobCount())
      ->capture_default_str();
  cmd->add_option("--timeout", args->options.timeout,
                  "seconds one case may take; a case that takes longer is reported as failed "
                  "and the others go on (0 = no limit)")
      ->check(TimeoutSeconds());
  cmd->add_flag("--quiet", args->quiet,
                "no per-case lines or progress bar; the final summary line and errors are still "
                "printed");
  cmd->add_option("--summary-json", args->options.summary_json,
                  "also write the run summary (per case: status, effect, confidence, error; "
                  "counts, seconds, provenance) as JSON to this file");
  cmd->callback([args, exit_code] { *exit_code = RunDiagnose(*args); });
}

}  // namespace cablefit::addin
