// `cablefit bench`: performance figures of the rod core, one per line `name: value unit`.
// Reports, never asserts (the goals: cold <= 5 ms, warm <= 1 ms, growth linear in the elements).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cablefit/cli/commands.h"
#include "cablefit/app/bench/bench_harness.h"
#include "cablefit/app/bench/drawn_shapes.h"
#include "cablefit/app/relax/relax_network.h"
#include "cablefit/core/rod/initial_shape.h"
#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/case_reader.h"
#include "bench_diagnose.h"
#include "bench_motion.h"
#include "bench_relax.h"

namespace cablefit::addin {
namespace {

using Clock = std::chrono::steady_clock;

// A 0.755 m cable sagging in 3-D between two clamps (the geometry of the public `sample-none`).
RodSpec BenchSpec() {
  RodSpec s;
  s.name = "bench-sag";
  s.length = 0.7553;
  s.material.bending_stiffness = 0.0125;
  s.material.torsional_stiffness = 0.0095;
  s.material.linear_density = 0.0338;
  s.material.diameter = 0.006;
  SupportSpec a, b;
  a.position = Vec3(-0.275, -0.2491, 0.2686);
  a.tangent = Vec3(-0.468254, -0.854122, 0.226306);
  a.normal = Vec3(-0.100022, -0.203236, -0.974008);
  b.s = s.length;
  b.position = Vec3(-0.4985, -0.8429, 0.2503);
  b.tangent = Vec3(-0.305022, -0.888788, 0.342078);
  b.normal = Vec3(-0.137248, -0.311707, -0.932259);
  s.supports = {a, b};
  return s;
}

template <class F>
double MedianMs(int reps, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < reps; ++i) {
    const auto t0 = Clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2];
}

// A whole branched harness relaxed from its drawn shape, at 1x, 4x and 16x the elements.
void BenchNetwork(int reps) {
  const NetworkSpec spec = SyntheticHarness();
  int clips = 0;
  for (const BranchSpec& b : spec.branches)
    for (const SupportSpec& sp : b.supports) clips += sp.kind == SupportKind::kClip;
  const double length = NetworkLength(spec);
  std::printf("network_branches: %zu branches\n", spec.branches.size());
  std::printf("network_junctions: %zu junctions\n", spec.junctions.size());
  std::printf("network_clips: %d clips\n", clips);
  std::printf("network_length: %.3f m\n", length);
  for (int factor : {1, 4, 16}) {
    NetworkOptions opt;
    opt.element_length = length / (3000.0 * factor);
    NetworkSolution sol;
    const double ms = MedianMs(factor == 1 ? std::max(3, reps / 2) : 1, [&] { sol = SolveNetwork(spec, opt); });
    std::printf("network_x%d: %.3f ms\n", factor, ms);
    std::printf("network_x%d_elements: %d elements\n", factor, sol.num_elements);
    std::printf("network_x%d_iterations: %d iterations\n", factor, sol.summary.iterations);
    std::printf("network_x%d_converged: %d bool\n", factor, sol.converged() ? 1 : 0);
    std::printf("network_x%d_stable: %d bool\n", factor, sol.summary.stable ? 1 : 0);
    std::printf("network_x%d_per_element: %.3f us\n", factor, ms / sol.num_elements * 1e3);
  }
}

// A harness the size of the largest real KBL harness (183 segments, 184 nodes, 16 fixings)
// solved as relax solves a network group: its refinement plan (levels until the accuracy or the
// element cap), then once more without gravity on one level (the springback/sag split).
void BenchKblSizedNetwork() {
  const NetworkSpec spec = KblSizedHarness();
  int clips = 0;
  for (const BranchSpec& b : spec.branches)
    for (const SupportSpec& sp : b.supports) clips += sp.kind == SupportKind::kClip;
  std::printf("kbl_network_segments: %zu segments\n", spec.branches.size());
  std::printf("kbl_network_junctions: %zu junctions\n", spec.junctions.size());
  std::printf("kbl_network_fixings: %d clips\n", clips);
  std::printf("kbl_network_length: %.3f m\n", NetworkLength(spec));
  const NetworkRelaxPlan planned = PlanNetworkRelax(spec, SimulationOptions{});
  const auto t0 = Clock::now();
  const NetworkSimulation sim = SimulateNetwork(spec, planned.plan, planned.options);
  const double solve = std::chrono::duration<double>(Clock::now() - t0).count();
  const auto t1 = Clock::now();
  const NetworkSimulation split = SimulateWithoutGravity(spec, planned.options, sim.finest.branches,
                                                          sim.finest.element_normals);
  const double springback = std::chrono::duration<double>(Clock::now() - t1).count();
  std::string levels;
  for (int e : sim.level_elements) levels += (levels.empty() ? "" : "+") + std::to_string(e);
  std::printf("kbl_network_levels: %s elements\n", levels.c_str());
  std::printf("kbl_network_iterations: %d iterations\n", sim.newton_iterations);
  std::printf("kbl_network_converged: %d bool\n", sim.converged ? 1 : 0);
  std::printf("kbl_network_estimated_error: %.2e m\n", sim.estimated_error);
  std::printf("kbl_network_solve: %.3f s\n", solve);
  std::printf("kbl_network_springback_converged: %d bool\n", split.converged ? 1 : 0);
  std::printf("kbl_network_springback: %.3f s\n", springback);
  std::printf("kbl_network_springback_iterations: %d iterations\n", split.newton_iterations);
  std::printf("kbl_network: %.3f s\n", solve + springback);
}

// The same harness with every segment cut shorter or longer than drawn (as harness.json's
// "length": "+2%"): shorter pulls stretches taut, longer gives slack that sags and buckles.
void BenchKblSizedLengths() {
  for (const double change : {-0.02, 0.02, 0.05}) {
    KblSizedHarnessSize size;
    size.length_change = change;
    const NetworkSpec spec = KblSizedHarness(size);
    const NetworkRelaxPlan planned = PlanNetworkRelax(spec, SimulationOptions{});
    const auto t0 = Clock::now();
    const NetworkSimulation sim = SimulateNetwork(spec, planned.plan, planned.options);
    const double solve = std::chrono::duration<double>(Clock::now() - t0).count();
    char row[64];
    std::snprintf(row, sizeof row, "kbl_network_cut_%s%d_pct", change < 0 ? "minus" : "plus",
                  static_cast<int>(std::lround(100 * std::abs(change))));
    std::printf("%s_converged: %d bool\n", row, sim.converged ? 1 : 0);
    std::printf("%s_iterations: %d iterations\n", row, sim.newton_iterations);
    std::printf("%s: %.3f s\n", row, solve);
  }
}

// Single cables drawn in shapes a straight-rest cable is hard to relax from (coils, a long
// spring, kinks, a nearly taut stretch), relaxed from their drawing as `relax` does.
void BenchDrawnShapes() {
  for (const DrawnShapeCase& c : DrawnShapeCases()) {
    NetworkOptions opt;
    opt.element_length = c.element_length;
    const auto t0 = Clock::now();
    const NetworkSolution sol = SolveNetwork(c.spec, opt);
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    const char* row = c.name.c_str();
    std::printf("%s_length: %.3f m\n", row, c.spec.branches[0].length);
    std::printf("%s_elements: %d elements\n", row, sol.num_elements);
    std::printf("%s_converged: %d bool\n", row, sol.converged() ? 1 : 0);
    std::printf("%s_stable: %d bool\n", row, sol.summary.stable ? 1 : 0);
    std::printf("%s_folds_passed: %d folds\n", row, sol.summary.folds_passed);
    std::printf("%s_iterations: %d iterations\n", row, sol.summary.iterations);
    std::printf("%s: %.3f s\n", row, seconds);
  }
}

// The harness with clips twice as sparse, so its spans sag, over a body panel tessellated as
// finely as CAD exports panels: what the contact search and the active set cost.
void BenchContact(int reps) {
  SyntheticHarnessSize size;
  size.clip_spacing *= 2;
  NetworkSpec spec = SyntheticHarness(size);
  NetworkOptions opt;
  opt.element_length = NetworkLength(spec) / 3000.0;
  // The panel's top goes halfway between the lowest drawn and free-hanging cable surface: clear
  // of the drawing, in the way of the sag.
  const NetworkSolution free = SolveNetwork(spec, opt);
  double drawn = 0.0, hung = 0.0;
  Eigen::AlignedBox3d extent;
  for (size_t b = 0; b < spec.branches.size(); ++b) {
    const double r = 0.5 * spec.branches[b].material.diameter;
    const Eigen::Matrix3Xd& route = spec.branches[b].route.points;
    drawn = std::min(drawn, route.row(2).minCoeff() - r);
    hung = std::min(hung, free.branches[b].points.row(2).minCoeff() - r);
    for (int i = 0; i < route.cols(); ++i) extent.extend(Vec3(route.col(i)));
  }
  const double top = 0.5 * (drawn + hung);
  const Vec3 lo(extent.min().x() - 0.1, extent.min().y() - 0.1, top);
  const Vec3 hi(extent.max().x() + 0.1, extent.max().y() + 0.1, top);
  spec.obstacles.push_back({"panel", FlatPanel(lo, hi, 400, 150)});
  NetworkSolution sol;
  const double ms = MedianMs(std::max(3, reps / 4), [&] { sol = SolveNetwork(spec, opt); });
  std::printf("contact_free_ms: %.3f ms\n", free.summary.seconds * 1e3);
  std::printf("contact_sag_below_panel: %.3f mm\n", (top - hung) * 1e3);
  std::printf("contact_panel_triangles: %lld triangles\n",
              static_cast<long long>(spec.obstacles[0].mesh.faces.cols()));
  std::printf("contact: %.3f ms\n", ms);
  std::printf("contact_elements: %d elements\n", sol.num_elements);
  std::printf("contact_contacts: %zu contacts\n", sol.contacts.size());
  std::printf("contact_rounds: %d rounds\n", sol.contact_rounds);
  std::printf("contact_iterations: %d iterations\n", sol.summary.iterations);
  std::printf("contact_converged: %d bool\n", sol.converged() ? 1 : 0);
  std::printf("contact_penetration: %.3g m\n", sol.max_penetration);
}

int RunBench(const std::string& case_path, int reps) {
  const RodSpec spec = case_path.empty() ? BenchSpec() : ReadRecordingCase(case_path).nominal;
  std::printf("case: %s\n", spec.name.c_str());
  SimulationOptions cold_opt;
  cold_opt.accuracy = 1e-5;
  SimulationResult cold;
  const double cold_ms = MedianMs(reps, [&] {
    RodSimulator sim(cold_opt);
    cold = sim.Simulate(spec);
  });
  std::printf("cold_solve: %.3f ms\n", cold_ms);
  std::printf("cold_solve_elements: %d elements\n", cold.level_elements.back());
  std::printf("cold_solve_levels: %zu levels\n", cold.level_elements.size());
  std::printf("cold_solve_newton_iterations: %d iterations\n", cold.newton_iterations);
  std::printf("cold_solve_estimated_error: %.2e m\n", cold.estimated_error);
  std::printf("cold_solve_converged: %d bool\n", cold.converged ? 1 : 0);

  // What a fit does: a small parameter change, re-solved warm at the same resolution.
  RodSimulator warm_sim(cold_opt);
  warm_sim.Simulate(spec);
  RodSpec changed = spec;
  int k = 0;
  SimulationResult warm;
  const double warm_ms = MedianMs(reps, [&] {
    changed.material.linear_density = spec.material.linear_density * (1.0 + 1e-3 * (++k % 2 ? 1 : -1));
    warm = warm_sim.Resimulate(changed);
  });
  std::printf("warm_resolve: %.3f ms\n", warm_ms);
  std::printf("warm_resolve_newton_iterations: %d iterations\n", warm.newton_iterations);

  // Growth with elements: one Newton solve from the built-in initial shape per resolution.
  const Polyline curve = DefaultInitialCurve(spec);
  double first_per_element = 0.0;
  for (int n : {100, 400, 1600, 6400}) {
    Discretisation d;
    d.elements_per_span = {n};
    const RodModel model = CompileRodModel(spec, d);
    StaticsSummary sum;
    const double ms = MedianMs(std::max(3, reps / 4), [&] {
      RodState st = MakeInitialState(model, curve);
      sum = SolveStatics(model, &st, StaticsOptions{});
    });
    const double per = ms / n * 1e3;
    if (first_per_element == 0.0) first_per_element = per;
    std::printf("solve_n%d: %.3f ms\n", n, ms);
    std::printf("solve_n%d_iterations: %d iterations\n", n, sum.iterations);
    std::printf("solve_n%d_per_element: %.3f us\n", n, per);
  }
  BenchNetwork(reps);
  BenchKblSizedNetwork();
  BenchKblSizedLengths();
  BenchDrawnShapes();
  BenchContact(reps);
  BenchMotionSweep(spec, reps);
  BenchNetworkMotionSweep();
  return kExitOk;
}

}  // namespace

void RegisterBenchCommand(CLI::App& app, int* exit_code) {
  auto case_path = std::make_shared<std::string>();
  auto diagnose_dir = std::make_shared<std::string>();
  auto reps = std::make_shared<int>(21);
  auto kbl_only = std::make_shared<bool>(false);
  auto drawn_only = std::make_shared<bool>(false);
  auto relax_files = std::make_shared<std::vector<std::string>>();
  auto processes = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand("bench", "Print performance figures (name: value unit)");
  cmd->add_option("--case", *case_path, "case.json to time instead of the built-in sagging cable");
  cmd->add_option("--repeat", *reps, "repetitions per figure (the median is printed)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  cmd->add_option("--diagnose", *diagnose_dir,
                  "instead: time the diagnosis of every case under DIR, one case at a time with "
                  "its fits on every usable core (taskset -c 0: one), as `diagnose --jobs 1` "
                  "(per case, median and worst)");
  cmd->add_flag("--kbl-network", *kbl_only,
               "instead: only the KBL-sized network figures (kbl_network*)");
  cmd->add_flag("--drawn-shapes", *drawn_only,
               "instead: only the cables drawn as coils, springs, kinks and taut (drawn_*)");
  cmd->add_option("--relax", *relax_files,
                  "instead: relax each FILE end to end as `cablefit relax FILE` does (pictures and "
                  "STEP included), --repeat times (default here 3), the median run's seconds per "
                  "stage and its network (relax_<stem>_*)");
  cmd->add_flag("--processes", *processes,
                "instead: whole `cablefit --version` and `cablefit simulate` processes, start-up "
                "included (process_*)");
  cmd->callback([=] {
    if (!relax_files->empty()) {
      *exit_code = BenchRelaxFiles(*relax_files, cmd->count("--repeat") ? *reps : 3);
      return;
    }
    if (*processes) {
      *exit_code = BenchProcesses(*reps);
      return;
    }
    if (*kbl_only || *drawn_only) {
      if (*kbl_only) {
        BenchKblSizedNetwork();
        BenchKblSizedLengths();
      }
      if (*drawn_only) BenchDrawnShapes();
      *exit_code = kExitOk;
      return;
    }
    *exit_code = diagnose_dir->empty() ? RunBench(*case_path, *reps) : BenchDiagnose(*diagnose_dir);
  });
}

}  // namespace cablefit::addin
