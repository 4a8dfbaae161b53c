#include "bench_motion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "cablefit/app/bench/bench_harness.h"
#include "cablefit/app/relax/relax_network.h"
#include "cablefit/core/network/network_sweep.h"
#include "cablefit/core/solver/motion_sweep.h"

namespace cablefit::addin {
namespace {

// 0 to 60 degrees in 50 steps and back.
std::vector<double> ThereAndBack() {
  constexpr int kSteps = 50;
  std::vector<double> q;
  for (int i = 0; i <= kSteps; ++i) q.push_back(M_PI / 3 * i / kSteps);
  for (int i = kSteps - 1; i >= 0; --i) q.push_back(M_PI / 3 * i / kSteps);
  return q;
}

// About the vertical axis through `point`.
std::function<Eigen::Isometry3d(double)> HingeAt(const Vec3& point) {
  return [point](double angle) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix();
    t.translation() = point - t.linear() * point;
    return t;
  };
}

}  // namespace

void BenchMotionSweep(const RodSpec& spec, int reps) {
  if (spec.supports.empty()) return;
  const auto hinge = HingeAt(spec.supports.back().position + Vec3(0.1, 0.0, 0.0));
  const std::vector<double> q = ThereAndBack();
  const int last = static_cast<int>(spec.supports.size()) - 1;
  std::vector<double> ms;
  SweepSummary sweep;
  for (int r = 0; r < std::max(1, reps / 4); ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    sweep = SweepRod(spec, nullptr, {last}, hinge, q);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(ms.begin(), ms.begin() + static_cast<long>(ms.size() / 2), ms.end());
  int iterations = 0;
  for (const SweepPose& p : sweep.poses) iterations += p.result.newton_iterations;
  double back = 0.0;
  if (sweep.completed) {
    const Eigen::VectorXd s = UniformArcLengths(spec.length, 201);
    back = (SampleCenterline(sweep.poses.front().result.solution.centerline, s).points -
            SampleCenterline(sweep.poses.back().result.solution.centerline, s).points)
               .colwise()
               .norm()
               .maxCoeff();
  }
  std::printf("motion_sweep_poses: %zu poses\n", sweep.poses.size());
  std::printf("motion_sweep: %.3f ms\n", ms[ms.size() / 2]);
  std::printf("motion_sweep_per_pose: %.3f ms\n",
              ms[ms.size() / 2] / std::max<size_t>(1, sweep.poses.size()));
  std::printf("motion_sweep_newton_iterations: %d iterations\n", iterations);
  std::printf("motion_sweep_completed: %d bool\n", sweep.completed ? 1 : 0);
  std::printf("motion_sweep_back_to_start: %.2e m\n", back);
}

void BenchNetworkMotionSweep() {
  const NetworkSpec spec = SyntheticHarness();
  // The end clamp of the trunk's last segment: the branch whose end no junction holds.
  int branch = -1;
  for (size_t b = 0; b < spec.branches.size(); ++b)
    if (spec.branches[b].end_junction < 0 && spec.branches[b].name.rfind("trunk", 0) == 0 &&
        !spec.branches[b].supports.empty())
      branch = static_cast<int>(b);
  if (branch < 0) return;
  const BranchSpec& moved = spec.branches[static_cast<size_t>(branch)];
  const int support = static_cast<int>(moved.supports.size()) - 1;
  // About the clip before it (or 0.1 m beside it): the span between them keeps its length.
  const Vec3 pivot = support > 0 ? moved.supports[static_cast<size_t>(support - 1)].position
                                 : moved.supports.back().position + Vec3(0.1, 0.0, 0.0);
  NetworkSweepOptions options;
  options.network = PlanNetworkRelax(spec, SimulationOptions{}).options;
  options.network.refinement = 0;
  const std::vector<double> q = ThereAndBack();
  const auto t0 = std::chrono::steady_clock::now();
  const NetworkSweepSummary sweep = SweepNetwork(
      spec, {{{branch, support}}, {}}, HingeAt(pivot), q, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double back = 0.0;
  if (sweep.completed)
    for (size_t b = 0; b < spec.branches.size(); ++b)
      back = std::max(back, (sweep.poses.front().solution.branches[b].points -
                             sweep.poses.back().solution.branches[b].points)
                                .colwise()
                                .norm()
                                .maxCoeff());
  std::printf("network_motion_branches: %zu branches\n", spec.branches.size());
  std::printf("network_motion_elements: %d elements\n",
              sweep.poses.empty() ? 0 : sweep.poses.front().solution.num_elements);
  std::printf("network_motion_poses: %zu poses\n", sweep.poses.size());
  std::printf("network_motion_sweep: %.3f s\n", seconds);
  std::printf("network_motion_per_pose: %.3f ms\n",
              1e3 * seconds / std::max<size_t>(1, sweep.poses.size()));
  std::printf("network_motion_newton_iterations: %d iterations\n", sweep.newton_iterations);
  std::printf("network_motion_completed: %d bool\n", sweep.completed ? 1 : 0);
  std::printf("network_motion_stability_lost_pose: %d pose\n", sweep.branch_lost_pose);
  std::printf("network_motion_back_to_start: %.2e m\n", back);
}

}  // namespace cablefit::addin
