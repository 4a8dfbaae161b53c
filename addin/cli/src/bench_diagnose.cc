#include "bench_diagnose.h"

#include <stdlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "cablefit/app/base/batch_pool.h"
#include "cablefit/app/diagnose/diagnose_case.h"
#include "cablefit/app/diagnose/diagnose_output.h"
#include "cablefit/app/diagnose/harness_case.h"
#include "cablefit/app/report/report_case.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/cli/commands.h"
#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/harness_case_reader.h"
#include "terminal_text.h"

namespace cablefit::addin {
namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::filesystem::path ScratchFolder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "cablefit-bench-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw FileError(pattern, std::string("cannot make a scratch folder: ") + std::strerror(errno));
  return pattern;
}

void Summary(const char* kind, const std::vector<double>& seconds) {
  if (seconds.empty()) return;
  std::printf("diagnose_%s_cases: %zu cases\n", kind, seconds.size());
  std::printf("diagnose_%s_median: %.3f s\n", kind, Median(seconds));
  std::printf("diagnose_%s_worst: %.3f s\n", kind, *std::max_element(seconds.begin(), seconds.end()));
}

}  // namespace

int BenchDiagnose(const std::string& dir) {
  const CaseFileList list = FindCaseFiles({dir});
  for (const FileError& e : list.errors) std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(e.what()).c_str());
  if (list.files.empty()) {
    std::fprintf(stderr, "cablefit: bench: no recording case under %s\n", TerminalSafe(dir).c_str());
    return kExitUsage;
  }
  // The pictures and the report count in a diagnosis' time: they are written, then removed.
  const std::filesystem::path scratch = ScratchFolder();
  std::vector<double> shape, force, harness;
  int index = 0;
  // As `cablefit diagnose --jobs 1`: one case at a time, its fits on every core the
  // process may run on (its affinity: `taskset -c 0` times one core without two threads taking
  // turns on it).
  const int threads = UsableCores();
  std::printf("diagnose_fit_threads: %d\n", threads);
  for (const std::string& file : list.files) {
    const std::string name = std::filesystem::path(file).parent_path().filename().string();
    DiagnoseCaseOptions options;
    options.shape.threads = threads;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      if (CaseFormatOf(file) == kHarnessRecordingFormat) {
        const DiagnosedHarness h = DiagnoseHarnessCase(file, threads);
        WriteHarnessCase((scratch / std::to_string(index++)).string(), h);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        harness.push_back(s);
        int branches_seen = 0;
        for (const ShapeObservation& o : h.observation.branches) branches_seen += o.points.cols() > 0;
        std::printf("diagnose_%s: %.3f s (harness, %s)\n", TerminalSafe(name).c_str(), s,
                    TerminalSafe(HarnessEffectsName(h)).c_str());
        std::printf("  %d scan points on %d branches, diagnosis %.3f s (%d forward solves)\n",
                    h.scan_points, branches_seen, h.diagnosis.seconds, h.diagnosis.forward_solves);
        continue;
      }
      const DiagnosedCase d = DiagnoseCase(file, options, nullptr);
      const auto t1 = std::chrono::steady_clock::now();
      const std::string dir = (scratch / std::to_string(index++)).string();
      WriteDiagnosisFiles(dir, d);
      WriteCaseReport(dir, d);
      const auto t2 = std::chrono::steady_clock::now();
      const double s = std::chrono::duration<double>(t2 - t0).count();
      (d.shape ? shape : force).push_back(s);
      std::printf("diagnose_%s: %.3f s (%s, %s)\n", TerminalSafe(name).c_str(), s,
                  d.shape ? "shape" : "force", TerminalSafe(EffectsName(d)).c_str());
      if (d.shape) {
        const ShapeDiagnosisCost& c = d.shape->cost;
        std::printf("  observation %.3f s, recording %.3f s, nominal %.3f s, fits %.3f s, "
                    "pairs %.3f s (%d forward solves, %d LM iterations), final solves %.3f s, "
                    "pictures and report %.3f s\n",
                    d.observation_seconds, c.recording_seconds, c.nominal_seconds,
                    c.fits_seconds, c.pairs_seconds, c.forward_solves, c.lm_iterations,
                    c.final_seconds,
                    std::chrono::duration<double>(t2 - t1).count());
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cablefit: %s: %s\n", TerminalSafe(file).c_str(),
                   TerminalSafe(e.what()).c_str());
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(scratch, ignored);
  Summary("shape", shape);
  Summary("force", force);
  Summary("harness", harness);
  return kExitOk;
}

}  // namespace cablefit::addin
