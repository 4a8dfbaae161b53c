// `cablefit simulate CASE --out DIR [--initial FILE.csv]`: the nominal set-up of one case.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cablefit/cli/commands.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/app/output/solution_json.h"
#include "cablefit/app/base/provenance.h"
#include "cablefit/app/output/output_folder.h"
#include "terminal_text.h"

namespace cablefit::addin {
namespace {

struct SimulateArgs {
  std::string case_path;
  std::string out_dir;
  std::string initial;
  double accuracy = 1e-6;
  int samples = 401;
};

int RunSimulate(const SimulateArgs& a) {
  // A simulate is made again in milliseconds; syncing its two files cost several times that.
  SetDurableWrites(false);
  SimulationOptions opt;
  opt.accuracy = a.accuracy;
  std::string why;
  if (!opt.IsValid(&why)) throw InvalidInput("--accuracy: " + why);
  const RecordingCase rc = ReadRecordingCase(a.case_path);
  // A force case's set-up is a test rig moved through a curve, not one equilibrium: solving
  // its nominal set-up alone gives nothing to compare (it once printed "0 Newton iterations,
  // UNSTABLE" and exited 0). Say where it belongs instead.
  bool has_shape = rc.recordings.empty();
  for (const RecordingRef& r : rc.recordings) has_shape = has_shape || r.kind != RecordingKind::kForceCurve;
  if (!has_shape) {
    throw FileError(rc.case_file,
                    "is a force case (only force_curve recordings): 'cablefit simulate' solves "
                    "the shape set-up of a case; 'cablefit diagnose' simulates its force test");
  }
  std::vector<std::string> inputs = {a.case_path, rc.case_file};
  for (const RecordingRef& r : rc.recordings) inputs.push_back(r.path);
  if (!a.initial.empty()) inputs.push_back(a.initial);
  const OutputFolder output(a.out_dir, inputs);
  output.CheckFile(output.path() / "centerline.csv");
  output.CheckFile(output.path() / "solution.json");
  Polyline initial;
  if (!a.initial.empty()) {
    initial = ReadCenterlineCsv(a.initial);
    if (initial.size() < 2) throw FileError(a.initial, "needs at least 2 points");
  }
  RodSimulator sim(opt);
  SimulationResult r;
  try {
    r = sim.Simulate(rc.nominal, a.initial.empty() ? nullptr : &initial);
  } catch (const FileError&) {
    throw;
  } catch (const InvalidInput& e) {
    throw FileError(rc.case_file, e.what());
  }
  const std::filesystem::path& dir = output.path();
  const Polyline out = SampleCenterline(r.solution.centerline,
                                        UniformArcLengths(rc.nominal.length, a.samples));
  WriteCenterlineCsv((dir / "centerline.csv").string(), out);
  const std::vector<std::pair<std::string, std::string>> sources = {{"case", rc.case_file},
                                                                    {"initial", a.initial}};
  WriteFileAtomically((dir / "solution.json").string(),
                      SolutionJsonText(rc.name, rc.nominal, r, ProvenanceJson(sources)));
  std::printf("%s: %s, %d elements, %d Newton iterations, est. error %.2g mm, %s, %.1f ms\n",
              TerminalSafe(rc.name).c_str(), r.converged ? "converged" : "NOT CONVERGED",
              r.level_elements.empty() ? 0 : r.level_elements.back(), r.newton_iterations,
              1e3 * r.estimated_error, r.solution.summary.stable ? "stable" : "UNSTABLE",
              r.seconds * 1e3);
  if (!r.converged) {
    std::fprintf(stderr, "cablefit: %s: solver did not converge: %s\n",
                 TerminalSafe(rc.case_file).c_str(), r.solution.summary.message.c_str());
    return kExitSomeFailed;
  }
  return kExitOk;
}

}  // namespace

void RegisterSimulateCommand(CLI::App& app, int* exit_code) {
  auto args = std::make_shared<SimulateArgs>();
  auto* cmd = app.add_subcommand("simulate", "Solve the nominal set-up of one recording case");
  cmd->add_option("CASE", args->case_path, "case.json or a folder holding one")->required();
  cmd->add_option("--out", args->out_dir, "output folder (centerline.csv, solution.json)")
      ->required();
  cmd->add_option("--initial", args->initial,
                  "starting shape, CSV with s,x,y,z or x,y,z (selects the equilibrium branch)");
  cmd->add_option("--accuracy", args->accuracy, "requested position accuracy [m]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--samples", args->samples, "rows of centerline.csv")
      ->check(CLI::Range(2, 1000000))
      ->capture_default_str();
  cmd->callback([args, exit_code] { *exit_code = RunSimulate(*args); });
}

}  // namespace cablefit::addin
