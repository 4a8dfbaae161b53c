#include "cablefit/core/solver/richardson.h"

#include <algorithm>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/solver/centerline_sampling.h"

namespace cablefit {
namespace {

// Ratio of the error of the extrapolated nodes to their change from the previous extrapolation,
// assuming only second-order convergence (2^2 - 1): see the header.
constexpr double kNodeErrorPerChange = 1.0 / 3.0;
// Ratio of the interpolation error at the finest spacing to that at twice the spacing,
// assuming only second order (a curvature jump): 1 / 2^2.
constexpr double kInterpolationErrorPerDoubling = 1.0 / 4.0;

bool Nested(const Polyline& fine, const Polyline& coarse) {
  return coarse.size() >= 2 && fine.size() == 2 * coarse.size() - 1;
}

// Every second node of `fine` (the coarser level's nodes).
Polyline EvenNodes(const Polyline& fine) {
  const int n = (fine.size() - 1) / 2 + 1;
  Polyline out;
  out.s.resize(n);
  out.points.resize(3, n);
  for (int k = 0; k < n; ++k) {
    out.s[k] = fine.s[2 * k];
    out.points.col(k) = fine.points.col(2 * k);
  }
  return out;
}

double MaxDistance(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  return a.cols() ? (a - b).colwise().norm().maxCoeff() : 0.0;
}

// Interpolation at twice the node spacing: how far the cubic through the even nodes misses
// the odd ones.
double InterpolationMiss(const Polyline& curve) {
  if (curve.size() < 3) return 0.0;
  const Polyline even = EvenNodes(curve);
  double worst = 0.0;
  Eigen::VectorXd odd_s((curve.size() - 1) / 2);
  for (int k = 0; k < odd_s.size(); ++k) odd_s[k] = curve.s[2 * k + 1];
  const Polyline at = SampleCenterline(even, odd_s);
  for (int k = 0; k < odd_s.size(); ++k)
    worst = std::max(worst, (at.points.col(k) - curve.points.col(2 * k + 1)).norm());
  return worst;
}

}  // namespace

void RichardsonLevels::Add(std::vector<Polyline> branches) {
  CABLEFIT_CHECK(levels_.empty() || branches.size() == levels_.back().size(),
                 "every level has the same branches");
  levels_.push_back(std::move(branches));
}

std::vector<Polyline> RichardsonLevels::Extrapolated(int level) const {
  CABLEFIT_CHECK(level >= 1 && level < levels(), "extrapolation needs a level and the one before");
  const std::vector<Polyline>& fine = levels_[level];
  const std::vector<Polyline>& coarse = levels_[level - 1];
  std::vector<Polyline> out = fine;
  for (size_t b = 0; b < fine.size(); ++b) {
    if (!Nested(fine[b], coarse[b])) continue;
    Polyline correction = coarse[b];
    const Polyline even = EvenNodes(fine[b]);
    correction.points = ExtrapolateRichardson(even.points, coarse[b].points) - even.points;
    out[b].points += SampleCenterline(correction, fine[b].s).points;
  }
  return out;
}

std::vector<Polyline> RichardsonLevels::Extrapolated() const {
  if (levels() == 0) return {};
  if (levels() == 1) return levels_[0];
  return Extrapolated(levels() - 1);
}

RichardsonError RichardsonLevels::EstimatedError() const {
  RichardsonError e;
  const int last = levels() - 1;
  if (last < 1) return e;
  const std::vector<Polyline> ext = Extrapolated(last);
  e.at_nodes = 0.0;
  e.between_nodes = 0.0;
  // Two levels: the finer level's own change, |P_h - P_2h| = 3 err(P_h).
  const bool two = last < 2;
  const std::vector<Polyline> before = two ? levels_[last - 1] : Extrapolated(last - 1);
  for (size_t b = 0; b < ext.size(); ++b) {
    const Polyline& fine = levels_[last][b];
    if (!Nested(fine, levels_[last - 1][b])) {
      e.at_nodes = e.between_nodes = std::numeric_limits<double>::infinity();
      return e;
    }
    const double change = MaxDistance(EvenNodes(two ? fine : ext[b]).points, before[b].points);
    e.at_nodes = std::max(e.at_nodes, change * kNodeErrorPerChange);
    e.between_nodes =
        std::max(e.between_nodes, InterpolationMiss(ext[b]) * kInterpolationErrorPerDoubling);
  }
  return e;
}

}  // namespace cablefit
