// Chaining of seen stretches and arc length across gaps. Bridges are cubic Hermite curves
// (e.g. Farin, "Curves and Surfaces for CAGD", 5th ed., ch. 7) whose length is integrated by
// Gauss-Legendre quadrature; the chord is the lower bound on the true length of the gap.
#include "stretch_chain.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "cablefit/core/base/errors.h"

namespace cablefit::scan {
namespace {

struct State {
  Eigen::Vector3d position;  // 3 [m]
  Eigen::Vector3d tangent;   // 3 [-] unit, direction of travel
};

struct Oriented {
  int index = -1;
  bool reversed = false;
};

// Start state of a stretch when traversed in the given orientation.
State Entry(const Stretch& s, bool reversed) {
  if (!reversed) return {s.centres.col(0), s.tangents.col(0)};
  const Eigen::Index last = s.centres.cols() - 1;
  return {s.centres.col(last), -s.tangents.col(last)};
}

State Exit(const Stretch& s, bool reversed) {
  const State e = Entry(s, !reversed);
  return {e.position, -e.tangent};
}

// Bridge plausibility: length, inflated by how much the cable would have to turn.
double BridgeCost(const State& from, const State& to, double diameter) {
  const Eigen::Vector3d v = to.position - from.position;
  const double d = v.norm();
  const double turn = 0.5 * (1.0 - from.tangent.dot(to.tangent));
  double detour = 0.0;
  if (d > 2.0 * diameter) {  // closer than that, the bridge direction is noise
    const Eigen::Vector3d u = v / d;
    detour = 0.5 * (1.0 - from.tangent.dot(u)) + 0.5 * (1.0 - u.dot(to.tangent));
  }
  return d * (1.0 + 2.0 * (turn + detour)) + 5.0 * diameter * turn;
}

// Greedy chain from `state` over all unused stretches; returns the total bridge cost.
double GreedyChain(const std::vector<Stretch>& stretches, State state, std::vector<char> used,
                   double diameter, std::vector<Oriented>* order) {
  double total = 0.0;
  for (;;) {
    Oriented best;
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < stretches.size(); ++j) {
      if (used[j]) continue;
      for (bool rev : {false, true}) {
        const double c = BridgeCost(state, Entry(stretches[j], rev), diameter);
        if (c < best_cost) {
          best_cost = c;
          best = {static_cast<int>(j), rev};
        }
      }
    }
    if (best.index < 0) return total;
    total += best_cost;
    used[static_cast<std::size_t>(best.index)] = 1;
    order->push_back(best);
    state = Exit(stretches[static_cast<std::size_t>(best.index)], best.reversed);
  }
}

double NearestCentre(const std::vector<Stretch>& stretches, const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Stretch& s : stretches)
    best = std::min(best, (s.centres.colwise() - p).colwise().norm().minCoeff());
  return best;
}

std::string Mm(double metres) {
  std::ostringstream o;
  o.precision(3);
  o << metres * 1e3 << " mm";
  return o.str();
}

}  // namespace

double HermiteLength(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1,
                     const Eigen::Vector3d& t1) {
  const double chord = (p1 - p0).norm();
  if (chord == 0.0) return 0.0;
  const Eigen::Vector3d m0 = chord * t0.normalized();
  const Eigen::Vector3d m1 = chord * t1.normalized();
  // 5-point Gauss-Legendre on each of 8 sub-intervals: far below the bridge's own uncertainty.
  static const double kX[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                               0.9061798459386640};
  static const double kW[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                               0.4786286704993665, 0.2369268850561891};
  constexpr int kPieces = 8;
  double length = 0.0;
  for (int piece = 0; piece < kPieces; ++piece) {
    for (int g = 0; g < 5; ++g) {
      const double u = (piece + 0.5 * (kX[g] + 1.0)) / kPieces;
      const double u2 = u * u;
      const Eigen::Vector3d d = (6.0 * u2 - 6.0 * u) * p0 + (3.0 * u2 - 4.0 * u + 1.0) * m0 +
                                (-6.0 * u2 + 6.0 * u) * p1 + (3.0 * u2 - 2.0 * u) * m1;
      length += 0.5 * kW[g] * d.norm() / kPieces;
    }
  }
  return length;
}

void ChainStretches(const std::vector<Stretch>& stretches, const std::optional<ScanGuide>& guide,
                    double diameter, ScanCenterline* out) {
  if (stretches.empty()) throw InvalidInput("no seen stretch to chain");
  std::vector<Oriented> order;
  const std::vector<char> unused(stretches.size(), 0);
  if (guide) {
    const double limit = guide->length > 0.0 ? guide->length : std::numeric_limits<double>::infinity();
    const double d0 = NearestCentre(stretches, guide->start_position);
    const double d1 = NearestCentre(stretches, guide->end_position);
    if (d0 > limit || d1 > limit) {
      throw InvalidInput("scan lies " + Mm(std::max(d0, d1)) + " from a clamp, farther than the cable length " +
                         Mm(guide->length) + " (wrong scan or coordinate frame?)");
    }
    GreedyChain(stretches, {guide->start_position, guide->start_tangent.normalized()}, unused, diameter,
                &order);
  } else {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < stretches.size(); ++j) {
      for (bool rev : {false, true}) {
        std::vector<Oriented> candidate{{static_cast<int>(j), rev}};
        std::vector<char> used = unused;
        used[j] = 1;
        const double c = GreedyChain(stretches, Exit(stretches[j], rev), used, diameter, &candidate);
        if (c < best) {
          best = c;
          order = candidate;
        }
      }
    }
  }

  int n = 0;
  for (const Stretch& s : stretches) n += s.size();
  out->points.resize(3, n);
  out->tangents.resize(3, n);
  out->s.resize(n);
  out->radius.resize(n);
  out->support.resize(n);
  out->stretch.resize(n);
  out->coverage.clear();

  double s = 0.0;
  double bound = 0.0;
  std::optional<State> previous;
  if (guide) previous = State{guide->start_position, guide->start_tangent.normalized()};
  int col = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Stretch& st = stretches[static_cast<std::size_t>(order[k].index)];
    const bool rev = order[k].reversed;
    const State entry = Entry(st, rev);
    const double head = rev ? st.tail_extent : st.head_extent;
    const double tail = rev ? st.head_extent : st.tail_extent;
    if (previous) {
      const double chord = (entry.position - previous->position).norm();
      const double bridge = HermiteLength(previous->position, previous->tangent, entry.position, entry.tangent);
      s += bridge;
      // The chord is a hard lower bound; the 1 % margin covers a cable that wavers in the gap.
      bound += (bridge - chord) + 0.01 * chord;
    } else {
      s = head;  // no guide: s starts at the first seen surface point
    }
    const int m = st.size();
    for (int i = 0; i < m; ++i) {
      const int src = rev ? m - 1 - i : i;
      if (i > 0) {
        const int prev_src = rev ? src + 1 : src - 1;
        s += (st.centres.col(src) - st.centres.col(prev_src)).norm();
      }
      out->points.col(col) = st.centres.col(src);
      out->tangents.col(col) = rev ? Eigen::Vector3d(-st.tangents.col(src)) : Eigen::Vector3d(st.tangents.col(src));
      out->s(col) = s;
      out->radius(col) = st.radius(src);
      out->support(col) = st.support(src);
      out->stretch(col) = static_cast<int>(k);
      ++col;
    }
    const double s_first = out->s(col - m);
    out->coverage.push_back({std::max(0.0, s_first - head), s + tail});
    previous = Exit(st, rev);
  }
  out->estimated_length = out->coverage.back().s_end;
  if (guide) {
    const double chord = (guide->end_position - previous->position).norm();
    const double bridge =
        HermiteLength(previous->position, previous->tangent, guide->end_position, guide->end_tangent);
    out->estimated_length = s + bridge;
    bound += (bridge - chord) + 0.01 * chord;
    if (guide->length > 0.0) {
      const double mismatch = out->estimated_length - guide->length;
      if (std::abs(mismatch) > bound + 0.01 * guide->length) {
        out->warnings.push_back("scanned cable length (seen + bridged) differs from the nominal by " +
                                Mm(mismatch));
      }
      const double unseen_start = out->coverage.front().s_start;
      if (unseen_start > 0.1 * guide->length)
        out->warnings.push_back("first " + Mm(unseen_start) + " after the first clamp not seen");
    }
  }
  out->s_error_bound = bound;
  // Merge overlapping intervals (a stretch re-entering a traced region, e.g. at a loop).
  std::vector<ScanCoverageInterval> merged;
  for (const ScanCoverageInterval& c : out->coverage) {
    if (!merged.empty() && c.s_start <= merged.back().s_end) {
      merged.back().s_end = std::max(merged.back().s_end, c.s_end);
    } else {
      merged.push_back(c);
    }
  }
  out->coverage = merged;
}

}  // namespace cablefit::scan
