// `cablefit relax INPUT... --out DIR [--config HARNESS.json] [--jobs N] [--unit U]`: every cable
// of harness CAD or meshes relaxed under gravity from its drawn shape (spec: cli-v1 "relax").
// The run itself is the application layer's RelaxPipeline (addin/app/pipeline); this file parses
// the command line, prints what the run says (progress bar, per-cable lines, notes, problems) and
// its summary, and turns it into the exit status.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cablefit/app/pipeline/relax_pipeline.h"
#include "cablefit/cli/commands.h"
#include "cablefit/core/base/errors.h"
#include "option_checks.h"
#include "run_printer.h"
#include "run_summary.h"
#include "terminal_text.h"

namespace cablefit::addin {
namespace {

struct RelaxArgs {
  std::vector<std::string> inputs;
  RelaxOptions options;
  double accuracy = 1e-6;
  bool accuracy_given = false;  // --accuracy on the command line (else KBL input gets kKblAccuracy)
  bool quiet = false;           // no per-cable or per-input lines, no notes, no progress bar
};

int RunRelax(const RelaxArgs& a) {
  RelaxOptions options = a.options;
  if (a.accuracy_given) {
    SimulationOptions check;
    check.accuracy = a.accuracy;
    std::string why;
    if (!check.IsValid(&why)) throw InvalidInput("--accuracy: " + why);
    options.accuracy = a.accuracy;
  }
  RunPrinter printer(a.quiet);
  RelaxPipeline pipeline(options, &printer);
  const RelaxSummary summary = pipeline.Run(a.inputs);
  if (summary.any_read) {
    // The run in one line, last, where a user looks (also with --quiet: it is the result); the
    // time per stage just above it.
    if (!a.quiet) std::printf("%s\n", StageSecondsLine(summary.seconds).c_str());
    std::printf("%s; report: %s\n", RelaxSummaryLine(summary.counts, summary.seconds.total).c_str(),
                TerminalSafe(summary.report).c_str());
    std::fflush(stdout);
  }
  PrintFailureList("relax", summary.failures);
  if (!summary.any_read) {
    std::fprintf(stderr, "cablefit: relax: no input could be read\n");
    return kExitUsage;
  }
  return summary.failures.empty() ? kExitOk : kExitSomeFailed;
}

}  // namespace

void RegisterRelaxCommand(CLI::App& app, int* exit_code) {
  auto args = std::make_shared<RelaxArgs>();
  auto* cmd = app.add_subcommand(
      "relax", "Relax the cables of harness CAD or meshes under gravity from their drawn shape");
  cmd->add_option("INPUT", args->inputs,
                  "STEP/IGES files, KBL harness files, meshes (STL, OBJ, PLY, glTF...), or "
                  "folders of them")
      ->required();
  cmd->add_option("--out", args->options.out_dir,
                  "output folder: <stem>.step, <stem>.json, <stem>-deviation.png, report.html (and "
                  "<stem>-motion-envelope.stl/.glb ... with a motion or tolerances)")
      ->required();
  cmd->add_option("--config", args->options.config_path, "harness.json: materials, supports, gravity per cable");
  cmd->add_option("--jobs", args->options.jobs, "parallel workers (0 = one per core)")
      ->check(JobCount())
      ->capture_default_str();
  cmd->add_option("--timeout", args->options.timeout,
                  "seconds one cable may take to relax; a cable that takes longer is reported "
                  "as failed and the others go on (0 = no limit)")
      ->check(TimeoutSeconds());
  cmd->add_option("--unit", args->options.mesh_unit, "length unit of mesh files (m, cm, mm, um, in, ft)")
      ->check(CLI::IsMember({"m", "cm", "mm", "um", "in", "inch", "ft"}))
      ->capture_default_str();
  CLI::Option* accuracy =
      cmd->add_option("--accuracy", args->accuracy,
                      "requested accuracy of relaxed positions [m] (KBL harnesses: 1e-4 unless "
                      "given)")
          ->check(CLI::PositiveNumber)
          ->capture_default_str();
  cmd->add_flag_callback("--no-pictures", [args] { args->options.pictures = false; },
                         "skip the deviation pictures");
  cmd->add_flag("--close-ups", args->options.close_ups,
                "also one picture per cable: <stem>-<cable>-deviation.png");
  cmd->add_flag("--quiet", args->quiet,
                "no per-cable lines, notes or progress bar; the final summary line, warnings and "
                "errors are still printed");
  cmd->add_option("--summary-json", args->options.summary_json,
                  "also write the run summary (per input and cable: status, errors; counts, "
                  "seconds, provenance) as JSON to this file");
  cmd->callback([args, exit_code, accuracy] {
    args->accuracy_given = accuracy->count() > 0;
    *exit_code = RunRelax(*args);
  });
}

}  // namespace cablefit::addin
