// The relax run as one object, in the style of the core's solvers (Options in, Summary out):
// read every input -> configure it (harness.json, a KBL file's own physics, rigid parts) ->
// group its cables (alone, or networks joined at breakouts / touching solids) -> relax and
// measure each group -> clearance, motion and tolerances per input -> write each input's
// STEP/JSON/envelopes/pictures -> report.html. `cablefit relax` calls Run(); the FreeCAD module
// drives the stages itself (one input, in order, on its GUI thread with its own progress), so
// both relax through the same code.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/pipeline/run_observer.h"
#include "cablefit/app/pipeline/stage_seconds.h"
#include "cablefit/app/output/relax_file.h"
#include "cablefit/app/relax/relax_network.h"
#include "cablefit/app/report/relax_summary.h"
#include "cablefit/core/solver/rod_simulation.h"

namespace cablefit::addin {

struct RelaxOptions {
  std::string out_dir;      ///< output folder (Run and the write stages only)
  std::string config_path;  ///< harness.json, empty = none
  int jobs = 0;             ///< parallel workers, 0 = one per core
  std::string mesh_unit = "mm";  ///< length unit of mesh files
  /// [m] requested accuracy of the relaxed positions; 0 = the default of each input (kKblAccuracy
  /// for a KBL harness, SimulationOptions' otherwise).
  double accuracy = 0.0;
  double timeout = 0.0;     ///< [s] per group of cables solved together, 0 = no limit
  bool pictures = true;     ///< deviation pictures and the motion's animation
  bool close_ups = false;   ///< also one picture per cable
  bool tolerance = true;    ///< run harness.json's tolerances (the FreeCAD module does not)
  std::string summary_json;  ///< also write the run summary as JSON here, empty = none
};

struct RelaxSummary {
  RelaxCounts counts;
  RelaxStageSeconds seconds;
  std::vector<std::string> failures;  ///< "<file>: <problem>", in the order of the work
  bool any_read = false;              ///< false: nothing could be read (a usage error)
  std::string report;  ///< report.html's path when any input was read (failures say if unwritten)
};

/// One group of cables of one input, solved together: the unit of work of the relax stage.
struct RelaxJob {
  int file = 0;
  RelaxGroup group;
  json::Json network;    ///< the group's network JSON (junction loads, contacts) when it has one
  double seconds = 0.0;  ///< solve and measure
  double measure_seconds = 0.0;
};

class RelaxPipeline {
 public:
  /// Reads harness.json and checks the options. Throws InvalidInput/FileError (usage errors:
  /// nothing was read yet). `observer` may be null and must outlive the pipeline.
  explicit RelaxPipeline(RelaxOptions options, RunObserver* observer = nullptr);

  /// The whole run for the inputs (files or folders of them): each stage in parallel over
  /// `jobs` workers; CAD I/O serialised (OCCT's readers and writers keep global state). A bad
  /// input or cable fails alone (RelaxSummary::failures); output folder and --summary-json
  /// problems throw InvalidInput before anything is read.
  RelaxSummary Run(const std::vector<std::string>& inputs);

  /// Progress slots of a run of `inputs` files: read, relax and write per input, and the report
  /// (RunObserver::Started).
  static int Slots(int inputs) { return 3 * inputs + 1; }

  // ---- The stages, for a caller that runs them itself (one input at a time, in order). ----
  /// Adds an input to read as `stem`; returns its index.
  int AddInput(const std::string& path, const std::string& stem);
  /// Reads input `i` (CAD, mesh or KBL with its own physics) and takes out harness.json's rigid
  /// parts. Throws FileError/InvalidInput.
  void ReadInput(int i);
  /// The groups input `i` is solved in, in the order of its cables. Throws InvalidInput.
  std::vector<RelaxJob> GroupInput(int i) const;
  /// Solves one group (within options().timeout, unless the caller's scope is already
  /// cancelled: then its cables fail as "cancelled") and keeps its cables in their input;
  /// `order` ranks its failures among the run's. `options`: SimulationOptionsFor(job.file),
  /// maybe with a progress callback.
  void RelaxGroupOf(RelaxJob* job, const SimulationOptions& options, int order);
  /// The networks and solve times of finished jobs, into their inputs in job order.
  void CollectJobs(std::vector<RelaxJob>* jobs);
  /// Clearance of the relaxed cables of input `i` to its solids and each other.
  void MeasureClearance(int i);
  /// The harness.json motion on input `i`, if any.
  void SweepMotion(int i, const SimulationOptions& options);
  /// The harness.json tolerances on input `i`, if any (its set-ups on every worker).
  void VaryTolerances(int i);
  /// Writes input `i`'s envelopes, JSON, STEP and pictures into options().out_dir.
  void WriteInput(int i);
  /// report.html over every input; its path.
  std::string WriteReport();

  /// The simulation options input `i` is relaxed with (its accuracy).
  SimulationOptions SimulationOptionsFor(int i) const;
  /// The settings input `i` is relaxed with: its own (a KBL file's), else the run's.
  const HarnessConfig& ConfigFor(int i) const;
  const RelaxOptions& options() const { return options_; }
  const HarnessConfig& config() const { return config_; }
  std::vector<RelaxedFile>& files() { return files_; }
  const std::vector<RelaxedFile>& files() const { return files_; }
  const RelaxStageSeconds& seconds() const { return seconds_; }

 private:
  struct Failure {
    int stage, file, order;
    std::string text;
  };
  std::vector<std::string> PlanOutputs(const std::vector<std::string>& inputs,
                                       std::vector<std::string>* failures);
  void ReadAll();
  void WarnUnusedConfigEntries();
  void RelaxAll();
  void MeasureAll();
  void WriteAll();
  RelaxSummary Finish(std::vector<std::string> failures);
  void Fail(int file, const std::string& problem, int stage, int order = 0);
  void Say(RunMessage kind, const std::string& text) const;
  void Progress(int slot, double fraction, const std::string& stage) const;
  void Finished(int slot) const;

  RelaxOptions options_;
  RunObserver* observer_;
  HarnessConfig config_;
  SimulationOptions simulation_;
  double mesh_unit_ = 1e-3;  // [m] per mesh file unit
  std::vector<RelaxedFile> files_;
  std::vector<std::vector<OrientedBox>> boxes_;  // per input, its solids' boxes
  std::vector<Failure> failure_log_;
  RelaxStageSeconds seconds_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::unique_ptr<std::mutex> cad_mutex_ = std::make_unique<std::mutex>();
  std::unique_ptr<std::mutex> failures_mutex_ = std::make_unique<std::mutex>();
};

}  // namespace cablefit::addin
