#include "cablefit/core/network/network_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/solver/internal/sweep_steps.h"

namespace cablefit {
namespace {

using Clock = std::chrono::steady_clock;

// Largest move of any node between two solutions of one network at one resolution.
double LargestStep(const NetworkSolution& a, const NetworkSolution& b) {
  double step = 0.0;
  for (size_t k = 0; k < a.branches.size() && k < b.branches.size(); ++k)
    if (a.branches[k].size() == b.branches[k].size() && a.branches[k].size() > 0)
      step = std::max(step,
                      (a.branches[k].points - b.branches[k].points).colwise().norm().maxCoeff());
  return step;
}

NetworkOptions Warm(NetworkOptions o, const NetworkSolution* from, bool escape) {
  o.statics.escape_unstable = escape;
  o.initial_routes.clear();
  o.initial_normals.clear();
  if (from) {
    o.initial_routes = from->branches;
    o.initial_normals = from->element_normals;
  }
  return o;
}

}  // namespace

NetworkSpec MovedNetworkSpec(const NetworkSpec& base, const NetworkMoving& moving,
                             const Eigen::Isometry3d& t) {
  NetworkSpec spec = base;
  for (int k : moving.obstacles) {
    if (k < 0 || k >= static_cast<int>(spec.obstacles.size()))
      throw InvalidInput("moving obstacle " + std::to_string(k) + " does not exist (the network has " +
                         std::to_string(spec.obstacles.size()) + ")");
    Eigen::Matrix3Xd& v = spec.obstacles[static_cast<size_t>(k)].mesh.vertices;
    v = (t.linear() * v).colwise() + t.translation();
  }
  for (const NetworkMovingSupport& m : moving.supports) {
    if (m.branch < 0 || m.branch >= static_cast<int>(spec.branches.size()))
      throw InvalidInput("moving support: branch " + std::to_string(m.branch) +
                         " does not exist (the network has " +
                         std::to_string(spec.branches.size()) + ")");
    BranchSpec& b = spec.branches[static_cast<size_t>(m.branch)];
    if (m.support < 0 || m.support >= static_cast<int>(b.supports.size()))
      throw InvalidInput("moving support " + std::to_string(m.support) + " of branch '" + b.name +
                         "' does not exist (it has " + std::to_string(b.supports.size()) + ")");
    SupportSpec& sp = b.supports[static_cast<size_t>(m.support)];
    sp.position = t * sp.position;
    sp.tangent = t.linear() * sp.tangent;
    sp.normal = t.linear() * sp.normal;
  }
  return spec;
}

bool NetworkSweepOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(jump_factor > 1)) return fail("jump_factor must be > 1");
  if (!(jump_floor >= 0)) return fail("jump_floor must be >= 0");
  if (substeps < 1) return fail("substeps must be >= 1");
  return network.IsValid(why);
}

NetworkSweepSummary SweepNetwork(const NetworkSpec& base, const NetworkMoving& moving,
                                 const std::function<Eigen::Isometry3d(double)>& motion,
                                 const std::vector<double>& q, const NetworkSweepOptions& options) {
  const auto t0 = Clock::now();
  NetworkSweepSummary out;
  std::string why;
  if (!options.IsValid(&why)) {
    out.message = "invalid sweep options: " + why;
    return out;
  }
  auto spec_at = [&](double p) { return MovedNetworkSpec(base, moving, motion(p)); };
  auto solve_from = [&](double p, const NetworkSolution* from, bool escape) {
    NetworkSolution s = SolveNetwork(spec_at(p), Warm(options.network, from, escape));
    out.newton_iterations += s.summary.iterations;
    return s;
  };
  NetworkSolution current = solve_from(0.0, nullptr, false);
  if (!current.converged()) {
    out.message = "the drawn pose does not converge: " + current.summary.message;
    return out;
  }
  // Warm solve at p from `current` (at `from`); in sub-steps when that fails.
  auto solve = [&](double from, double p) {
    NetworkSolution r = solve_from(p, &current, false);
    if (r.converged()) return r;
    r = current;
    for (int k = 1; k <= options.substeps; ++k) {
      r = solve_from(from + (p - from) * k / options.substeps, &r, false);
      if (!r.converged()) break;
    }
    return r;
  };
  double walked = 0.0;  // from the drawn pose to the first one (not reported)
  for (double p : internal::ApproachSteps(q)) {
    NetworkSolution r = solve(walked, p);
    walked = p;
    if (!r.converged()) {
      out.message = "the motion's first pose could not be reached from the drawn one: " +
                    r.summary.message;
      return out;
    }
    current = std::move(r);
  }
  double previous_step = 0.0;
  double previous_q = q.empty() ? 0.0 : q.front();
  for (size_t i = 0; i < q.size(); ++i) {
    NetworkSweepPose pose;
    pose.q = q[i];
    NetworkSolution r = solve(previous_q, q[i]);
    if (!r.converged()) {
      out.message = "pose " + std::to_string(i) + " did not converge: " + r.summary.message;
      break;
    }
    pose.step = LargestStep(r, current);
    pose.jumped = internal::Jumped(pose.step, previous_step, options.jump_factor, options.jump_floor);
    if (!r.summary.stable) {
      // The branch followed is unstable here: leave it for the nearest stable equilibrium
      // (bent starts, the solver's escape on) and follow that one from now on.
      pose.escaped_unstable = true;
      for (double fraction : internal::kEscapeBends) {
        NetworkOptions o = Warm(options.network, nullptr, true);
        o.initial_routes = r.branches;  // each branch bent over its own length
        for (Polyline& b : o.initial_routes)
          if (b.size() > 1) b = internal::BentSideways(b, fraction * (b.s[b.size() - 1] - b.s[0]));
        NetworkSolution stable = SolveNetwork(spec_at(q[i]), o);
        out.newton_iterations += stable.summary.iterations;
        if (!stable.converged() || !stable.summary.stable) continue;
        r = std::move(stable);
        break;
      }
    }
    pose.converged = r.converged();
    pose.stable = r.summary.stable;
    pose.solution = std::move(r);
    if ((pose.jumped || pose.escaped_unstable) && out.branch_lost_pose < 0)
      out.branch_lost_pose = static_cast<int>(i);
    // A jump's step is no yardstick for the next pose's, nor is one within the solver's noise
    // (a pose solved again where it already is).
    if (!pose.jumped && pose.step > options.jump_floor) previous_step = pose.step;
    current = pose.solution;
    previous_q = q[i];
    out.poses.push_back(std::move(pose));
  }
  out.completed = out.poses.size() == q.size();
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

}  // namespace cablefit
