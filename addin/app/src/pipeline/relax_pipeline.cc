#include "cablefit/app/pipeline/relax_pipeline.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>
#include <tuple>

#include "cablefit/app/base/batch_pool.h"
#include "cablefit/app/config/cable_selection.h"
#include "cablefit/app/input/harness_input.h"
#include "cablefit/app/input/kbl_input.h"
#include "cablefit/app/output/output_folder.h"
#include "cablefit/app/output/relax_envelope.h"
#include "cablefit/app/output/relax_motion_pictures.h"
#include "cablefit/app/report/relax_report.h"
#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "pipeline/relax_inputs.h"
#include "pipeline/relax_lines.h"

namespace cablefit::addin {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Where a failure comes from, so that a file's failures are listed in the order of the work
// whatever thread found them first.
enum Stage { kReadStage = 1, kGroupStage, kRelaxStage, kStepStage, kWriteStage };

}  // namespace

RelaxPipeline::RelaxPipeline(RelaxOptions options, RunObserver* observer)
    : options_(std::move(options)), observer_(observer) {
  mesh_unit_ = UnitInMetres(options_.mesh_unit);
  if (!options_.config_path.empty()) config_ = ReadHarnessConfig(options_.config_path);
  if (!(options_.accuracy <= 0)) simulation_.accuracy = options_.accuracy;  // NaN too: rejected
  std::string why;
  if (!simulation_.IsValid(&why)) throw InvalidInput("accuracy: " + why);
}

void RelaxPipeline::Say(RunMessage kind, const std::string& text) const {
  if (observer_) observer_->Message(kind, text);
}

void RelaxPipeline::Progress(int slot, double fraction, const std::string& stage) const {
  if (observer_) observer_->Progress(slot, fraction, stage);
}

void RelaxPipeline::Finished(int slot) const {
  if (observer_) observer_->Finished(slot);
}

void RelaxPipeline::Fail(int file, const std::string& problem, int stage, int order) {
  {
    std::lock_guard lock(*failures_mutex_);
    failure_log_.push_back({stage, file, order, problem});
  }
  Say(RunMessage::kProblem, files_[static_cast<size_t>(file)].input + ": " + problem);
}

int RelaxPipeline::AddInput(const std::string& path, const std::string& stem) {
  RelaxedFile f;
  f.input = path;
  f.stem = stem;
  files_.push_back(std::move(f));
  boxes_.emplace_back();
  return static_cast<int>(files_.size()) - 1;
}

SimulationOptions RelaxPipeline::SimulationOptionsFor(int i) const {
  SimulationOptions o = simulation_;
  // A KBL harness is relaxed to kKblAccuracy unless an accuracy was asked for.
  if (options_.accuracy <= 0 && files_[static_cast<size_t>(i)].own_config != nullptr)
    o.accuracy = kKblAccuracy;
  return o;
}

const HarnessConfig& RelaxPipeline::ConfigFor(int i) const {
  return ConfigOf(files_[static_cast<size_t>(i)], config_);
}

void RelaxPipeline::ReadInput(int i) {
  RelaxedFile& f = files_[static_cast<size_t>(i)];
  {
    const auto t0 = Clock::now();
    struct ReadTime {  // also when reading throws: the time it took to fail
      double* seconds;
      Clock::time_point t0;
      ~ReadTime() { *seconds = Since(t0); }
    } read_time{&f.times.read, t0};
    std::unique_lock lock(*cad_mutex_, std::defer_lock);
    if (IsCadPath(f.input)) lock.lock();
    if (IsKblInput(f.input)) {
      // The file's own physics per segment, the user's harness.json over it.
      KblInput kbl = ReadKblInput(f.input, config_);
      f.drawing = std::move(kbl.drawing);
      f.own_config = std::make_shared<const HarnessConfig>(std::move(kbl.config));
      f.cable_json = std::move(kbl.cable_json);
      f.notes = std::move(kbl.notes);
    } else {
      f.drawing = ReadHarnessInput(f.input, mesh_unit_);
    }
    ApplyCableSelection(config_, &f.drawing);
    f.read_ok = true;
    for (const std::string& why : f.drawing.skipped)
      Say(RunMessage::kNote, f.input + ": not taken as a cable: " + why);
    for (const std::string& why : f.drawing.warnings) Say(RunMessage::kWarning, f.input + ": " + why);
    for (const std::string& note : f.notes) Say(RunMessage::kNote, f.input + ": " + note);
    f.cables.resize(f.drawing.cables.size());
    f.cable_errors.resize(f.drawing.cables.size());
  }
  boxes_[static_cast<size_t>(i)] = SolidBoxes(f.drawing);
}

std::vector<RelaxJob> RelaxPipeline::GroupInput(int i) const {
  std::vector<RelaxJob> jobs;
  const RelaxedFile& f = files_[static_cast<size_t>(i)];
  for (RelaxGroup& g : GroupCables(f.drawing, boxes_[static_cast<size_t>(i)], ConfigFor(i))) {
    RelaxJob job;
    job.file = i;
    job.group = std::move(g);
    jobs.push_back(std::move(job));
  }
  return jobs;
}

void RelaxPipeline::RelaxGroupOf(RelaxJob* job, const SimulationOptions& options, int order) {
  const auto t0 = Clock::now();
  RelaxedFile& f = files_[static_cast<size_t>(job->file)];
  GroupOutcome g;
  if (!CancellationRequested()) {
    const CancellationScope deadline(options_.timeout);  // the solvers check it
    g = RelaxGroupCables(f.drawing, job->group, boxes_[static_cast<size_t>(job->file)],
                         ConfigFor(job->file), options);
  }
  // The caller's own scope (the FreeCAD module's progress) was cancelled, before or during it.
  if (CancellationRequested()) g.problem = "cancelled";
  job->network = std::move(g.network);
  job->measure_seconds = g.measure_seconds;
  if (g.problem.empty()) {
    for (CableRelaxation& r : g.cables) {
      Say(RunMessage::kDetail, CableLine(f, r));
      f.cables[static_cast<size_t>(r.setup.cable)] = std::move(r);
    }
    for (const auto& [c, why] : g.cable_problems) {
      f.cable_errors[static_cast<size_t>(c)] = why;
      Fail(job->file, "cable '" + f.drawing.cables[static_cast<size_t>(c)].name + "': " + why,
           kRelaxStage, order);
    }
  } else {
    for (int c : job->group.cables) f.cable_errors[static_cast<size_t>(c)] = g.problem;
    Fail(job->file,
         (job->group.cables.size() > 1 ? "cables '" : "cable '") +
             GroupLabel(f.drawing, job->group) + "': " + g.problem,
         kRelaxStage, order);
  }
  job->seconds = Since(t0);
}

void RelaxPipeline::CollectJobs(std::vector<RelaxJob>* jobs) {
  for (RelaxJob& job : *jobs) {
    RelaxedFile& f = files_[static_cast<size_t>(job.file)];
    if (!job.network.is_null()) f.networks.push_back(std::move(job.network));
    f.times.relax += job.seconds;
    seconds_.relax += job.seconds - job.measure_seconds;
    seconds_.measure += job.measure_seconds;
  }
}

void RelaxPipeline::MeasureClearance(int i) {
  const auto t0 = Clock::now();
  RelaxedFile& f = files_[static_cast<size_t>(i)];
  f.clearances = MeasureHarnessClearances(ConfigFor(i), f);
  for (const ClearancePair& p : f.clearances)
    if (p.violation()) Say(RunMessage::kResult, f.stem + ": CLEARANCE: " + ClearanceViolationText(p));
  seconds_.clearance += Since(t0);
}

void RelaxPipeline::SweepMotion(int i, const SimulationOptions& options) {
  const auto t0 = Clock::now();
  RelaxedFile& f = files_[static_cast<size_t>(i)];
  f.motion = SweepHarnessMotion(ConfigFor(i), options, f);  // unset without a motion
  if (f.motion)
    for (const std::string& line : MotionLines(*f.motion)) Say(RunMessage::kResult, f.stem + ": " + line);
  seconds_.motion += Since(t0);
}

void RelaxPipeline::VaryTolerances(int i) {
  if (!options_.tolerance) return;
  const auto t0 = Clock::now();
  RelaxedFile& f = files_[static_cast<size_t>(i)];
  // One input at a time, its set-ups on every worker.
  f.tolerance = VaryHarnessTolerances(ConfigFor(i), SimulationOptionsFor(i), f,
                                      ResolveJobs(options_.jobs, 1 << 20));
  if (f.tolerance)
    for (const std::string& line : ToleranceLines(*f.tolerance)) Say(RunMessage::kResult, f.stem + ": " + line);
  seconds_.tolerance += Since(t0);
}

void RelaxPipeline::WriteInput(int i) {
  RelaxedFile& f = files_[static_cast<size_t>(i)];
  const HarnessConfig& config = ConfigFor(i);
  const fs::path out(options_.out_dir);
  const int slot = 2 * static_cast<int>(files_.size()) + i;
  Progress(slot, 0.1, f.stem + ": write JSON, STEP");
  auto t0 = Clock::now();
  // The envelopes first: the JSON names them.
  f.envelopes = WriteEnvelopeFiles(out.string(), f, config);
  json::WriteJsonFile((out / (f.stem + ".json")).string(), RelaxedFileToJson(f, config));
  f.times.json = Since(t0);
  t0 = Clock::now();
  {
    std::lock_guard lock(*cad_mutex_);
    int order = 0;
    for (const std::string& problem : WriteRelaxedStepFile((out / (f.stem + ".step")).string(), f, config))
      Fail(i, problem, kStepStage, order++);
  }
  f.times.step = Since(t0);
  if (options_.pictures) {
    Progress(slot, 0.5, f.stem + ": picture");
    t0 = Clock::now();
    f.picture = f.stem + "-deviation.png";
    // Also under the CAD lock: a crash was once seen with OSMesa rendering while OCCT wrote
    // another file (not reproduced since); both spawn their own worker threads.
    std::lock_guard lock(*cad_mutex_);
    WriteDeviationPicture((out / f.picture).string(), f, config);
    if (options_.close_ups) f.close_ups = WriteCloseUpPictures(out.string(), f, config);
    f.motion_pictures = WriteMotionAnimation(out.string(), f, config);
    f.times.picture = Since(t0);
  }
  Say(RunMessage::kDetail, InputLine(f));
}

std::string RelaxPipeline::WriteReport() {
  const auto t0 = Clock::now();
  const std::string path = (fs::path(options_.out_dir) / "report.html").string();
  WriteRelaxReport(path, files_, config_, Since(start_));
  seconds_.report += Since(t0);
  return path;
}

std::vector<std::string> RelaxPipeline::PlanOutputs(const std::vector<std::string>& inputs,
                                                    std::vector<std::string>* failures) {
  const std::vector<std::string> paths = ExpandInputs(inputs, failures);
  for (const std::string& f : *failures) Say(RunMessage::kProblem, f);
  const std::vector<std::string> stems = UniqueStems(paths);
  // Nothing is written over an input, checked before anything is read.
  std::vector<std::string> all = inputs;
  all.insert(all.end(), paths.begin(), paths.end());
  if (!options_.config_path.empty()) all.push_back(options_.config_path);
  const OutputFolder output(options_.out_dir, all);
  const fs::path& out = output.path();
  output.CheckFile(out / "report.html");
  if (!options_.summary_json.empty()) CheckSummaryJsonPath(options_.summary_json, all);
  for (const std::string& stem : stems) {
    for (const char* suffix : {".step", ".json", "-deviation.png"}) output.CheckFile(out / (stem + suffix));
    for (const std::string& name : EnvelopeFileNames(stem)) output.CheckFile(out / name);
    output.CheckFile(out / (stem + "-motion.png"));
    output.CheckFolder(out / MotionFramesFolder(stem));
  }
  for (size_t i = 0; i < paths.size(); ++i) AddInput(paths[i], stems[i]);
  return paths;
}

void RelaxPipeline::ReadAll() {
  const int n = static_cast<int>(files_.size());
  RunBatch(n, ResolveJobs(options_.jobs, n), [&](int i) {
    Progress(i, 0.5, files_[static_cast<size_t>(i)].stem + ": read");
    try {
      ReadInput(i);
    } catch (...) {
      Fail(i, ErrorText(std::current_exception()), kReadStage);
    }
    Finished(i);
  });
  for (const RelaxedFile& f : files_) seconds_.read += f.times.read;
}

void RelaxPipeline::WarnUnusedConfigEntries() {
  // A harness.json entry that names no cable is most likely a typo: said, not a failure (the
  // same sidecar may serve several drawings).
  for (const auto& [name, unused] : config_.cables) {
    bool found = false;
    for (const RelaxedFile& f : files_)
      for (const DrawnCable& c : f.drawing.cables) found = found || c.name == name;
    if (!found)
      Say(RunMessage::kWarning, config_.path + ": cables." + name + " matches no cable of the inputs");
  }
}

void RelaxPipeline::RelaxAll() {
  const int n = static_cast<int>(files_.size());
  std::vector<RelaxJob> jobs;
  for (int i = 0; i < n; ++i) {
    if (!files_[static_cast<size_t>(i)].read_ok) continue;
    try {
      for (RelaxJob& job : GroupInput(i)) jobs.push_back(std::move(job));
    } catch (...) {
      Fail(i, ErrorText(std::current_exception()), kGroupStage);
    }
  }
  const int nj = static_cast<int>(jobs.size());
  RunBatch(nj, ResolveJobs(options_.jobs, nj), [&](int k) {
    RelaxJob& job = jobs[static_cast<size_t>(k)];
    const RelaxedFile& f = files_[static_cast<size_t>(job.file)];
    Progress(n + job.file,
             static_cast<double>(job.group.cables.front()) / static_cast<double>(f.drawing.cables.size()),
             f.stem + ": relax " + GroupLabel(f.drawing, job.group));
    RelaxGroupOf(&job, SimulationOptionsFor(job.file), k);
  });
  CollectJobs(&jobs);
}

void RelaxPipeline::MeasureAll() {
  for (int i = 0; i < static_cast<int>(files_.size()); ++i) {
    if (!files_[static_cast<size_t>(i)].read_ok) continue;
    MeasureClearance(i);
    SweepMotion(i, SimulationOptionsFor(i));
    VaryTolerances(i);
  }
}

void RelaxPipeline::WriteAll() {
  const int n = static_cast<int>(files_.size());
  RunBatch(n, ResolveJobs(options_.jobs, n), [&](int i) {
    RelaxedFile& f = files_[static_cast<size_t>(i)];
    Finished(n + i);
    if (f.read_ok) {
      try {
        WriteInput(i);
      } catch (const FileError& e) {
        // Names the output that could not be written: the input is not to blame.
        Fail(i, std::string("its results could not be written: ") + e.what(), kWriteStage);
      } catch (...) {
        Fail(i, ErrorText(std::current_exception()), kWriteStage);
      }
    }
    Finished(2 * n + i);
  });
  for (const RelaxedFile& f : files_) {
    seconds_.json += f.times.json;
    seconds_.step += f.times.step;
    seconds_.pictures += f.times.picture;
  }
}

RelaxSummary RelaxPipeline::Finish(std::vector<std::string> failures) {
  // Failures were said as they happened; listed (and a file's first problem kept) in the order
  // of the work, not of the threads: the same run gives the same list and JSON.
  std::stable_sort(failure_log_.begin(), failure_log_.end(), [](const Failure& x, const Failure& y) {
    return std::tie(x.file, x.stage, x.order) < std::tie(y.file, y.stage, y.order);
  });
  for (const Failure& e : failure_log_) {
    RelaxedFile& f = files_[static_cast<size_t>(e.file)];
    if (f.error.empty()) f.error = e.text;
    failures.push_back(f.input + ": " + e.text);
  }
  RelaxSummary summary;
  summary.any_read = std::any_of(files_.begin(), files_.end(), [](const RelaxedFile& f) { return f.read_ok; });
  if (summary.any_read) {
    summary.report = (fs::path(options_.out_dir) / "report.html").string();
    try {
      WriteReport();
    } catch (const std::exception& e) {
      failures.push_back(std::string("report.html: ") + e.what());
      Say(RunMessage::kProblem, e.what());
    }
  }
  Finished(3 * static_cast<int>(files_.size()));
  if (!options_.summary_json.empty()) {
    try {
      seconds_.total = Since(start_);
      json::Json j = RelaxSummaryJson(files_, failures, config_.path, seconds_.total);
      j["stage_seconds"] = StageSecondsJson(seconds_);
      json::WriteJsonFile(options_.summary_json, j);
    } catch (const std::exception& e) {
      failures.push_back(options_.summary_json + ": " + OneLine(e.what()));
      Say(RunMessage::kProblem, failures.back());
    }
  }
  summary.counts = CountRelaxation(files_);
  summary.failures = std::move(failures);
  seconds_.total = Since(start_);
  summary.seconds = seconds_;
  return summary;
}

RelaxSummary RelaxPipeline::Run(const std::vector<std::string>& inputs) {
  start_ = Clock::now();
  std::vector<std::string> failures;  // "<file>: <problem>"
  PlanOutputs(inputs, &failures);
  if (observer_) observer_->Started(Slots(static_cast<int>(files_.size())));
  ReadAll();
  WarnUnusedConfigEntries();
  // The STEP writer's sweep helpers load OpenCASCADE while the cables relax (this thread lives
  // until they are used or let go).
  for (const RelaxedFile& f : files_) {
    if (!f.read_ok || f.drawing.cables.empty()) continue;
    PrepareRelaxedStep(f.drawing.cables.size());
    break;
  }
  // The renderer's start-up (OSMesa, llvmpipe compiling its shaders) on a core of its own while
  // the cables relax; no OpenCASCADE work runs in this process until the write stage (see
  // cad_mutex_).
  std::jthread warm_up;  // joined on every way out
  if (options_.pictures &&
      std::any_of(files_.begin(), files_.end(), [](const RelaxedFile& f) { return f.read_ok; }))
    warm_up = std::jthread(WarmUpDeviationPictures);
  RelaxAll();
  MeasureAll();
  if (warm_up.joinable()) warm_up.join();
  WriteAll();
  return Finish(std::move(failures));
}

}  // namespace cablefit::addin
