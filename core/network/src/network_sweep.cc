#include "cablefit/core/network/network_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "cablefit/core/base/errors.h"

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

// Leaving an unstable branch, as SweepRod does: every branch bent sideways by a half sine of
// these fractions of its length (zero at its ends, so junctions stay joined), then solved with
// the solver's own escape on. A symmetric saddle (a straight branch pushed past its Euler load)
// holds the solver's small frame kicks; a bend of the order of the buckled shape's does not.
constexpr double kEscapeBumps[] = {0.01, 0.03, 0.1};

std::vector<Polyline> Bumped(const std::vector<Polyline>& branches, double fraction) {
  std::vector<Polyline> out = branches;
  const Vec3 fixed = Vec3(0.267, 0.534, 0.802).normalized();  // along no axis a drawing uses
  for (Polyline& c : out) {
    const int n = c.size();
    if (n < 3) continue;
    const double length = c.s[n - 1] - c.s[0];
    if (!(length > 0)) continue;
    const Polyline original = c;
    for (int i = 0; i < n; ++i) {
      const int a = std::max(0, i - 1), b = std::min(n - 1, i + 1);
      Vec3 tangent = original.points.col(b) - original.points.col(a);
      if (tangent.norm() == 0) continue;
      tangent.normalize();
      Vec3 side = fixed - fixed.dot(tangent) * tangent;
      if (side.norm() < 1e-6) side = tangent.unitOrthogonal();
      c.points.col(i) += fraction * length * std::sin(M_PI * (c.s[i] - c.s[0]) / length) *
                         side.normalized();
    }
  }
  return out;
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
  if (!q.empty() && q.front() != 0.0) {
    double largest = 0.0;
    for (size_t i = 1; i < q.size(); ++i) largest = std::max(largest, std::abs(q[i] - q[i - 1]));
    const int n =
        largest > 0 ? std::max(1, static_cast<int>(std::ceil(std::abs(q.front()) / largest))) : 1;
    for (int k = 1; k <= n; ++k) {
      NetworkSolution r = solve(q.front() * (k - 1) / n, q.front() * k / n);
      if (!r.converged()) {
        out.message = "the motion's first pose could not be reached from the drawn one: " +
                      r.summary.message;
        return out;
      }
      current = std::move(r);
    }
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
    pose.jumped = i > 0 && previous_step > 0 && pose.step > options.jump_factor * previous_step &&
                  pose.step > options.jump_floor;
    if (!r.summary.stable) {
      // The branch followed is unstable here: leave it for the nearest stable equilibrium
      // (bent starts, the solver's escape on) and follow that one from now on.
      pose.escaped_unstable = true;
      for (double fraction : kEscapeBumps) {
        NetworkOptions o = Warm(options.network, nullptr, true);
        o.initial_routes = Bumped(r.branches, fraction);
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
