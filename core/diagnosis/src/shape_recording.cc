#include "shape_recording.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

std::string Fixed(double v, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}

// How far the recording is from fitting between the clamps: for every clamp, the largest
// distance of a recorded point from it minus the farthest the cable could reach from it [m].
struct Reach {
  double excess = -INFINITY;  // > 0: some point is out of reach
  int clamp = 0;
  double distance = 0.0;
};
Reach ReachExcess(const RodSpec& spec, const Eigen::Matrix3Xd& pts) {
  Reach out;
  for (size_t k = 0; k < spec.supports.size(); ++k) {
    const SupportSpec& c = spec.supports[k];
    const double reach = std::max(c.s, spec.length - c.s);
    const double d = (pts.colwise() - c.position).colwise().norm().maxCoeff();
    if (d - reach > out.excess) out = {d - reach, static_cast<int>(k), d};
  }
  return out;
}

}  // namespace

PreparedRecording PrepareRecording(const RodSpec& nominal, const ShapeObservation& recorded,
                                   int max_points) {
  const int n_all = static_cast<int>(recorded.points.cols());
  if (n_all < 5) throw InvalidInput("the recording has only " + std::to_string(n_all) + " points");
  if (!recorded.points.allFinite()) throw InvalidInput("the recording has non-finite points");
  const double L = nominal.length;
  PreparedRecording out;

  // Does the recording belong between these clamps? How far a point may stray beyond the
  // cable's reach: its radius, the noise, and the uncertainty of where the clamps hold it.
  const double reach_tolerance =
      nominal.material.diameter + 10.0 * recorded.noise_sigma + 0.01 * L;
  ShapeObservation& obs = out.observation;
  obs = recorded;
  {
    const SupportSpec& c0 = nominal.supports.front();
    const SupportSpec& c1 = nominal.supports.back();
    const Vec3 first = obs.points.col(0), last = obs.points.col(n_all - 1);
    // A recording's ends lie at its end clamps (less the unseen margins); a recording listed from
    // the last clamp to the first has them swapped.
    double forward = 0.0, reverse = 0.0;
    if (c0.s <= 1e-6 * L) {
      forward += (first - c0.position).norm();
      reverse += (last - c0.position).norm();
    }
    if (nominal.supports.size() > 1 && c1.s >= (1 - 1e-6) * L &&
        (c1.position - c0.position).norm() > reach_tolerance) {
      forward += (last - c1.position).norm();
      reverse += (first - c1.position).norm();
    }
    if (forward > reach_tolerance && reverse < 0.5 * forward) {
      obs.points = recorded.points.rowwise().reverse();
      if (recorded.s.size() == n_all) obs.s = (L - recorded.s.reverse().array()).matrix();
      obs.coverage.clear();
      for (auto it = recorded.coverage.rbegin(); it != recorded.coverage.rend(); ++it)
        obs.coverage.emplace_back(L - it->second, L - it->first);
      DiagnosisNote note;
      note.kind = DiagnosisNote::Kind::kRecordingReversed;
      note.gap_as_listed = forward;
      note.gap_reversed = reverse;
      out.notes.push_back(note);
    }
  }
  const Reach reach = ReachExcess(nominal, obs.points);
  if (reach.excess > reach_tolerance) {
    const SupportSpec& c = nominal.supports[static_cast<size_t>(reach.clamp)];
    std::ostringstream os;
    os << "the recording does not fit its set-up: a recorded point lies "
       << Fixed(reach.distance, 3) << " m from the clamp at s=" << Fixed(c.s, 3) << " m, but "
       << Fixed(std::max(c.s, L - c.s), 3)
       << " m of cable cannot reach farther; check the units (metres), the clamp positions and "
          "that the recording belongs to this case";
    throw RecordingMismatch(os.str());
  }

  // Thin the points to a spacing of about two diameters: neighbouring centre points of a scan
  // share errors, and treating them as independent would overstate the evidence.
  Eigen::VectorXd& s_obs = out.s;
  s_obs = obs.s;
  if (s_obs.size() != n_all || !s_obs.allFinite()) {
    Polyline p;
    p.points = obs.points;
    p.ParameteriseByChords(0.0);
    s_obs = p.s * (L / std::max(p.s[n_all - 1], 1e-12));
  }
  const double spacing = std::max(L / max_points, 2.0 * nominal.material.diameter);
  std::vector<int> keep;
  for (int i = 0; i < n_all; ++i)
    if (keep.empty() || s_obs[i] - s_obs[keep.back()] >= spacing) keep.push_back(i);
  out.fit_points.resize(3, static_cast<int>(keep.size()));
  out.fit_s.resize(static_cast<int>(keep.size()));
  for (size_t k = 0; k < keep.size(); ++k) {
    out.fit_points.col(k) = obs.points.col(keep[k]);
    out.fit_s[k] = s_obs[keep[k]];
  }

  // Starting shape: the clamps' own positions plus the recorded points.
  std::vector<std::pair<double, Vec3>> pts;
  pts.emplace_back(0.0, nominal.supports.front().position);
  for (int i = 0; i < n_all; ++i)
    if (s_obs[i] > 0.005 * L && s_obs[i] < 0.995 * L) pts.emplace_back(s_obs[i], obs.points.col(i));
  if (nominal.supports.back().s >= L * (1 - 1e-9))
    pts.emplace_back(L, nominal.supports.back().position);
  std::sort(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.first < b.first; });
  out.initial.points.resize(3, static_cast<int>(pts.size()));
  out.initial.s.resize(static_cast<int>(pts.size()));
  for (size_t i = 0; i < pts.size(); ++i) {
    out.initial.s[i] = pts[i].first;
    out.initial.points.col(i) = pts[i].second;
  }
  return out;
}

}  // namespace cablefit
