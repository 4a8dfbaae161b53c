#include "cablefit/core/solver/motion_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/solver/internal/sweep_steps.h"

namespace cablefit {
namespace {

using Clock = std::chrono::steady_clock;

// Samples compared between poses: enough to see any shape change a snap makes.
constexpr int kCompareSamples = 101;

double LargestStep(const SimulationResult& a, const SimulationResult& b, double length) {
  const Eigen::VectorXd s = UniformArcLengths(length, kCompareSamples);
  const Polyline pa = SampleCenterline(a.solution.centerline, s);
  const Polyline pb = SampleCenterline(b.solution.centerline, s);
  return (pa.points - pb.points).colwise().norm().maxCoeff();
}

SimulationOptions WithEscape(SimulationOptions o, bool escape) {
  o.statics.escape_unstable = escape;
  return o;
}

}  // namespace

RodSpec MovedSpec(const RodSpec& base, const std::vector<int>& moving, const Eigen::Isometry3d& t) {
  RodSpec spec = base;
  for (int k : moving) {
    if (k < 0 || k >= static_cast<int>(spec.supports.size()))
      throw InvalidInput("moving support " + std::to_string(k) + " does not exist (the cable has " +
                         std::to_string(spec.supports.size()) + ")");
    SupportSpec& sp = spec.supports[static_cast<size_t>(k)];
    sp.position = t * sp.position;
    sp.tangent = t.linear() * sp.tangent;
    sp.normal = t.linear() * sp.normal;
  }
  return spec;
}

bool SweepOptions::IsValid(std::string* why) const {
  if (!(jump_factor > 1)) {
    if (why) *why = "jump_factor must be > 1";
    return false;
  }
  if (substeps < 1) {
    if (why) *why = "substeps must be >= 1";
    return false;
  }
  return simulation.IsValid(why);
}

SweepSummary SweepRod(const RodSpec& base, const Polyline* initial, const std::vector<int>& moving,
                      const std::function<Eigen::Isometry3d(double)>& motion,
                      const std::vector<double>& q, const SweepOptions& options) {
  const auto t0 = Clock::now();
  SweepSummary out;
  std::string why;
  if (!options.IsValid(&why)) {
    out.message = "invalid sweep options: " + why;
    return out;
  }
  auto spec_at = [&](double p) { return MovedSpec(base, moving, motion(p)); };
  auto follow = std::make_unique<RodSimulator>(WithEscape(options.simulation, false));
  SimulationResult current = follow->Simulate(spec_at(0.0), initial);
  if (!current.converged) {
    out.message = "the drawn pose does not converge: " + current.solution.summary.message;
    return out;
  }
  // Warm solve at p from the simulator's last state; sub-steps from `from` when it fails.
  // Warm solve at p from the simulator's last state (`current`, at parameter `from`). When it
  // fails, the simulator is put back on `current` (a failed solve leaves its state anywhere)
  // and p is approached in sub-steps.
  auto solve = [&](double from, double p) {
    SimulationResult r = follow->Resimulate(spec_at(p));
    if (r.converged) return r;
    follow = std::make_unique<RodSimulator>(WithEscape(options.simulation, false));
    r = follow->Simulate(spec_at(from), &current.solution.centerline);
    for (int k = 1; k <= options.substeps && r.converged; ++k)
      r = follow->Resimulate(spec_at(from + (p - from) * k / options.substeps));
    return r;
  };
  // Walk from the drawn pose to the first one (not reported).
  double walked = 0.0;
  for (double p : internal::ApproachSteps(q)) {
    current = solve(walked, p);
    walked = p;
    if (!current.converged) {
      out.message = "the motion's first pose could not be reached from the drawn one";
      return out;
    }
  }
  double previous_step = 0.0;
  double previous_q = q.empty() ? 0.0 : q.front();
  for (size_t i = 0; i < q.size(); ++i) {
    SweepPose pose;
    pose.q = q[i];
    SimulationResult r = solve(previous_q, q[i]);
    if (!r.converged) {
      out.message =
          "pose " + std::to_string(i) + " did not converge: " + r.solution.summary.message;
      break;
    }
    pose.step = LargestStep(r, current, base.length);
    pose.jumped = internal::Jumped(pose.step, previous_step, options.jump_factor,
                                   10 * options.simulation.accuracy);
    if (!r.solution.summary.stable) {
      // The branch followed is unstable here: leave it for the nearest stable equilibrium and
      // follow that one from now on.
      pose.escaped_unstable = true;
      for (double fraction : internal::kEscapeBends) {
        RodSimulator escape(WithEscape(options.simulation, true));
        const Polyline bumped =
            internal::BentSideways(r.solution.centerline, fraction * base.length);
        const SimulationResult stable = escape.Simulate(spec_at(q[i]), &bumped);
        if (!stable.converged || !stable.solution.summary.stable) continue;
        follow = std::make_unique<RodSimulator>(WithEscape(options.simulation, false));
        SimulationResult again = follow->Simulate(spec_at(q[i]), &stable.solution.centerline);
        r = again.converged && again.solution.summary.stable ? std::move(again) : stable;
        break;
      }
    }
    pose.converged = r.converged;
    pose.stable = r.solution.summary.stable;
    pose.result = std::move(r);
    if ((pose.jumped || pose.escaped_unstable) && out.branch_lost_pose < 0)
      out.branch_lost_pose = static_cast<int>(i);
    // A jump's step is no yardstick for the next pose's, nor is one within the solver's
    // accuracy (a pose solved again where it already is).
    if (!pose.jumped && pose.step > 10 * options.simulation.accuracy) previous_step = pose.step;
    current = pose.result;
    previous_q = q[i];
    out.poses.push_back(std::move(pose));
  }
  out.completed = out.poses.size() == q.size();
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

}  // namespace cablefit
