// One recording case from case.json to a diagnosis: read the recordings, build the observation
// (shape) or the curves (force), run the core diagnosis, and collect everything the outputs
// (diagnosis.json, model curves, report) need in one plain struct.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cablefit/core/force/force_diagnosis.h"
#include "cablefit/core/rod/recording_case.h"
#include "cablefit/core/diagnosis/scan_centerline.h"
#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "cablefit/core/solver/statics_solver.h"

namespace cablefit::addin {

/// Max and rms deviation of a model from the recording (metres, or the curve's unit).
struct Deviation {
  double max = 0.0;
  double rms = 0.0;
};

/// One recorded force curve with the nominal and the fitted model evaluated on its rows.
struct DiagnosedCurve {
  std::string file;  // as named in case.json
  std::string path;  // resolved
  ForceCurve recorded;
  ForceCurve nominal;  // same steps and x as recorded
  ForceCurve fitted;
  ForceDiagnosis diagnosis;  // re-expressed with the case-level effect
};

/// One piece of physics found (diagnosis.json's `effects`).
struct FoundEffectSummary {
  std::string effect;
  std::optional<int> clamp;
  std::optional<std::pair<double, double>> interval;  // [m]
  std::map<std::string, double> parameters;
  std::map<std::string, Vec3> vectors;
  double share = 0.0;  // part of the baseline mismatch (sum of squares) it removes [-]
};

enum class CaseKind { kShape, kForce };
const char* ToString(CaseKind kind);

struct DiagnosedCase {
  RecordingCase recording;
  CaseKind kind = CaseKind::kShape;

  // ---- the cable-diagnosis/1 fields ----
  std::string effect = "none";
  double confidence = 0.0;
  std::optional<std::pair<double, double>> interval;  // [m]
  std::optional<int> clamp;
  std::map<std::string, double> parameters;
  std::map<std::string, Vec3> vectors;  // world vectors (axis, force_vector ...)
  Deviation baseline, fitted;
  std::string deviation_unit = "m";  // "m", or the force curve's "N" / "N m"
  std::string explanation;
  std::vector<std::pair<std::string, double>> candidates;  // (effect, score), best first
  /// Every effect found, dominant first (the first is `effect`'s); empty for none.
  std::vector<FoundEffectSummary> effects;
  bool explained = true;  // false: nothing in the catalogue fits the recording within its noise

  // ---- shape cases ----
  std::optional<ShapeDiagnosis> shape;
  std::string observation_source;       // file the fit used: scan or centreline, whichever
                                        // carries more information (points / sigma^2)
  ShapeObservation observation;         // what the fit saw
  Eigen::Matrix3Xd scan_points;         // 3 x m [m] sub-sampled raw scan (pictures), may be empty
  std::optional<ScanCenterline> scan;   // when the fit used a scan
  std::vector<std::string> notes;       // quality remarks for the report
  double observation_seconds = 0.0;     // reading the recording, scan -> centre line

  // ---- force cases ----
  std::vector<DiagnosedCurve> curves;

  double seconds = 0.0;
};

/// The effects found as people read them: "none", one name, or "a + b" (dominant first).
std::string EffectsName(const DiagnosedCase& d);

struct DiagnoseCaseOptions {
  ShapeDiagnosisOptions shape;
  ForceDiagnosisOptions force;
  /// At most this many raw scan points are kept for pictures.
  int max_picture_points = 4000;
};

/// Reads `case_file` and diagnoses it. `progress` (may be empty) receives (fraction, stage).
/// Every problem with an input throws FileError naming the file at fault (case.json, the scan,
/// the centreline or the force CSV) with a one-line description.
DiagnosedCase DiagnoseCase(const std::string& case_file, const DiagnoseCaseOptions& options,
                           const ProgressCallback& progress);

}  // namespace cablefit::addin
