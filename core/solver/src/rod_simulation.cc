#include "cablefit/core/solver/rod_simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/initial_shape.h"

namespace cablefit {
namespace {

using Clock = std::chrono::steady_clock;

// Positions of the finer level at the coarser level's nodes (every second node).
Eigen::Matrix3Xd Coarsen(const Eigen::Matrix3Xd& fine) {
  const int nc = static_cast<int>((fine.cols() - 1) / 2 + 1);
  Eigen::Matrix3Xd out(3, nc);
  for (int i = 0; i < nc; ++i) out.col(i) = fine.col(2 * i);
  return out;
}

std::vector<int> SpanCounts(const RodSpec& spec, double h0) {
  const std::vector<double> bp = SpanBreakpoints(spec);
  std::vector<int> counts;
  for (size_t k = 0; k + 1 < bp.size(); ++k)
    counts.push_back(std::max(2, static_cast<int>(std::ceil((bp[k + 1] - bp[k]) / h0 - 1e-9))));
  return counts;
}

double MaxDistance(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  return (a - b).colwise().norm().maxCoeff();
}

}  // namespace

bool SimulationOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(accuracy > 0)) return fail("accuracy must be > 0");
  if (coarse_element_length < 0) return fail("coarse_element_length must be >= 0");
  if (min_levels < 1 || max_levels < min_levels) return fail("need 1 <= min_levels <= max_levels");
  return statics.IsValid(why);
}

RodSimulator::RodSimulator(SimulationOptions options) : options_(std::move(options)) {
  std::string why;
  if (!options_.IsValid(&why)) throw InvalidInput("simulation options: " + why);
}

SimulationResult RodSimulator::Simulate(const RodSpec& spec, const Polyline* initial) {
  const auto t0 = Clock::now();
  ValidateRodSpec(spec);
  models_.clear();
  states_.clear();
  const double h0 = options_.coarse_element_length > 0 ? options_.coarse_element_length
                                                        : spec.length / 24.0;
  // Span counts of the coarsest level: at least two elements per span.
  coarse_h_ = h0;
  span_elements_ = SpanCounts(spec, h0);
  const Polyline curve = initial ? ReparameteriseToLength(*initial, spec.length)
                                 : DefaultInitialCurve(spec);
  std::vector<StaticsSummary> summaries;
  std::vector<Eigen::Matrix3Xd> positions, extrapolated;
  SimulationResult result;
  double estimate = INFINITY;
  for (int level = 0; level < options_.max_levels; ++level) {
    Discretisation disc;
    disc.elements_per_span = span_elements_;
    disc.refinement = level;
    models_.push_back(CompileRodModel(spec, disc));
    const RodModel& model = models_.back();
    RodState state = level == 0 ? MakeInitialState(model, curve)
                                : TransferState(models_[level - 1], states_[level - 1], model);
    StaticsSummary sum = SolveStatics(model, &state, options_.statics);
    states_.push_back(std::move(state));
    summaries.push_back(sum);
    if (!sum.converged()) break;
    positions.push_back(states_.back().NodePositions(model));
    if (level >= 1) {
      const Eigen::Matrix3Xd fine = Coarsen(positions[level]);
      extrapolated.push_back((4.0 * fine - positions[level - 1]) / 3.0);
      const int e = static_cast<int>(extrapolated.size()) - 1;
      if (e >= 1) {
        // Successive extrapolations: the older one is ~16x less accurate.
        estimate = MaxDistance(Coarsen(extrapolated[e]), extrapolated[e - 1]) / 15.0;
      } else {
        estimate = MaxDistance(fine, positions[level - 1]) / 3.0;  // error of the finer level
      }
    }
    if (level + 1 >= options_.min_levels && estimate <= options_.accuracy) break;
  }
  result = Finish(summaries, std::chrono::duration<double>(Clock::now() - t0).count());
  result.estimated_error = estimate;
  result.accuracy_met = result.converged && estimate <= options_.accuracy;
  return result;
}

SimulationResult RodSimulator::Resimulate(const RodSpec& spec) {
  CABLEFIT_REQUIRE(!states_.empty(), "Resimulate needs a previous Simulate");
  const auto t0 = Clock::now();
  ValidateRodSpec(spec);
  std::vector<StaticsSummary> summaries;
  // A changed layout (a point load moved, a support added) gets new spans of the same size.
  if (SpanBreakpoints(spec).size() != span_elements_.size() + 1 ||
      spec.length != models_[0].spec.length)
    span_elements_ = SpanCounts(spec, coarse_h_);
  for (size_t level = 0; level < models_.size(); ++level) {
    Discretisation disc;
    disc.elements_per_span = span_elements_;
    disc.refinement = static_cast<int>(level);
    RodModel model = CompileRodModel(spec, disc);
    RodState state = TransferState(models_[level], states_[level], model);
    StaticsSummary sum = SolveStatics(model, &state, options_.statics);
    models_[level] = std::move(model);
    states_[level] = std::move(state);
    summaries.push_back(sum);
    if (!sum.converged()) break;
  }
  SimulationResult result = Finish(summaries, std::chrono::duration<double>(Clock::now() - t0).count());
  return result;
}

SimulationResult RodSimulator::Finish(std::vector<StaticsSummary> summaries, double seconds) {
  SimulationResult r;
  r.seconds = seconds;
  r.converged = !summaries.empty() && std::all_of(summaries.begin(), summaries.end(),
                                                  [](const StaticsSummary& s) { return s.converged(); });
  for (const auto& s : summaries) r.newton_iterations += s.iterations;
  const int nl = static_cast<int>(summaries.size());
  for (int l = 0; l < nl; ++l) r.level_elements.push_back(models_[l].num_elements);
  const int fin = nl - 1;
  r.solution = ExtractSolution(models_[fin], states_[fin], summaries[fin]);
  r.solution.summary.iterations = r.newton_iterations;
  r.solution.summary.seconds = seconds;
  if (r.converged && nl >= 2) {
    // Richardson on the last two levels: positions at the coarser nodes, and reactions.
    const RodSolution coarse = ExtractSolution(models_[fin - 1], states_[fin - 1], summaries[fin - 1]);
    const Eigen::Matrix3Xd fine = Coarsen(r.solution.centerline.points);
    Polyline ext;
    ext.s = coarse.centerline.s;
    ext.points = (4.0 * fine - coarse.centerline.points) / 3.0;
    r.solution.centerline = ext;
    for (size_t k = 0; k < r.solution.reactions.size(); ++k) {
      auto& a = r.solution.reactions[k];
      const auto& b = coarse.reactions[k];
      a.force = (4.0 * a.force - b.force) / 3.0;
      a.moment = (4.0 * a.moment - b.moment) / 3.0;
    }
  }
  return r;
}

Eigen::VectorXd UniformArcLengths(double length, int n) {
  return Eigen::VectorXd::LinSpaced(n, 0.0, length);
}

Polyline SampleCenterline(const Polyline& nodes, const Eigen::VectorXd& s) {
  const int n = nodes.size();
  Polyline out;
  out.s = s;
  out.points.resize(3, s.size());
  for (int k = 0; k < s.size(); ++k) {
    const double x = std::clamp(s[k], nodes.s[0], nodes.s[n - 1]);
    int i = static_cast<int>(std::upper_bound(nodes.s.data(), nodes.s.data() + n, x) - nodes.s.data()) - 1;
    i = std::clamp(i, 0, n - 2);
    // Cubic Lagrange through the four nodes around the interval (fewer near the ends).
    const int lo = std::clamp(i - 1, 0, std::max(0, n - 4));
    const int hi = std::min(n - 1, lo + 3);
    Vec3 p = Vec3::Zero();
    for (int a = lo; a <= hi; ++a) {
      double w = 1.0;
      for (int b = lo; b <= hi; ++b)
        if (b != a) w *= (x - nodes.s[b]) / (nodes.s[a] - nodes.s[b]);
      p += w * nodes.points.col(a);
    }
    out.points.col(k) = p;
  }
  return out;
}

}  // namespace cablefit
