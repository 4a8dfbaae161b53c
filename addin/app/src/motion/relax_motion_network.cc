#include "motion/relax_motion_network.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "cablefit/core/network/network_sweep.h"
#include "motion/motion_pose.h"

namespace cablefit::addin {

std::vector<CableMotion> SweepNetworkGroupMotion(const RelaxedHarness& f, const RelaxGroup& group,
                                                 const std::map<int, std::vector<int>>& moving,
                                                 const std::vector<OrientedBox>& boxes,
                                                 const HarnessConfig& config,
                                                 const SimulationOptions& options,
                                                 const std::vector<double>& q,
                                                 const std::vector<int>& moving_solids) {
  const auto t0 = std::chrono::steady_clock::now();
  const MotionConfig& mc = *config.motion;
  std::vector<CableMotion> out;
  for (int c : group.cables) {
    CableMotion cm;
    cm.cable = c;
    cm.name = f.cables[static_cast<size_t>(c)]->setup.name;
    const auto it = moving.find(c);
    if (it != moving.end()) cm.moving = it->second;
    cm.network = GroupLabel(f.drawing, group);
    out.push_back(std::move(cm));
  }
  try {
    std::vector<CableSetup> setups;
    const NetworkSpec spec = GroupNetworkSpec(f.drawing, group, boxes, config, &setups);
    NetworkMoving parts;
    for (size_t b = 0; b < group.cables.size(); ++b)
      for (const CableMotion& cm : out)
        if (cm.cable == group.cables[b])
          for (int k : cm.moving) parts.supports.push_back({static_cast<int>(b), k});
    for (size_t k = 0; k < group.obstacles.size(); ++k)
      if (std::count(moving_solids.begin(), moving_solids.end(), group.obstacles[k]) > 0)
        parts.obstacles.push_back(static_cast<int>(k));
    // Every pose at one of the relax's levels (RepeatedSolveLevel); how far it is from the
    // refined relax is measured at the drawn pose and reported.
    NetworkSweepOptions so;
    so.network = PlanNetworkRelax(spec, options).options;
    so.network.refinement = RepeatedSolveLevel(
        f.cables[static_cast<size_t>(group.cables[0])]->result.level_elements);
    so.jump_floor = 10 * options.accuracy;
    const NetworkSweepSummary sweep =
        SweepNetwork(spec, parts, [&mc](double p) { return mc.At(p); }, q, so);
    for (size_t b = 0; b < out.size(); ++b) {
      CableMotion& cm = out[b];
      const CableRelaxation& relaxed = *f.cables[static_cast<size_t>(cm.cable)];
      cm.branch_lost_pose = sweep.branch_lost_pose;
      cm.completed = sweep.completed;
      cm.message = sweep.message;
      for (const NetworkSweepPose& np : sweep.poses) {
        SweepPose p;
        p.q = np.q;
        p.converged = np.converged;
        p.stable = np.stable;
        p.escaped_unstable = np.escaped_unstable;
        p.jumped = np.jumped;
        p.step = np.step;
        p.result.converged = np.converged;
        p.result.newton_iterations = np.solution.summary.iterations;
        p.result.solution = BranchSolution(spec, np.solution, static_cast<int>(b));
        cm.poses.push_back(MeasurePose(relaxed, p, config.min_bend_radius_factor));
        cm.elements = np.solution.num_elements;
      }
      // The sweep's resolution against the refined relax, where both have the drawn pose.
      if (!cm.poses.empty() && cm.poses.front().q == 0.0) {
        const Polyline& a = cm.poses.front().centreline;
        const Polyline b2 = SampleCenterline(relaxed.relaxed, a.s);
        cm.resolution_error = (a.points - b2.points).colwise().norm().maxCoeff();
      }
    }
  } catch (const std::exception& e) {
    for (CableMotion& cm : out) cm.message = e.what();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (CableMotion& cm : out) {
    cm.back_to_start = BackToStart(cm, mc.there_and_back);
    cm.seconds = seconds;
  }
  return out;
}

}  // namespace cablefit::addin
