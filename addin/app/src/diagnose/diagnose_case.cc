#include "cablefit/app/diagnose/diagnose_case.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <filesystem>

#include "cablefit/app/diagnose/shape_explanation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/force_curve_csv.h"
#include "cablefit/formats/ply_reader.h"
#include "cablefit/formats/scan_centerline_extractor.h"
#include "diagnose/diagnose_observation.h"

namespace cablefit::addin {
namespace {

using Clock = std::chrono::steady_clock;

/// Forwards progress of one stage, mapped onto [begin, end] of the whole case.
ProgressCallback Stage(const ProgressCallback& progress, double begin, double end) {
  if (!progress) return {};
  return [progress, begin, end](double f, const std::string& stage) {
    return progress(begin + (end - begin) * std::clamp(f, 0.0, 1.0), stage);
  };
}

void Report(const ProgressCallback& progress, double f, const std::string& stage) {
  if (progress) progress(f, stage);
}

/// Runs `fn`, turning a bare InvalidInput (no file in it) into a FileError naming `file`.
template <typename Fn>
auto Blame(const std::string& file, Fn&& fn) {
  try {
    return fn();
  } catch (const FileError&) {
    throw;
  } catch (const InvalidInput& e) {
    throw FileError(file, e.what());
  }
}

std::string FormatMicrons(double metres) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.1f \u00b5m", metres * 1e6);
  return buf;
}

Eigen::Matrix3Xd SubSample(const Eigen::Matrix3Xd& points, int max_points) {
  const Eigen::Index n = points.cols();
  if (n <= max_points || max_points <= 0) return points;
  Eigen::Matrix3Xd out(3, max_points);
  for (int i = 0; i < max_points; ++i)
    out.col(i) = points.col(static_cast<Eigen::Index>(static_cast<double>(i) * n / max_points));
  return out;
}

// The shape case in the order the report tells it (observation, diagnosis, deviations,
// notes); one function so the progress stages and the DiagnosedCase fields read in that order.
void DiagnoseShapeCase(const DiagnoseCaseOptions& options, const ProgressCallback& progress,
                       DiagnosedCase* out) {
  const RecordingCase& rc = out->recording;
  const RecordingRef* scan_ref = nullptr;
  const RecordingRef* line_ref = nullptr;
  for (const RecordingRef& r : rc.recordings) {
    if (r.kind == RecordingKind::kScan && !scan_ref) scan_ref = &r;
    if (r.kind == RecordingKind::kCenterline && !line_ref) line_ref = &r;
  }
  Report(progress, 0.01, "reading");
  const auto t0 = std::chrono::steady_clock::now();
  PointCloud cloud;
  if (scan_ref) {
    cloud = ReadPly(scan_ref->path);
    out->scan_points = SubSample(cloud.points, options.max_picture_points);
  }
  // With both a scan and a measured centreline, the fit uses the one that carries more
  // information about the shape: the larger (number of centre points) / sigma^2. A scan that
  // cannot be traced then only shows in the pictures.
  std::optional<ShapeObservation> from_line;
  if (line_ref) {
    const Polyline line = ReadCenterlineCsv(line_ref->path);
    if (line.size() < 3) throw FileError(line_ref->path, "needs at least 3 points");
    from_line = ObservationFromCenterline(line, rc.nominal.length);
  }
  std::optional<ScanCenterline> scan;
  if (scan_ref) {
    Report(progress, 0.05, "scan centreline");
    ScanCenterlineOptions so;
    so.diameter = rc.nominal.material.diameter;
    try {
      scan = Blame(scan_ref->path, [&] {
        return ExtractScanCenterline(cloud, so, ScanGuide::FromRodSpec(rc.nominal));
      });
      if (scan->size() < 3) throw FileError(scan_ref->path, "too few cable centres recovered");
    } catch (const FileError& e) {
      if (!from_line) throw;
      out->notes.push_back(std::string(e.what()) + "; the centre line is used instead");
      scan.reset();
    }
  }
  const auto information = [](const ShapeObservation& o) {
    return static_cast<double>(o.points.cols()) / (o.noise_sigma * o.noise_sigma);
  };
  std::optional<ShapeObservation> from_scan;
  if (scan) from_scan = ObservationFromScan(*scan);
  if (from_scan && (!from_line || information(*from_scan) > information(*from_line))) {
    out->observation = std::move(*from_scan);
    out->observation_source = scan_ref->file;
    for (const std::string& w : scan->warnings) out->notes.push_back(scan_ref->file + ": " + w);
    if (from_line)
      out->notes.push_back("fitted to the scan (" + std::to_string(scan->size()) +
                           " centres, noise " + FormatMicrons(out->observation.noise_sigma) +
                           ") rather than " + line_ref->file + " (" +
                           std::to_string(from_line->points.cols()) + " points, noise " +
                           FormatMicrons(from_line->noise_sigma) + "): it carries more information");
    out->scan = std::move(scan);
  } else {
    out->observation = std::move(*from_line);
    out->observation_source = line_ref->file;
  }
  out->observation_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ShapeDiagnosisOptions so = options.shape;
  so.progress = Stage(progress, 0.15, 1.0);
  const std::string observation_path =
      line_ref && out->observation_source == line_ref->file ? line_ref->path : scan_ref->path;
  ShapeDiagnosis d = Blame(rc.case_file, [&] {
    try {
      return DiagnoseShape(rc.nominal, out->observation, so);
    } catch (const RecordingMismatch& e) {
      throw FileError(observation_path, e.what());
    }
  });
  out->effect = ToString(d.effect);
  out->confidence = d.confidence;
  out->interval = d.interval;
  out->clamp = d.clamp;
  out->parameters = d.parameters;
  out->vectors = d.vectors;
  out->baseline = {d.baseline_max, d.baseline_rms};
  out->fitted = {d.fitted_max, d.fitted_rms};
  out->deviation_unit = "m";
  out->explanation = ExplainShapeDiagnosis(d, rc.nominal);
  out->explained = d.explained;
  for (const DiagnosisNote& note : d.notes)
    out->notes.push_back(out->observation_source + ": " + DescribeNote(note));
  for (const EffectCandidate& c : d.candidates)
    out->candidates.emplace_back(ToString(c.effect), c.score);
  for (const FoundEffect& f : d.effects)
    out->effects.push_back(
        {ToString(f.effect), f.clamp, f.interval, f.parameters, f.vectors, f.share});
  out->shape = std::move(d);
}

// A torsion curve read as a bending curve would be fitted with metres taken for radians and
// newtons for newton-metres, and still give a confident answer.
void RequireColumnsOfTest(const RecordingRef& r, const ForceCurve& curve) {
  const bool torsion = r.test.type == ForceTestType::kClampedTorsion;
  const char* x = torsion ? "angle" : "displacement";
  const char* y = torsion ? "moment" : "force";
  if (curve.x_name != x || curve.y_name != y) {
    throw FileError(r.path, "has columns " + curve.x_name + "," + curve.y_name + " but its test is " +
                                (torsion ? "clamped_torsion" : "pinned_bending") + ", which records step," +
                                x + "," + y);
  }
}

ForceCurve WithY(const ForceCurve& recorded, const Eigen::VectorXd& y) {
  ForceCurve c = recorded;
  c.y = y;
  return c;
}

void DiagnoseForceCase(const DiagnoseCaseOptions& options, const ProgressCallback& progress,
                       DiagnosedCase* out) {
  const RecordingCase& rc = out->recording;
  std::vector<const RecordingRef*> refs;
  for (const RecordingRef& r : rc.recordings)
    if (r.kind == RecordingKind::kForceCurve) refs.push_back(&r);
  std::vector<ForceCurve> recorded;
  std::vector<ForceDiagnosis> each;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const RecordingRef& r = *refs[i];
    Report(progress, 0.05 + 0.85 * static_cast<double>(i) / refs.size(), "fitting " + r.file);
    recorded.push_back(ReadForceCurveCsv(r.path));
    RequireColumnsOfTest(r, recorded.back());
    each.push_back(Blame(r.path, [&] {
      try {
        return DiagnoseForceCurve(rc.nominal, r.test, recorded.back(), options.force, r.file);
      } catch (const FileError& e) {
        // The diagnosis names the curve as the case lists it; the error names the file itself.
        if (e.file() != r.file) throw;
        throw FileError(r.path, e.problem());
      }
    }));
  }
  const ForceCaseDiagnosis all = Blame(rc.case_file, [&] { return CombineForceDiagnoses(each, options.force); });
  out->effect = ToString(all.effect);
  out->confidence = all.confidence;
  // The effect acts on the whole cable; none has no interval (as the reference writes it).
  if (all.effect != ForceEffect::kNone) out->interval = std::make_pair(0.0, rc.nominal.length);
  out->parameters = all.parameters;
  out->baseline = {all.baseline.max_deviation, all.baseline.rms_deviation};
  out->fitted = {all.fitted.max_deviation, all.fitted.rms_deviation};
  out->deviation_unit = all.curves.front().y_unit;
  for (const ForceDiagnosis& d : all.curves)
    if (d.y_unit != out->deviation_unit) out->deviation_unit = "curve units";
  out->explanation = all.explanation;
  out->explained = all.explained;
  for (const auto& [effect, score] : all.candidates) out->candidates.emplace_back(ToString(effect), score);
  if (all.effect != ForceEffect::kNone) {
    // One effect explains what the fit removes of the mismatch (the rms over the same rows).
    const double b = out->baseline.rms, f = out->fitted.rms;
    out->effects.push_back({out->effect, std::nullopt, out->interval, out->parameters, {},
                            b > 0 ? 1.0 - (f * f) / (b * b) : 0.0});
  }
  for (std::size_t i = 0; i < refs.size(); ++i) {
    DiagnosedCurve c;
    c.file = refs[i]->file;
    c.path = refs[i]->path;
    c.recorded = recorded[i];
    c.diagnosis = all.curves[i];
    c.nominal = WithY(recorded[i], c.diagnosis.nominal_curve);
    c.fitted = WithY(recorded[i], c.diagnosis.fitted_curve);
    out->curves.push_back(std::move(c));
  }
}

}  // namespace

const char* ToString(CaseKind kind) { return kind == CaseKind::kForce ? "force" : "shape"; }

std::string EffectsName(const DiagnosedCase& d) {
  if (d.effects.size() < 2) return d.effect;
  std::string name;
  for (const FoundEffectSummary& f : d.effects) name += (name.empty() ? "" : " + ") + f.effect;
  return name;
}

DiagnosedCase DiagnoseCase(const std::string& case_file, const DiagnoseCaseOptions& options,
                           const ProgressCallback& progress) {
  const auto start = Clock::now();
  DiagnosedCase out;
  out.recording = ReadRecordingCase(case_file);
  bool has_shape = false, has_force = false;
  for (const RecordingRef& r : out.recording.recordings) {
    has_shape = has_shape || r.kind != RecordingKind::kForceCurve;
    has_force = has_force || r.kind == RecordingKind::kForceCurve;
  }
  if (!has_shape && !has_force) throw FileError(out.recording.case_file, "has no recordings");
  // One diagnosis.json holds one effect, and a shape and a force test are two experiments: using
  // one and ignoring the other would hide half of what was recorded.
  if (has_shape && has_force) {
    throw FileError(out.recording.case_file,
                    "has both a shape recording (scan or centerline) and force curves; diagnose "
                    "them as two cases");
  }
  out.kind = has_shape ? CaseKind::kShape : CaseKind::kForce;
  if (out.kind == CaseKind::kShape)
    DiagnoseShapeCase(options, progress, &out);
  else
    DiagnoseForceCase(options, progress, &out);
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  Report(progress, 1.0, "done");
  return out;
}

}  // namespace cablefit::addin
