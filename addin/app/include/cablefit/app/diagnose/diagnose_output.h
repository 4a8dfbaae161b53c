// The machine-readable outputs of `cablefit diagnose` for one case: diagnosis.json
// (cable-diagnosis/1, recording-v1.md) and the simulated nominal/fitted curves (cli-v1.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cablefit/app/diagnose/diagnose_case.h"

namespace cablefit::addin {

inline constexpr const char* kDiagnosisFormat = "cable-diagnosis/1";
/// Rows of the shape cases' nominal.csv / fitted.csv (uniform in s from 0 to L).
inline constexpr int kCenterlineRows = 401;

/// Exactly the cable-diagnosis/1 object. Vector parameters (axis, force_vector ...) are added to
/// `parameters` as [x, y, z] arrays; every other parameter is a number.
nlohmann::json DiagnosisToJson(const DiagnosedCase& d);

/// A model curve file written for a case.
struct ModelCurveFile {
  std::string name;   // file name inside the case folder, e.g. "fitted.csv"
  std::string model;  // "nominal" or "fitted"
  std::string recording;  // the recorded file it belongs to (force), else empty
};

/// The names WriteModelCurves writes: nominal.csv, fitted.csv, or for a force case with several
/// curves nominal-<file>, fitted-<file> per curve.
std::vector<ModelCurveFile> ModelCurveFiles(const DiagnosedCase& d);

/// Writes diagnosis.json and the model curves into `dir` (atomically, created if missing).
void WriteDiagnosisFiles(const std::string& dir, const DiagnosedCase& d);

}  // namespace cablefit::addin
