#include "curve_pieces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>

#include "curve_routes.h"

namespace cablefit::internal {
namespace {

struct End {
  int cable = 0;
  int side = 0;  // 0 = start (s = 0), 1 = finish
  Vec3 point;
};

using Cell = std::array<std::int64_t, 3>;

Cell CellOf(const Vec3& p, double size) {
  return {static_cast<std::int64_t>(std::floor(p.x() / size)),
          static_cast<std::int64_t>(std::floor(p.y() / size)),
          static_cast<std::int64_t>(std::floor(p.z() / size))};
}

// Appends `piece` (walked forwards or backwards) to `out`, leaving out its first point when it
// repeats the last one there.
void Append(const Eigen::Matrix3Xd& piece, bool forward, std::vector<Vec3>* out) {
  const Eigen::Index n = piece.cols();
  for (Eigen::Index k = 0; k < n; ++k) {
    const Vec3 p = piece.col(forward ? k : n - 1 - k);
    if (k == 0 && !out->empty()) continue;  // the shared end point
    out->push_back(p);
  }
}

}  // namespace

std::vector<int> JoinCurvePieces(HarnessDrawing* drawing, double tolerance) {
  std::vector<DrawnCable>& cables = drawing->cables;
  const int nc = static_cast<int>(cables.size());
  // Every cable end, grouped with the ends within `tolerance` of it.
  std::vector<End> ends;
  for (int c = 0; c < nc; ++c) {
    const Eigen::Matrix3Xd& p = cables[c].centreline.points;
    if (p.cols() < 2) continue;
    ends.push_back({c, 0, p.col(0)});
    ends.push_back({c, 1, p.col(p.cols() - 1)});
  }
  const double cell = std::max(tolerance, 1e-12);
  std::map<Cell, std::vector<int>> grid;
  for (size_t e = 0; e < ends.size(); ++e) grid[CellOf(ends[e].point, cell)].push_back(static_cast<int>(e));
  // link[c][side]: the (cable, side) that end is joined to, or {-1, -1}.
  std::vector<std::array<std::pair<int, int>, 2>> link(nc, {{{-1, -1}, {-1, -1}}});
  for (size_t e = 0; e < ends.size(); ++e) {
    const Cell c0 = CellOf(ends[e].point, cell);
    std::vector<int> near;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({c0[0] + dx, c0[1] + dy, c0[2] + dz});
          if (it == grid.end()) continue;
          for (int f : it->second)
            if (static_cast<size_t>(f) != e && (ends[f].point - ends[e].point).norm() <= tolerance)
              near.push_back(f);
        }
    if (near.size() != 1) continue;  // a free end, or a branch point of three or more
    const End& a = ends[e];
    const End& b = ends[near[0]];
    if (a.cable == b.cable) continue;
    const DrawnCable &ca = cables[a.cable], &cb = cables[b.cable];
    if (ca.source != CableSourceKind::kCurve || cb.source != CableSourceKind::kCurve ||
        ca.name != cb.name || ca.diameter > 0 || cb.diameter > 0)
      continue;
    link[a.cable][a.side] = {b.cable, b.side};
  }
  // A link must be mutual (each end sees only the other).
  for (int c = 0; c < nc; ++c)
    for (int side = 0; side < 2; ++side) {
      const auto [d, dside] = link[c][side];
      if (d >= 0 && link[d][dside] != std::make_pair(c, side)) link[c][side] = {-1, -1};
    }
  std::vector<char> done(nc, 0);
  std::vector<DrawnCable> out;
  std::vector<int> new_index(nc, -1);
  for (int c = 0; c < nc; ++c) {
    if (done[c]) continue;
    // The pieces linked to c; a chain starts at a piece with a free side, a loop at its
    // lowest-numbered piece.
    std::vector<int> group = {c};
    std::vector<char> in_group(nc, 0);
    in_group[c] = 1;
    for (size_t k = 0; k < group.size(); ++k)
      for (int side = 0; side < 2; ++side)
        if (const int d = link[group[k]][side].first; d >= 0 && !in_group[d]) {
          in_group[d] = 1;
          group.push_back(d);
        }
    std::sort(group.begin(), group.end());
    int first = group.front(), enter = 0;
    for (int p : group) {
      if (link[p][0].first < 0 || link[p][1].first < 0) {
        first = p;
        enter = link[p][0].first < 0 ? 0 : 1;
        break;
      }
    }
    const bool closed = link[first][enter].first >= 0;
    std::vector<std::pair<int, bool>> chain;  // piece, walked forwards
    for (int piece = first, from = enter; piece >= 0 && !done[piece];) {
      done[piece] = 1;
      chain.push_back({piece, from == 0});
      const auto [next, next_side] = link[piece][1 - from];
      piece = next;
      from = next_side;
    }
    if (chain.size() == 1) {
      new_index[c] = static_cast<int>(out.size());
      out.push_back(std::move(cables[c]));
      continue;
    }
    std::vector<Vec3> points;
    double fit_error = 0.0;
    for (const auto& [p, forward] : chain) {
      Append(cables[p].centreline.points, forward, &points);
      fit_error = std::max(fit_error, cables[p].fit_error);
    }
    DrawnCable joined = cables[chain.front().first];
    if (closed) points.back() = points.front();
    joined.centreline.points.resize(3, static_cast<Eigen::Index>(points.size()));
    for (size_t k = 0; k < points.size(); ++k)
      joined.centreline.points.col(static_cast<Eigen::Index>(k)) = points[k];
    joined.centreline.ParameteriseByChords(0.0);
    joined.fit_error = fit_error;
    if (closed && IsClosedPlanar(joined.centreline.points)) {
      drawing->skipped.push_back("'" + (joined.name.empty() ? std::string("unnamed") : joined.name) +
                                 "': a closed planar curve (a sketch profile) of " +
                                 std::to_string(chain.size()) + " pieces, not a cable route");
      continue;
    }
    new_index[chain.front().first] = static_cast<int>(out.size());
    out.push_back(std::move(joined));
  }
  cables = std::move(out);
  return new_index;
}

}  // namespace cablefit::internal
