// The facade over addin/app: the relax pipeline's stages (one input, groups in order, no worker
// pool: FreeCAD calls it from its GUI thread and shows the progress), and DiagnoseCase + the
// CLI's per-case writers.
#include "cablefit_facade.h"

#include <chrono>
#include <exception>
#include <filesystem>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/colour_map.h"
#include "cablefit/app/diagnose/diagnose_case.h"
#include "cablefit/app/pipeline/diagnose_pipeline.h"
#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/pipeline/relax_pipeline.h"
#include "cablefit/app/output/relax_file.h"
#include "cablefit/app/motion/relax_motion.h"
#include "cablefit/app/report/relax_report.h"

namespace cablefit::freecad {

struct RelaxedFile {
  addin::RelaxedFile file;
  addin::HarnessConfig config;
};

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

CableSummary Summarise(const addin::RelaxedFile& f, const addin::HarnessConfig& config, int i) {
  const size_t k = static_cast<size_t>(i);
  const DrawnCable& drawn = f.drawing.cables[k];
  CableSummary c;
  c.name = drawn.name;
  c.drawn = drawn.centreline.points;
  c.diameter = addin::OutputDiameter(f, i, config);
  if (!f.cables[k]) {
    c.error = f.cable_errors[k];
    c.length = drawn.centreline.size() > 0 ? drawn.centreline.s[drawn.centreline.size() - 1] : 0;
    return c;
  }
  const addin::CableRelaxation& r = *f.cables[k];
  const RodSpec& spec = r.setup.spec;
  c.ok = true;
  c.length = spec.length;
  c.drawn = r.setup.route.points;
  c.s = r.relaxed.s;
  c.relaxed = r.relaxed.points;
  c.deviation = r.deviation;
  c.max_deviation = r.max_deviation;
  c.rms_deviation = r.rms_deviation;
  c.max_deviation_s = r.max_deviation_s;
  c.min_bend_radius = r.min_bend_radius;
  c.bend_limit = r.bend_limit;
  c.bend_flag = r.bend_flag;
  c.stable = r.result.solution.summary.stable;
  c.material_source = r.setup.material_source;
  c.material_defaulted = r.setup.material_defaulted;
  c.bending_stiffness = spec.material.bending_stiffness;
  c.linear_density = spec.material.linear_density;
  c.gravity = spec.gravity;
  for (size_t j = 0; j < spec.supports.size(); ++j) {
    const SupportSpec& sp = spec.supports[j];
    c.supports.push_back(
        {ToString(sp.kind), r.setup.support_origin[j], sp.s, sp.position, sp.sliding});
  }
  c.notes = r.setup.notes;
  c.iterations = r.result.newton_iterations;
  c.seconds = r.seconds;
  return c;
}

MotionSummary SummariseMotion(const addin::FileMotion& m) {
  MotionSummary out;
  out.name = m.config.name;
  out.kind = m.config.KindName();
  out.unit = m.config.kind == addin::MotionConfig::Kind::kRotation ? "rad"
             : m.config.kind == addin::MotionConfig::Kind::kPoses  ? "pose"
                                                                   : "m";
  out.q = m.q;
  out.problems = m.problems;
  out.seconds = m.seconds;
  for (const addin::CableMotion& cm : m.cables) {
    SweptCableSummary c;
    c.cable = cm.cable;
    c.name = cm.name;
    c.branch_lost_pose = cm.branch_lost_pose;
    c.completed = cm.completed;
    c.message = cm.message;
    c.back_to_start = cm.back_to_start;
    c.seconds = cm.seconds;
    for (const addin::MotionPose& p : cm.poses) {
      MotionPoseSummary ps;
      ps.q = p.q;
      ps.converged = p.converged;
      ps.stable = p.stable;
      ps.escaped_unstable = p.escaped_unstable;
      ps.jumped = p.jumped;
      ps.min_bend_radius = p.min_bend_radius;
      ps.min_bend_radius_s = p.min_bend_radius_s;
      ps.bend_flag = p.bend_flag;
      ps.max_tension = p.max_tension;
      ps.max_tension_s = p.max_tension_s;
      ps.clearance = p.clearance.clearance;
      ps.clearance_s = p.clearance.s;
      ps.clearance_required = p.clearance_required;
      ps.clearance_to = p.clearance_to;
      ps.s = p.centreline.s;
      ps.centreline = p.centreline.points;
      c.poses.push_back(std::move(ps));
    }
    out.cables.push_back(std::move(c));
  }
  return out;
}

}  // namespace

HarnessRelaxation HarnessRelaxation::Run(const std::string& input, const std::string& config_path,
                                         double accuracy, const std::string& mesh_unit,
                                         double timeout, const ProgressCallback& progress) {
  // The relax pipeline's stages one by one, in order on this (FreeCAD's GUI) thread, so that the
  // progress can be told per group and a cancel stops between groups. Tolerances are left to the
  // command line: the workbench has no view of them.
  addin::RelaxOptions options;
  options.config_path = config_path;
  options.accuracy = accuracy;  // <= 0: the input's default
  options.mesh_unit = mesh_unit;
  options.timeout = timeout;
  options.jobs = 1;
  options.tolerance = false;
  addin::RelaxPipeline pipeline(options);
  const int i = pipeline.AddInput(input, fs::path(input).stem().string());
  // A cancel while reading takes effect once the drawing is read (its cables are listed, each
  // failing with "cancelled"): reading itself checks the cancellation scope.
  const bool cancel_at_read =
      progress && !progress(0.0, "read " + fs::path(input).filename().string());
  pipeline.ReadInput(i);
  // One cancellation scope for the solves: a progress call returning false trips it (here or in
  // the solver's continuation steps), and every group after that fails with "cancelled".
  const CancellationScope run;
  if (cancel_at_read) RequestCancellation();
  auto report = [&](double fraction, const std::string& stage) {
    if (progress && !progress(fraction, stage)) RequestCancellation();
  };
  const addin::HarnessConfig config = pipeline.ConfigFor(i);
  addin::RelaxedFile& f = pipeline.files()[static_cast<size_t>(i)];
  std::vector<addin::RelaxJob> jobs = pipeline.GroupInput(i);
  const double ng = static_cast<double>(jobs.size());
  // A motion gets the last part of the bar: its poses are solves of their own.
  const double relax_share = config.motion ? 0.8 : 1.0;
  SimulationOptions simulation = pipeline.SimulationOptionsFor(i);
  for (size_t g = 0; g < jobs.size(); ++g) {
    const std::string label = addin::GroupLabel(f.drawing, jobs[g].group);
    // Continuation steps report inside the group's share of the bar.
    simulation.statics.progress = [&](double fraction, const std::string& stage) {
      return !progress ||
             progress(relax_share * (g + 0.1 + 0.8 * fraction) / ng, label + ": " + stage);
    };
    if (!CancellationRequested()) report(relax_share * (g + 0.05) / ng, "relax " + label);
    pipeline.RelaxGroupOf(&jobs[g], simulation, static_cast<int>(g));
  }
  pipeline.CollectJobs(&jobs);
  // Then what the command line does per file once its cables are relaxed: clearances and the
  // motion, with the same options (the groups' progress callback refers to this loop's state).
  simulation.statics.progress = {};
  if (!CancellationRequested()) {
    pipeline.MeasureClearance(i);
    if (config.motion) {
      const std::string label = "motion '" + config.motion->name + "'";
      report(relax_share, label);
      simulation.statics.progress = [&](double, const std::string& stage) {
        // A sweep does not say how far it is: the bar stays in the motion's part.
        return !progress || progress(relax_share + 0.5 * (1 - relax_share), label + ": " + stage);
      };
      pipeline.SweepMotion(i, simulation);
    }
  }
  if (progress) progress(1.0, CancellationRequested() ? "cancelled" : "relaxed");

  auto state = std::make_shared<RelaxedFile>();
  state->file = std::move(f);
  state->config = config;
  HarnessRelaxation out;
  out.file_ = state;
  const size_t n = state->file.drawing.cables.size();
  for (size_t c = 0; c < n; ++c)
    out.cables_.push_back(Summarise(state->file, state->config, static_cast<int>(c)));
  if (state->file.motion) out.motion_ = SummariseMotion(*state->file.motion);
  return out;
}

std::vector<std::string> HarnessRelaxation::solid_names() const {
  std::vector<std::string> names;
  for (const DrawnSolid& s : file_->file.drawing.solids) names.push_back(s.name);
  return names;
}

double HarnessRelaxation::read_seconds() const { return file_->file.times.read; }

namespace {

// The file is written with every cable that could be swept; the caller still learns about the
// others, as the command line reports them.
void ThrowIfCablesLeftOut(const std::string& path, const std::vector<std::string>& left_out) {
  if (left_out.empty()) return;
  std::string problem = left_out.front();
  if (left_out.size() > 1) problem += " and " + std::to_string(left_out.size() - 1) + " more";
  throw FileError(path, problem);
}

// The centreline of `cable` at `pose` of the file's motion, checked: the tube of a pose is
// swept along it exactly as the relaxed cable's tube along its relaxed centreline.
const Polyline& PoseCentreline(const addin::RelaxedFile& f, int cable, int pose) {
  if (!f.motion) throw InvalidInput("the harness has no motion: harness.json has no \"motion\"");
  for (const addin::CableMotion& m : f.motion->cables) {
    if (m.cable != cable) continue;
    if (pose >= static_cast<int>(m.poses.size()))
      throw InvalidInput("cable '" + m.name + "' has " + std::to_string(m.poses.size()) +
                         " poses, not pose " + std::to_string(pose));
    // The poses keep no material frames: a flat strip's wide axis would be the relaxed one's.
    if (f.drawing.cables[static_cast<size_t>(cable)].flat)
      throw InvalidInput("cable '" + m.name + "' is a flat cable: its poses are not written yet");
    return m.poses[static_cast<size_t>(pose)].centreline;
  }
  throw InvalidInput("cable " + std::to_string(cable) + " is not moved by the motion");
}

}  // namespace

void HarnessRelaxation::WriteStep(const std::string& path, bool with_solids, int cable,
                                  int pose) const {
  const addin::RelaxedFile& f = file_->file;
  if (pose >= 0 && cable < 0) throw InvalidInput("a pose is written for one cable: name it");
  if (with_solids && cable < 0) {
    ThrowIfCablesLeftOut(path, addin::WriteRelaxedStepFile(path, f, file_->config));
    return;
  }
  addin::RelaxedFile part = f;  // the solids' shapes are shared, not copied
  if (!with_solids) part.drawing.solids.clear();
  if (cable >= 0) {
    if (cable >= static_cast<int>(f.cables.size())) {
      throw InvalidInput("cable " + std::to_string(cable) + " does not exist (" +
                         std::to_string(f.cables.size()) + " cables)");
    }
    const size_t k = static_cast<size_t>(cable);
    part.drawing.cables = {f.drawing.cables[k]};
    part.drawing.junctions.clear();
    part.cables = {f.cables[k]};
    part.cable_errors = {f.cable_errors[k]};
    if (pose >= 0) part.cables[0]->relaxed = PoseCentreline(f, cable, pose);
  }
  ThrowIfCablesLeftOut(path, addin::WriteRelaxedStepFile(path, part, file_->config));
}

std::string HarnessRelaxation::WriteReport(const std::string& dir, bool pictures) const {
  addin::RelaxedFile f = file_->file;
  const addin::HarnessConfig& config = file_->config;
  const fs::path out(dir);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw FileError(dir, "cannot create folder: " + ec.message());
  auto t0 = Clock::now();
  json::WriteJsonFile((out / (f.stem + ".json")).string(), addin::RelaxedFileToJson(f, config));
  f.times.json = Since(t0);
  t0 = Clock::now();
  const std::vector<std::string> left_out =
      addin::WriteRelaxedStepFile((out / (f.stem + ".step")).string(), f, config);
  f.times.step = Since(t0);
  if (pictures) {
    t0 = Clock::now();
    f.picture = f.stem + "-deviation.png";
    addin::WriteDeviationPicture((out / f.picture).string(), f, config);
    f.times.picture = Since(t0);
  }
  const std::string report = (out / "report.html").string();
  addin::WriteRelaxReport(report, {f}, config, f.times.read + f.times.relax);
  ThrowIfCablesLeftOut((out / (f.stem + ".step")).string(), left_out);
  return report;
}

std::array<double, 3> DeviationColour(double value, double lo, double hi) {
  ColourScale scale;
  scale.min = lo;
  scale.max = hi;
  std::string why;
  if (!scale.IsValid(&why)) throw InvalidInput("colour scale: " + why);
  const Rgb c = scale.Map(value);
  return {c.r / 255.0, c.g / 255.0, c.b / 255.0};
}

DiagnosisSummary DiagnoseRecording(const std::string& case_file, const std::string& report_dir,
                                   const ProgressCallback& progress) {
  const addin::DiagnosedCase d = addin::DiagnosePipeline::DiagnoseAndWrite(
      case_file, addin::DiagnoseCaseOptions(), report_dir, progress);
  DiagnosisSummary s;
  s.name = d.recording.name;
  s.kind = addin::ToString(d.kind);
  s.effect = d.effect;
  s.confidence = d.confidence;
  s.interval = d.interval;
  s.parameters = d.parameters;
  s.candidates = d.candidates;
  for (const addin::FoundEffectSummary& f : d.effects) s.effects.emplace_back(f.effect, f.share);
  s.baseline_max = d.baseline.max;
  s.fitted_max = d.fitted.max;
  s.deviation_unit = d.deviation_unit;
  s.explanation = d.explanation;
  s.observation_source = d.observation_source;
  s.scan_points = d.scan_points;
  s.observation = d.observation.points;
  if (d.shape) {
    s.nominal = d.shape->nominal_solution.centerline.points;
    s.fitted = d.shape->fitted_solution.centerline.points;
  }
  s.notes = d.notes;
  s.seconds = d.seconds;
  if (!report_dir.empty()) s.report = (fs::path(report_dir) / "report.html").string();
  return s;
}

}  // namespace cablefit::freecad
