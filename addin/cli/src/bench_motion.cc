#include "bench_motion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cablefit/core/solver/motion_sweep.h"

namespace cablefit::addin {

void BenchMotionSweep(const RodSpec& spec, int reps) {
  if (spec.supports.empty()) return;
  const Vec3 end = spec.supports.back().position;
  const Vec3 point = end + Vec3(0.1, 0.0, 0.0);
  const auto hinge = [&point](double angle) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix();
    t.translation() = point - t.linear() * point;
    return t;
  };
  constexpr int kSteps = 50;
  std::vector<double> q;
  for (int i = 0; i <= kSteps; ++i) q.push_back(M_PI / 3 * i / kSteps);
  for (int i = kSteps - 1; i >= 0; --i) q.push_back(M_PI / 3 * i / kSteps);
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

}  // namespace cablefit::addin
