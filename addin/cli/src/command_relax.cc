// `cablefit relax INPUT... --out DIR [--config HARNESS.json] [--jobs N] [--unit U]`: every cable
// of harness CAD or meshes relaxed under gravity from its drawn shape (spec: cli-v1 "relax").
// Three phases, each parallel over `--jobs` workers: read the inputs, solve every cable of every
// input, write each input's STEP/JSON/PNG; then report.html. CAD I/O is serialised (OCCT's
// readers and writers keep global state).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>
#include <set>
#include <string>
#include <tuple>

#include "cablefit/app/batch_pool.h"
#include "cablefit/cli/commands.h"
#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/app/harness_config.h"
#include "option_checks.h"
#include "output_folder.h"
#include "cablefit/app/cable_selection.h"
#include "progress_bar.h"
#include "cablefit/app/kbl_input.h"
#include "cablefit/app/relax_cable.h"
#include "cablefit/app/relax_file.h"
#include "cablefit/app/relax_motion_pictures.h"
#include "cablefit/app/relax_network.h"
#include "cablefit/app/relax_report.h"
#include "cablefit/app/relax_summary.h"
#include "run_summary.h"
#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/input_file.h"
#include "terminal_text.h"

namespace cablefit::addin {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct RelaxArgs {
  std::vector<std::string> inputs;
  std::string out_dir;
  std::string config;
  int jobs = 0;
  std::string unit = "mm";
  double accuracy = 1e-6;
  bool accuracy_given = false;  // --accuracy on the command line (else KBL input gets kKblAccuracy)
  bool pictures = true;
  bool close_ups = false;
  double timeout = 0.0;  // [s] per cable (or group solved together), 0 = no limit
  bool quiet = false;        // no per-cable or per-input lines, no notes, no progress bar
  std::string summary_json;  // --summary-json FILE, empty = none
};

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Files named on the command line, and the STEP/IGES/mesh files directly inside named folders
// (sorted, so runs are reproducible). A path that does not exist is a failure of its own.
std::vector<std::string> ExpandInputs(const std::vector<std::string>& inputs,
                                      std::vector<std::string>* failures) {
  std::vector<std::string> files;
  for (const std::string& p : inputs) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<std::string> found;
      for (const auto& entry : fs::directory_iterator(p, ec)) {
        const std::string f = entry.path().string();
        if (entry.is_regular_file() && (IsCadPath(f) || IsKblPath(f) || IsMeshPath(f)))
          found.push_back(f);
      }
      std::sort(found.begin(), found.end());
      if (found.empty()) failures->push_back(p + ": folder holds no STEP, IGES, KBL or mesh file");
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::exists(p, ec)) {
      files.push_back(p);
    } else {
      failures->push_back(p + ": " + UnreachablePathProblem(p));
    }
  }
  return files;
}

// Output stems unique within the run: a second "harness" becomes "harness-igs", then "-2"...
// A stem is cut to kMaxStemBytes so that "<stem>-deviation.png" and the close-ups' names stay
// within the file system's 255 bytes for any input name.
std::vector<std::string> UniqueStems(const std::vector<std::string>& files) {
  std::set<std::string> used;
  std::vector<std::string> stems;
  for (const std::string& f : files) {
    const fs::path p(f);
    const std::string base = Utf8Prefix(p.stem().string(), kMaxStemBytes);
    std::string stem = base;
    if (used.count(stem))
      stem +=
          "-" + p.extension().string().substr(std::min<size_t>(1, p.extension().string().size()));
    for (int k = 2; used.count(stem); ++k) stem = base + "-" + std::to_string(k);
    used.insert(stem);
    stems.push_back(stem);
  }
  return stems;
}

std::string CableLine(const RelaxedFile& f, const CableRelaxation& r) {
  // A bend radius a thousand times the cable's length is a straight cable drawn with round-off.
  char bend[160];
  if (!std::isfinite(r.min_bend_radius) || r.min_bend_radius > 1e3 * r.setup.spec.length) {
    std::snprintf(bend, sizeof bend, "straight");
  } else if (r.bend_flag && r.setup.min_bend_radius_limit > 0) {
    // A cable's own limit (a KBL file's wires) is not the run's factor: say which and where.
    std::snprintf(bend, sizeof bend, "%.1f mm (TOO TIGHT: the cable's limit %.1f mm, at s=%.0f mm)",
                  1e3 * r.min_bend_radius, 1e3 * r.bend_limit, 1e3 * r.min_bend_radius_s);
  } else {
    std::snprintf(bend, sizeof bend, "%.1f mm%s", 1e3 * r.min_bend_radius,
                  r.bend_flag ? " (TOO TIGHT)" : "");
  }
  double least_slack = std::numeric_limits<double>::infinity();
  for (const CableRelaxation::Stretch& st : r.stretches) least_slack = std::min(least_slack, st.slack);
  char taut[96] = "";
  if (r.taut) {
    std::snprintf(taut, sizeof taut, ", TAUT (slack %.3f %% between supports)", 100 * least_slack);
  }
  char tension[48] = "not computed";
  if (std::isfinite(r.max_tension)) std::snprintf(tension, sizeof tension, "%.3g N", r.max_tension);
  char flat[64] = "";
  if (r.setup.flat_width > 0)
    std::snprintf(flat, sizeof flat, ", flat %.3g x %.3g mm", 1e3 * r.setup.flat_width,
                  1e3 * r.setup.flat_thickness);
  char buf[704];
  std::snprintf(buf, sizeof buf,
                "%s: %s: L=%.0f mm%s, max deviation %.2f mm at s=%.0f mm (rms %.2f mm), min bend "
                "radius %s, max tension %s, %d supports, %s%s%s, %.1f ms",
                f.stem.c_str(), r.setup.name.c_str(), 1e3 * r.setup.spec.length, flat,
                1e3 * r.max_deviation, 1e3 * r.max_deviation_s, 1e3 * r.rms_deviation, bend, tension,
                static_cast<int>(r.setup.spec.supports.size()),
                r.result.solution.summary.stable ? "stable" : "UNSTABLE", taut,
                r.setup.material_defaulted ? ", default material" : "", 1e3 * r.seconds);
  return buf;
}

int RunRelax(const RelaxArgs& a) {
  const auto start = Clock::now();
  const double unit = UnitInMetres(a.unit);
  HarnessConfig config;
  if (!a.config.empty()) config = ReadHarnessConfig(a.config);
  SimulationOptions sim_options;
  sim_options.accuracy = a.accuracy;
  std::string why;
  if (!sim_options.IsValid(&why)) throw InvalidInput("--accuracy: " + why);
  // A KBL harness is relaxed to kKblAccuracy unless --accuracy was given.
  auto options_for = [&](const RelaxedFile& f) {
    SimulationOptions o = sim_options;
    if (!a.accuracy_given && f.own_config != nullptr) o.accuracy = kKblAccuracy;
    return o;
  };

  std::vector<std::string> failures;  // "<file>: <problem>"
  const std::vector<std::string> paths = ExpandInputs(a.inputs, &failures);
  for (const std::string& f : failures) std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(f).c_str());
  const std::vector<std::string> stems = UniqueStems(paths);
  std::vector<std::string> inputs = a.inputs;
  inputs.insert(inputs.end(), paths.begin(), paths.end());
  if (!a.config.empty()) inputs.push_back(a.config);
  const OutputFolder output(a.out_dir, inputs);
  const fs::path& out = output.path();
  output.CheckFile(out / "report.html");
  if (!a.summary_json.empty()) CheckSummaryJsonPath(a.summary_json, inputs);
  for (const std::string& stem : stems) {
    for (const char* suffix : {".step", ".json", "-deviation.png"}) output.CheckFile(out / (stem + suffix));
    for (const std::string& name : EnvelopeFileNames(stem)) output.CheckFile(out / name);
    output.CheckFile(out / (stem + "-motion.png"));
    output.CheckFolder(out / MotionFramesFolder(stem));
  }
  const int n = static_cast<int>(paths.size());
  std::vector<RelaxedFile> files(static_cast<size_t>(n));
  std::mutex cad_mutex, failures_mutex;
  ProgressBar bar(3 * n + 1, a.quiet ? nullptr : stderr);
  // Failures are printed as they happen but listed (and a file's first problem kept) in the
  // order of the work, not of the threads: the same run gives the same list and JSON.
  struct Failure {
    int stage, file, order;
    std::string text;
  };
  std::vector<Failure> failure_log;
  auto record = [&](RelaxedFile& f, const std::string& problem, int stage, int order) {
    std::lock_guard lock(failures_mutex);
    failure_log.push_back({stage, static_cast<int>(&f - files.data()), order, problem});
  };
  auto say = [&](RelaxedFile& f, const std::string& problem) {
    bar.PrintLine(stderr, "cablefit: " + f.input + ": " + problem);
  };
  auto fail = [&](RelaxedFile& f, const std::string& problem, int stage, int order = 0) {
    record(f, problem, stage, order);
    say(f, problem);
  };

  // 1. Read.
  RunBatch(n, ResolveJobs(a.jobs, n), [&](int i) {
    RelaxedFile& f = files[static_cast<size_t>(i)];
    f.input = paths[static_cast<size_t>(i)];
    f.stem = stems[static_cast<size_t>(i)];
    bar.Update(i, 0.5, f.stem + ": read");
    const auto t0 = Clock::now();
    try {
      std::unique_lock lock(cad_mutex, std::defer_lock);
      if (IsCadPath(f.input)) lock.lock();
      if (IsKblInput(f.input)) {
        // The file's own physics per segment, the user's harness.json over it.
        KblInput kbl = ReadKblInput(f.input, config);
        f.drawing = std::move(kbl.drawing);
        f.own_config = std::make_shared<const HarnessConfig>(std::move(kbl.config));
        f.cable_json = std::move(kbl.cable_json);
        f.notes = std::move(kbl.notes);
      } else {
        f.drawing = ReadHarnessInput(f.input, unit);
      }
      ApplyCableSelection(config, &f.drawing);
      f.read_ok = true;
      for (const std::string& why : f.drawing.skipped)
        if (!a.quiet) bar.PrintLine(stderr, "cablefit: note: " + f.input + ": not taken as a cable: " + why);
      for (const std::string& why : f.drawing.warnings)
        bar.PrintLine(stderr, "cablefit: warning: " + f.input + ": " + why);
      for (const std::string& note : f.notes)
        if (!a.quiet) bar.PrintLine(stderr, "cablefit: note: " + f.input + ": " + note);
      f.cables.resize(f.drawing.cables.size());
      f.cable_errors.resize(f.drawing.cables.size());
    } catch (...) {
      fail(f, ErrorText(std::current_exception()), 1);
    }
    f.times.read = Since(t0);
    bar.Finish(i);
  });

  // A harness.json entry that names no cable is most likely a typo: say so (not a failure,
  // the same sidecar may serve several drawings).
  for (const auto& [name, unused] : config.cables) {
    bool found = false;
    for (const RelaxedFile& f : files)
      for (const DrawnCable& c : f.drawing.cables) found = found || c.name == name;
    if (!found) {
      bar.PrintLine(stderr, "cablefit: warning: " + config.path + ": cables." + name +
                                " matches no cable of the inputs");
    }
  }

  // The STEP writer's sweep helpers load OpenCASCADE while the cables relax (this thread lives
  // until they are used or let go).
  for (const RelaxedFile& f : files) {
    if (!f.read_ok || f.drawing.cables.empty()) continue;
    PrepareRelaxedStep(f.drawing.cables.size());
    break;
  }
  // The renderer's start-up (OSMesa, llvmpipe compiling its shaders) on a core of its own while
  // the cables relax; no OpenCASCADE work runs in this process until stage 3 (see cad_mutex).
  std::jthread warm_up;  // joined on every way out
  if (a.pictures && std::any_of(files.begin(), files.end(), [](const RelaxedFile& f) { return f.read_ok; }))
    warm_up = std::jthread(WarmUpDeviationPictures);

  // 2. Relax every cable of every input that was read.
  // A job is one group of cables solved together: a single cable, or a network of cables
  // joined at breakouts / near solids they may touch (see relax_network.h).
  struct Job {
    int file;
    RelaxGroup group;
  };
  std::vector<Job> jobs;
  std::vector<std::vector<OrientedBox>> boxes(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    RelaxedFile& f = files[static_cast<size_t>(i)];
    boxes[static_cast<size_t>(i)] = SolidBoxes(f.drawing);
    if (!f.read_ok) continue;
    try {
      for (RelaxGroup& g : GroupCables(f.drawing, boxes[static_cast<size_t>(i)], ConfigOf(f, config)))
        jobs.push_back({i, std::move(g)});
    } catch (...) {
      fail(f, ErrorText(std::current_exception()), 2);
    }
  }
  const int nj = static_cast<int>(jobs.size());
  std::vector<double> job_seconds(static_cast<size_t>(nj), 0.0);
  std::vector<json::Json> job_network(static_cast<size_t>(nj));
  RunBatch(nj, ResolveJobs(a.jobs, nj), [&](int k) {
    const Job& job = jobs[static_cast<size_t>(k)];
    RelaxedFile& f = files[static_cast<size_t>(job.file)];
    const std::string label = GroupLabel(f.drawing, job.group);
    bar.Update(n + job.file, static_cast<double>(job.group.cables.front()) / f.drawing.cables.size(),
               f.stem + ": relax " + label);
    const auto t0 = Clock::now();
    const CancellationScope deadline(a.timeout);  // the solver checks it (core/base/cancellation.h)
    GroupOutcome g = RelaxGroupCables(f.drawing, job.group, boxes[static_cast<size_t>(job.file)],
                                      ConfigOf(f, config), options_for(f));
    const std::string& problem = g.problem;
    std::vector<CableRelaxation>& done = g.cables;
    job_network[static_cast<size_t>(k)] = std::move(g.network);
    if (problem.empty()) {
      for (CableRelaxation& r : done) {
        if (!a.quiet) bar.PrintLine(stdout, CableLine(f, r));
        f.cables[static_cast<size_t>(r.setup.cable)] = std::move(r);
      }
      for (const auto& [c, why] : g.cable_problems) {
        f.cable_errors[static_cast<size_t>(c)] = why;
        fail(f, "cable '" + f.drawing.cables[static_cast<size_t>(c)].name + "': " + why, 3, k);
      }
    } else {
      for (int c : job.group.cables) f.cable_errors[static_cast<size_t>(c)] = problem;
      fail(f, (job.group.cables.size() > 1 ? "cables '" : "cable '") + label + "': " + problem, 3,
           k);
    }
    job_seconds[static_cast<size_t>(k)] = Since(t0);
  });
  for (int k = 0; k < nj; ++k)
    if (!job_network[static_cast<size_t>(k)].is_null())
      files[static_cast<size_t>(jobs[static_cast<size_t>(k)].file)].networks.push_back(
          std::move(job_network[static_cast<size_t>(k)]));
  for (int k = 0; k < nj; ++k)
    files[static_cast<size_t>(jobs[static_cast<size_t>(k)].file)].times.relax +=
        job_seconds[static_cast<size_t>(k)];
  // Clearance of the relaxed cables: the violations on stdout, all pairs in the JSON.
  for (RelaxedFile& f : files) {
    if (!f.read_ok) continue;
    MeasureFileClearances(ConfigOf(f, config), &f);
    for (const ClearancePair& p : f.clearances)
      if (p.violation()) bar.PrintLine(stdout, f.stem + ": CLEARANCE: " + ClearanceViolationText(p));
    RunFileMotion(ConfigOf(f, config), options_for(f), &f);  // the harness.json motion, if any
    if (f.motion)
      for (const std::string& line : MotionLines(*f.motion)) bar.PrintLine(stdout, f.stem + ": " + line);
    // harness.json tolerances, if any: one file at a time, its set-ups on every worker
    RunFileTolerance(ConfigOf(f, config), options_for(f), &f, ResolveJobs(a.jobs, 1 << 20));
    if (f.tolerance)
      for (const std::string& line : ToleranceLines(*f.tolerance)) bar.PrintLine(stdout, f.stem + ": " + line);
  }

  if (warm_up.joinable()) warm_up.join();

  // 3. Write each input's outputs.
  RunBatch(n, ResolveJobs(a.jobs, n), [&](int i) {
    RelaxedFile& f = files[static_cast<size_t>(i)];
    bar.Finish(n + i);
    if (!f.read_ok) {
      bar.Finish(2 * n + i);
      return;
    }
    try {
      bar.Update(2 * n + i, 0.1, f.stem + ": write JSON, STEP");
      auto t0 = Clock::now();
      // The envelopes first: the JSON names them.
      f.envelopes = WriteEnvelopeFiles(out.string(), f, ConfigOf(f, config));
      json::WriteJsonFile((out / (f.stem + ".json")).string(), RelaxedFileToJson(f, ConfigOf(f, config)));
      f.times.json = Since(t0);
      t0 = Clock::now();
      {
        std::lock_guard lock(cad_mutex);
        int order = 0;
        for (const std::string& problem : WriteRelaxedStepFile((out / (f.stem + ".step")).string(), f, ConfigOf(f, config)))
          fail(f, problem, 4, order++);
      }
      f.times.step = Since(t0);
      if (a.pictures) {
        bar.Update(2 * n + i, 0.5, f.stem + ": picture");
        t0 = Clock::now();
        f.picture = f.stem + "-deviation.png";
        // Also under the CAD lock: a crash was once seen with OSMesa rendering while OCCT wrote
        // another file (not reproduced since); both spawn their own worker threads.
        std::lock_guard lock(cad_mutex);
        WriteDeviationPicture((out / f.picture).string(), f, ConfigOf(f, config));
        if (a.close_ups) f.close_ups = WriteCloseUpPictures(out.string(), f, ConfigOf(f, config));
        f.motion_pictures = WriteMotionAnimation(out.string(), f, ConfigOf(f, config));
        f.times.picture = Since(t0);
      }
      char buf[512];
      std::snprintf(buf, sizeof buf,
                    "%s: %zu cables, %zu solids; seconds: read %.3f, relax %.3f, STEP %.3f, "
                    "JSON %.3f, picture %.3f",
                    f.stem.c_str(), f.drawing.cables.size(), f.drawing.solids.size(), f.times.read,
                    f.times.relax, f.times.step, f.times.json, f.times.picture);
      if (!a.quiet) bar.PrintLine(stdout, buf);
    } catch (const FileError& e) {
      // Names the output that could not be written: the input is not to blame.
      fail(f, std::string("its results could not be written: ") + e.what(), 5);
    } catch (...) {
      fail(f, ErrorText(std::current_exception()), 5);
    }
    bar.Finish(2 * n + i);
  });
  std::stable_sort(failure_log.begin(), failure_log.end(), [](const Failure& x, const Failure& y) {
    return std::tie(x.file, x.stage, x.order) < std::tie(y.file, y.stage, y.order);
  });
  for (const Failure& e : failure_log) {
    RelaxedFile& f = files[static_cast<size_t>(e.file)];
    if (f.error.empty()) f.error = e.text;  // the file's first problem, in the order of the work
    failures.push_back(f.input + ": " + e.text);
  }

  bool any_read = false;
  for (const RelaxedFile& f : files) any_read = any_read || f.read_ok;
  if (any_read) {
    try {
      WriteRelaxReport((out / "report.html").string(), files, config, Since(start));
    } catch (const std::exception& e) {
      failures.push_back(std::string("report.html: ") + e.what());
      bar.PrintLine(stderr, std::string("cablefit: ") + e.what());
    }
  }
  bar.Finish(3 * n);
  if (!a.summary_json.empty()) {
    try {
      json::WriteJsonFile(a.summary_json, RelaxSummaryJson(files, failures, config.path, Since(start)));
    } catch (const std::exception& e) {
      failures.push_back(a.summary_json + ": " + OneLine(e.what()));
      std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(failures.back()).c_str());
    }
  }
  if (any_read) {
    // The run in one line, last, where a user looks (also with --quiet: it is the result).
    std::printf("%s; report: %s\n", RelaxSummaryLine(CountRelaxation(files), Since(start)).c_str(),
                TerminalSafe((out / "report.html").string()).c_str());
    std::fflush(stdout);
  }
  PrintFailureList("relax", failures);
  if (!any_read) {
    std::fprintf(stderr, "cablefit: relax: no input could be read\n");
    return kExitUsage;
  }
  return failures.empty() ? kExitOk : kExitSomeFailed;
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
  cmd->add_option("--out", args->out_dir,
                  "output folder: <stem>.step, <stem>.json, <stem>-deviation.png, report.html (and "
                  "<stem>-motion-envelope.stl/.glb ... with a motion or tolerances)")
      ->required();
  cmd->add_option("--config", args->config, "harness.json: materials, supports, gravity per cable");
  cmd->add_option("--jobs", args->jobs, "parallel workers (0 = one per core)")
      ->check(JobCount())
      ->capture_default_str();
  cmd->add_option("--timeout", args->timeout,
                  "seconds one cable may take to relax; a cable that takes longer is reported "
                  "as failed and the others go on (0 = no limit)")
      ->check(TimeoutSeconds());
  cmd->add_option("--unit", args->unit, "length unit of mesh files (m, cm, mm, um, in, ft)")
      ->check(CLI::IsMember({"m", "cm", "mm", "um", "in", "inch", "ft"}))
      ->capture_default_str();
  CLI::Option* accuracy =
      cmd->add_option("--accuracy", args->accuracy,
                      "requested accuracy of relaxed positions [m] (KBL harnesses: 1e-4 unless "
                      "given)")
          ->check(CLI::PositiveNumber)
          ->capture_default_str();
  cmd->add_flag_callback("--no-pictures", [args] { args->pictures = false; },
                         "skip the deviation pictures");
  cmd->add_flag("--close-ups", args->close_ups,
                "also one picture per cable: <stem>-<cable>-deviation.png");
  cmd->add_flag("--quiet", args->quiet,
                "no per-cable lines, notes or progress bar; the final summary line, warnings and "
                "errors are still printed");
  cmd->add_option("--summary-json", args->summary_json,
                  "also write the run summary (per input and cable: status, errors; counts, "
                  "seconds, provenance) as JSON to this file");
  cmd->callback([args, exit_code, accuracy] {
    args->accuracy_given = accuracy->count() > 0;
    *exit_code = RunRelax(*args);
  });
}

}  // namespace cablefit::addin
