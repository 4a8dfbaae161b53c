#include "cablefit/app/diagnose/harness_case.h"

#include <chrono>
#include <cstdlib>

#include "cablefit/core/base/solver_failure.h"
#include "cablefit/core/network/network_simulation.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/ply_reader.h"
#include "diagnose/diagnose_observation.h"
#include "diagnose/harness_scan_split.h"

namespace cablefit::addin {
namespace {

// The nominal harness solved finely enough to split a scan along it.
std::vector<Polyline> NominalShapes(const NetworkSpec& spec) {
  double total = 0.0;
  for (const BranchSpec& b : spec.branches) total += b.length;
  NetworkOptions opt;
  opt.element_length = total / 800.0;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  if (!sol.converged())
    throw SolverFailure("the nominal harness could not be solved: " + sol.summary.message);
  return sol.branches;
}

Eigen::Matrix3Xd EveryNth(const PointCloud& cloud, int at_most) {
  const int n = cloud.size();
  const int step = std::max(1, n / std::max(at_most, 1));
  Eigen::Matrix3Xd out(3, (n + step - 1) / step);
  for (int i = 0, k = 0; i < n; i += step, ++k) out.col(k) = cloud.points.col(i);
  return out;
}

}  // namespace

DiagnosedHarness DiagnoseHarnessCase(const std::string& case_file, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  DiagnosedHarness d;
  d.recording = ReadHarnessRecording(case_file);
  const NetworkSpec& spec = d.recording.nominal;
  HarnessDiagnosisOptions options;
  options.threads = threads;
  const HarnessRecordingRef* scan = nullptr;
  for (const HarnessRecordingRef& r : d.recording.recordings)
    if (r.kind == HarnessRecordingRef::Kind::kScan && !scan) scan = &r;
  if (scan) {
    const PointCloud cloud = ReadPly(scan->path);
    if (cloud.size() == 0) throw FileError(scan->path, "the scan holds no points");
    d.observation_source = scan->file;
    d.scan_points = cloud.size();
    d.shown_points = EveryNth(cloud, 4000);
    // Split along the nominal harness, diagnose; split again along the fitted one when it moved
    // the branches, and diagnose that.
    std::vector<Polyline> shapes = NominalShapes(spec);
    HarnessScanSplit split = SplitHarnessScan(cloud, spec, shapes);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::string> problems;
      HarnessObservation obs = ObserveHarnessScan(split, spec, shapes, &problems);
      d.diagnosis = DiagnoseHarness(spec, obs, options);
      d.observation = std::move(obs);
      d.split_points.clear();
      for (const PointCloud& c : split.branches) d.split_points.push_back(c.size());
      if (pass == 0) d.notes.insert(d.notes.end(), problems.begin(), problems.end());
      if (d.diagnosis.effects.empty()) break;
      // Split again along the fitted harness; diagnosed once more only when that moves points
      // between branches (more than 0.5 % of them).
      shapes = d.diagnosis.fitted;
      HarnessScanSplit again = SplitHarnessScan(cloud, spec, shapes);
      int moved = 0;
      for (size_t b = 0; b < again.branches.size(); ++b)
        moved += std::abs(again.branches[b].size() - split.branches[b].size());
      if (pass == 1 || moved <= 0.005 * cloud.size()) break;
      split = std::move(again);
      d.notes.push_back("the scan was split onto the branches again along the fitted harness (" +
                        std::to_string(moved) + " points changed branch) and diagnosed once more");
    }
  } else {
    d.observation_source = "centrelines";
    d.observation.branches.resize(spec.branches.size());
    for (ShapeObservation& o : d.observation.branches) o.points.resize(3, 0);
    for (const HarnessRecordingRef& r : d.recording.recordings) {
      const Polyline line = ReadCenterlineCsv(r.path);
      if (line.size() < 2) throw FileError(r.path, "a centreline needs at least two points");
      d.observation.branches[static_cast<size_t>(r.branch)] =
          ObservationFromCenterline(line, spec.branches[static_cast<size_t>(r.branch)].length);
    }
    d.diagnosis = DiagnoseHarness(spec, d.observation, options);
  }
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return d;
}

}  // namespace cablefit::addin
