#include "bench_relax.h"

#include <fcntl.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "cablefit/app/pipeline/relax_pipeline.h"
#include "cablefit/cli/commands.h"
#include "cablefit/core/base/errors.h"
#include "terminal_text.h"

extern char** environ;

namespace cablefit::addin {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

fs::path ScratchFolder() {
  std::string pattern = (fs::temp_directory_path() / "cablefit-bench-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw FileError(pattern, std::string("cannot make a scratch folder: ") + std::strerror(errno));
  return pattern;
}

// A row name from a file stem: letters, digits and '_' only.
std::string RowName(const std::string& stem) {
  std::string out;
  for (char c : stem) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out;
}

struct StageRow {
  const char* name;
  double RelaxStageSeconds::*field;
};
constexpr StageRow kStages[] = {
    {"read", &RelaxStageSeconds::read},       {"relax", &RelaxStageSeconds::relax},
    {"measure", &RelaxStageSeconds::measure}, {"clearance", &RelaxStageSeconds::clearance},
    {"json", &RelaxStageSeconds::json},       {"step", &RelaxStageSeconds::step},
    {"pictures", &RelaxStageSeconds::pictures}, {"report", &RelaxStageSeconds::report}};

struct FileRun {
  RelaxStageSeconds seconds;
  int cables = 0, failed = 0;
  json::Json network;  // the largest network group's JSON, null without one
};

FileRun RelaxOnce(const std::string& file, const fs::path& out) {
  RelaxOptions options;
  options.out_dir = out.string();
  RelaxPipeline pipeline(options);
  const RelaxSummary summary = pipeline.Run({file});
  if (!summary.any_read) throw FileError(file, summary.failures.empty() ? "not read" : summary.failures.front());
  FileRun run;
  run.seconds = summary.seconds;
  run.cables = summary.counts.cables;
  run.failed = summary.counts.failed;
  for (const RelaxedFile& f : pipeline.files())
    for (const json::Json& n : f.networks)
      if (run.network.is_null() || n.at("cables").size() > run.network.at("cables").size()) run.network = n;
  return run;
}

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Runs argv (argv[0] a path) to its end with stdout and stderr to /dev/null; its wall time [s].
double TimeProcess(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const auto t0 = Clock::now();
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw FileError(args[0], std::string("cannot run: ") + std::strerror(rc));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw FileError(args[0], "exited with status " + std::to_string(WEXITSTATUS(status)) + " in the bench");
  return seconds;
}

void ProcessRows(const char* row, const std::vector<std::string>& args, int reps) {
  std::vector<double> t;
  TimeProcess(args);  // once to warm the page cache
  for (int i = 0; i < reps; ++i) t.push_back(TimeProcess(args));
  std::printf("%s: %.2f ms\n", row, 1e3 * Median(t));
  std::printf("%s_fastest: %.2f ms\n", row, 1e3 * *std::min_element(t.begin(), t.end()));
}

// The bench cable of RunBench (command_bench.cc) as a recording case.
void WriteBenchCase(const fs::path& path) {
  std::ofstream(path) << R"({"format": "cable-recording/1", "name": "bench-sag",
  "cable": {"length": 0.7553, "diameter": 0.006, "bending_stiffness": 0.0125,
            "torsional_stiffness": 0.0095, "linear_density": 0.0338},
  "gravity": [0, 0, -9.81],
  "clamps": [{"s": 0.0, "position": [-0.275, -0.2491, 0.2686],
              "tangent": [-0.468254, -0.854122, 0.226306], "normal": [-0.100022, -0.203236, -0.974008]},
             {"s": 0.7553, "position": [-0.4985, -0.8429, 0.2503],
              "tangent": [-0.305022, -0.888788, 0.342078], "normal": [-0.137248, -0.311707, -0.932259]}],
  "recordings": [{"kind": "centerline", "file": "centerline.csv"}]})";
  // A recording the case can name; simulate solves the set-up and does not read it.
  std::ofstream(path.parent_path() / "centerline.csv")
      << "s,x,y,z\n0,-0.275,-0.2491,0.2686\n0.7553,-0.4985,-0.8429,0.2503\n";
}

}  // namespace

int BenchRelaxFiles(const std::vector<std::string>& files, int reps) {
  const fs::path scratch = ScratchFolder();
  for (const std::string& file : files) {
    const std::string row = "relax_" + RowName(fs::path(file).stem().string());
    std::vector<FileRun> runs;
    for (int i = 0; i < reps; ++i) runs.push_back(RelaxOnce(file, scratch / std::to_string(i)));
    std::sort(runs.begin(), runs.end(),
              [](const FileRun& a, const FileRun& b) { return a.seconds.total < b.seconds.total; });
    const FileRun& run = runs[runs.size() / 2];
    std::printf("%s_cables: %d cables\n", row.c_str(), run.cables);
    std::printf("%s_failed: %d cables\n", row.c_str(), run.failed);
    const StageRow* largest = &kStages[0];
    for (const StageRow& s : kStages) {
      std::printf("%s_%s: %.3f s\n", row.c_str(), s.name, run.seconds.*s.field);
      if (run.seconds.*s.field > run.seconds.*largest->field) largest = &s;
    }
    std::printf("%s: %.3f s\n", row.c_str(), run.seconds.total);
    std::printf("%s_largest_stage: %.0f %% (%s)\n", row.c_str(),
                100 * run.seconds.*largest->field / run.seconds.total, largest->name);
    if (!run.network.is_null()) {
      const json::Json& n = run.network;
      std::printf("%s_network_segments: %zu segments\n", row.c_str(), n.at("cables").size());
      std::printf("%s_network_elements: %d elements\n", row.c_str(), n.at("elements").get<int>());
      if (n.contains("levels"))
        for (const json::Json& level : n.at("levels"))
          std::printf("%s_network_level_%d: %d iterations, %.3f s\n", row.c_str(),
                      level.at("elements").get<int>(), level.at("iterations").get<int>(),
                      level.at("seconds").get<double>());
      if (n.contains("coarse_start")) {
        const json::Json& c = n.at("coarse_start");
        std::printf("%s_network_coarse_start_%d: %d iterations, %.3f s\n", row.c_str(),
                    c.at("elements").get<int>(), c.at("iterations").get<int>(),
                    c.at("seconds").get<double>());
      }
      std::printf("%s_network_estimated_error: %.2e m\n", row.c_str(),
                  n.at("estimated_error").is_number() ? n.at("estimated_error").get<double>() : -1.0);
      std::printf("%s_network_solve: %.3f s\n", row.c_str(), n.at("seconds").get<double>());
    }
    std::fflush(stdout);
  }
  std::error_code ec;
  fs::remove_all(scratch, ec);
  return kExitOk;
}

int BenchProcesses(int reps) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const std::string cablefit = ((ec ? fs::path(".") : self.parent_path()) / "cablefit").string();
  const fs::path scratch = ScratchFolder();
  WriteBenchCase(scratch / "case.json");
  // What starting any process costs on this machine: the floor the other rows stand on.
  if (fs::exists("/bin/true")) ProcessRows("process_floor_bin_true", {"/bin/true"}, reps);
  ProcessRows("process_version", {cablefit, "--version"}, reps);
  const std::string case_json = (scratch / "case.json").string(), out = (scratch / "out").string();
  // The default accuracy (1e-6 m) ends at 192 elements on this case; 1e-5 m at 96, the size
  // the start-up target was set for.
  ProcessRows("process_simulate", {cablefit, "simulate", case_json, "--out", out}, reps);
  ProcessRows("process_simulate_96_elements",
              {cablefit, "simulate", case_json, "--out", out, "--accuracy", "1e-5"}, reps);
  fs::remove_all(scratch, ec);
  return kExitOk;
}

}  // namespace cablefit::addin
