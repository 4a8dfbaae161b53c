#include "tube_pieces.h"

#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <algorithm>
#include <array>
#include <cmath>

namespace cablefit::internal {
namespace {

constexpr double kSameRadius = 0.01;
constexpr double kSamePoint = 0.05;

Eigen::Vector3d End(const RecoveredTube& t, int side) {
  return side == 0 ? Eigen::Vector3d(t.centres.col(0))
                   : Eigen::Vector3d(t.centres.col(t.centres.cols() - 1));
}

double Length(const Eigen::Matrix3Xd& centres) {  // 3 x n
  double length = 0;
  for (Eigen::Index k = 1; k < centres.cols(); ++k)
    length += (centres.col(k) - centres.col(k - 1)).norm();
  return length;
}

bool SameSize(const RecoveredTube& a, const RecoveredTube& b) {
  const auto same = [](double x, double y) {
    return std::abs(x - y) <= kSameRadius * std::max(x, y);
  };
  return same(a.radius, b.radius) && same(a.inner_radius, b.inner_radius);
}

}  // namespace

void JoinTubePieces(std::vector<TubePiece>* pieces) {
  const int n = static_cast<int>(pieces->size());
  if (n < 2) return;
  // link[i][side]: the (piece, side) that end meets, {-1, -1} where none or several do.
  std::vector<std::array<std::pair<int, int>, 2>> link(static_cast<size_t>(n),
                                                       {{{-1, -1}, {-1, -1}}});
  for (int i = 0; i < n; ++i) {
    const std::optional<RecoveredTube>& a = (*pieces)[static_cast<size_t>(i)].tube;
    if (!a || a->centres.cols() < 2) continue;
    for (int side = 0; side < 2; ++side) {
      std::vector<std::pair<int, int>> meeting;
      for (int j = 0; j < n; ++j) {
        const std::optional<RecoveredTube>& b = (*pieces)[static_cast<size_t>(j)].tube;
        if (j == i || !b || b->centres.cols() < 2) continue;
        for (int other = 0; other < 2; ++other)
          if ((End(*a, side) - End(*b, other)).norm() <= kSamePoint * a->radius)
            meeting.emplace_back(j, other);
      }
      if (meeting.size() == 1 &&
          SameSize(*a, *(*pieces)[static_cast<size_t>(meeting[0].first)].tube))
        link[static_cast<size_t>(i)][static_cast<size_t>(side)] = meeting[0];
    }
  }
  std::vector<char> done(static_cast<size_t>(n), 0);
  std::vector<TubePiece> out;
  for (int i = 0; i < n; ++i) {
    if (done[static_cast<size_t>(i)]) continue;
    // Walk back to a chain's free end (a closed chain has none: left as its pieces).
    int first = i, enter = 0;
    bool closed = false;
    for (int piece = i, from = 1, steps = 0;; ++steps) {
      const auto [prev, prev_side] =
          link[static_cast<size_t>(piece)][static_cast<size_t>(1 - from)];
      if (prev < 0) {
        first = piece;
        enter = 1 - from;
        break;
      }
      if (prev == i || steps > n) {
        closed = true;
        break;
      }
      piece = prev;
      from = prev_side;
    }
    if (closed || (link[static_cast<size_t>(first)][static_cast<size_t>(1 - enter)].first < 0)) {
      done[static_cast<size_t>(i)] = 1;
      out.push_back(std::move((*pieces)[static_cast<size_t>(i)]));
      continue;
    }
    std::vector<std::pair<int, bool>> chain;  // piece, walked from its start
    for (int piece = first, from = enter; piece >= 0 && !done[static_cast<size_t>(piece)];) {
      done[static_cast<size_t>(piece)] = 1;
      chain.emplace_back(piece, from == 0);
      const auto [next, next_side] =
          link[static_cast<size_t>(piece)][static_cast<size_t>(1 - from)];
      piece = next;
      from = next_side;
    }
    TubePiece joined = std::move((*pieces)[static_cast<size_t>(chain.front().first)]);
    TopoDS_Compound shapes;
    BRep_Builder builder;
    builder.MakeCompound(shapes);
    std::vector<Eigen::Vector3d> centres;
    double length = 0, radius = 0, residual2 = 0;
    RecoveredTube tube = *joined.tube;
    for (const auto& [p, forward] : chain) {
      TubePiece& piece = p == chain.front().first ? joined : (*pieces)[static_cast<size_t>(p)];
      builder.Add(shapes, piece.shape);
      const RecoveredTube& t = *piece.tube;
      const Eigen::Index m = t.centres.cols();
      for (Eigen::Index k = centres.empty() ? 0 : 1; k < m; ++k)
        centres.push_back(t.centres.col(forward ? k : m - 1 - k));
      const double l = Length(t.centres);
      length += l;
      radius += l * t.radius;
      residual2 += l * t.rms_residual * t.rms_residual;
      tube.min_section_radius = std::min(tube.min_section_radius, t.min_section_radius);
      tube.max_section_radius = std::max(tube.max_section_radius, t.max_section_radius);
    }
    tube.centres.resize(3, static_cast<Eigen::Index>(centres.size()));
    for (size_t k = 0; k < centres.size(); ++k)
      tube.centres.col(static_cast<Eigen::Index>(k)) = centres[k];
    if (length > 0) {
      tube.radius = radius / length;
      tube.rms_residual = std::sqrt(residual2 / length);
    }
    joined.shape = shapes;
    joined.tube = std::move(tube);
    out.push_back(std::move(joined));
  }
  *pieces = std::move(out);
}

}  // namespace cablefit::internal
