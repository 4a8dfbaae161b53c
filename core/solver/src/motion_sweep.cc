#include "cablefit/core/solver/motion_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "cablefit/core/base/errors.h"

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

// Leaving an unstable branch: the shape is bent sideways by a half sine of these fractions of
// the length (zero at the ends), in a fixed direction normal to it, and solved again with the
// solver's own escape on. A symmetric saddle (a straight rod pushed past its Euler load) holds
// the solver's small frame kicks; a bend of the order of the buckled shape's does not.
constexpr double kEscapeBumps[] = {0.01, 0.03, 0.1};

Polyline Bumped(const Polyline& c, double amplitude) {
  Polyline out = c;
  const double length = c.s[c.size() - 1] - c.s[0];
  // A fixed direction, not parallel to any axis a drawing is likely to use.
  const Vec3 fixed = Vec3(0.267, 0.534, 0.802).normalized();
  for (int i = 0; i < c.size(); ++i) {
    const int a = std::max(0, i - 1), b = std::min(c.size() - 1, i + 1);
    Vec3 tangent = c.points.col(b) - c.points.col(a);
    if (tangent.norm() == 0) continue;
    tangent.normalize();
    Vec3 side = fixed - fixed.dot(tangent) * tangent;
    if (side.norm() < 1e-6) side = tangent.unitOrthogonal();
    out.points.col(i) +=
        amplitude * std::sin(M_PI * (c.s[i] - c.s[0]) / length) * side.normalized();
  }
  return out;
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
  if (!q.empty() && q.front() != 0.0) {
    double largest = 0.0;
    for (size_t i = 1; i < q.size(); ++i) largest = std::max(largest, std::abs(q[i] - q[i - 1]));
    const int n =
        largest > 0 ? std::max(1, static_cast<int>(std::ceil(std::abs(q.front()) / largest))) : 1;
    for (int k = 1; k <= n && current.converged; ++k)
      current = solve(q.front() * (k - 1) / n, q.front() * k / n);
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
    pose.jumped = i > 0 && previous_step > 0 && pose.step > options.jump_factor * previous_step &&
                  pose.step > 10 * options.simulation.accuracy;
    if (!r.solution.summary.stable) {
      // The branch followed is unstable here: leave it for the nearest stable equilibrium and
      // follow that one from now on.
      pose.escaped_unstable = true;
      for (double amplitude : kEscapeBumps) {
        RodSimulator escape(WithEscape(options.simulation, true));
        const Polyline bumped = Bumped(r.solution.centerline, amplitude * base.length);
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
