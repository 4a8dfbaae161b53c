// A harness recording (harness-recording/1) diagnosed: read, the nominal harness solved, the scan
// split onto its branches (or the branches' measured centrelines read), DiagnoseHarness, and the
// split refined along the fitted harness when that moved it; then written as diagnosis.json
// (harness-diagnosis/1), the nominal and fitted centreline of every branch, and a report.
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/diagnosis/harness_diagnosis.h"
#include "cablefit/formats/harness_case_reader.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

struct DiagnosedHarness {
  HarnessRecording recording;
  HarnessDiagnosis diagnosis;
  HarnessObservation observation;  // what the fits saw, per branch
  std::string observation_source;  // the scan's file, or "centrelines"
  int scan_points = 0;             // points in the scan (0 without one)
  std::vector<int> split_points;   // per branch: scan points assigned to it
  Eigen::Matrix3Xd shown_points;   // 3 x m [m] sub-sampled scan for the pictures
  std::vector<std::string> notes;  // a branch not traced, the split refined, ...
  double seconds = 0.0;
};

/// Diagnoses the harness recording `case_file` (fits on `threads` threads). Throws FileError /
/// InvalidInput for bad input, SolverFailure when the nominal harness cannot be solved.
DiagnosedHarness DiagnoseHarnessCase(const std::string& case_file, int threads);

/// DIR/diagnosis.json, DIR/nominal-<branch>.csv and DIR/fitted-<branch>.csv (s,x,y,z), the
/// picture DIR/deviation-views.png and DIR/report.html.
void WriteHarnessCase(const std::string& dir, const DiagnosedHarness& d);

/// The harness-diagnosis/1 object of diagnosis.json.
json::Json HarnessDiagnosisToJson(const DiagnosedHarness& d);

/// "branch_stiffness on branch_b", "junction_position at breakout + clip_position on trunk_1",
/// "none" or "not explained".
std::string HarnessEffectsName(const DiagnosedHarness& d);

}  // namespace cablefit::addin
