#include "bench_diagnose.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "cablefit/app/diagnose_case.h"
#include "cablefit/cli/commands.h"
#include "cablefit/formats/case_reader.h"
#include "terminal_text.h"

namespace cablefit::addin {
namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
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
  std::vector<double> shape, force;
  for (const std::string& file : list.files) {
    const std::string name = std::filesystem::path(file).parent_path().filename().string();
    DiagnoseCaseOptions options;
    options.shape.threads = 1;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      const DiagnosedCase d = DiagnoseCase(file, options, nullptr);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      (d.shape ? shape : force).push_back(s);
      std::printf("diagnose_%s: %.3f s (%s, %s)\n", TerminalSafe(name).c_str(), s,
                  d.shape ? "shape" : "force", TerminalSafe(d.effect).c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cablefit: %s: %s\n", TerminalSafe(file).c_str(),
                   TerminalSafe(e.what()).c_str());
    }
  }
  Summary("shape", shape);
  Summary("force", force);
  return kExitOk;
}

}  // namespace cablefit::addin
