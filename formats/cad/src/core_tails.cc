#include "core_tails.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

namespace cablefit::internal {
namespace {

// Slack on "inside the end section", as a fraction of the cable's radius (or half thickness):
// tessellated end faces and a core touching the jacket's inner wall are within it.
constexpr double kSectionSlack = 0.1;
// A round cable's cores are at most this fraction of its diameter (two side by side and the
// jacket); a tube as thick as the cable at its end continues the route (a splice).
constexpr double kRoundCoreFraction = 0.6;

struct CableEnd {
  Vec3 point, out;  // end centre [m], unit tangent pointing away from the cable
  Vec3 wide;        // a flat cable's wide axis there (unit), zero for a round one
};

CableEnd EndOf(const DrawnCable& cable, bool at_start) {
  const Eigen::Matrix3Xd& p = cable.centreline.points;
  const Eigen::Index n = p.cols();
  // The tangent over a few samples: the last segment alone can be a sliver.
  const Eigen::Index k = std::min<Eigen::Index>(3, n - 1);
  CableEnd end;
  end.point = at_start ? p.col(0) : p.col(n - 1);
  const Vec3 inner = at_start ? p.col(k) : p.col(n - 1 - k);
  end.out = (end.point - inner).normalized();
  end.wide = Vec3::Zero();
  if (cable.flat && cable.flat->wide_axes.cols() == n) {
    const Vec3 u = cable.flat->wide_axes.col(at_start ? 0 : n - 1);
    end.wide = (u - u.dot(end.out) * end.out).normalized();
  }
  return end;
}

// Whether `root` (a tube end centre) lies in the cable's section at `end`: within its outline
// across, and no farther beyond the end face than the slack (it may start deeper inside).
bool InEndSection(const DrawnCable& cable, const CableEnd& end, const Vec3& root,
                  double tube_radius) {
  const Vec3 d = root - end.point;
  const double along = d.dot(end.out);
  const Vec3 across = d - along * end.out;
  if (cable.flat) {
    const double half_t = 0.5 * cable.flat->thickness, half_w = 0.5 * cable.flat->width;
    if (along > kSectionSlack * half_t) return false;
    const Vec3 v = end.out.cross(end.wide);
    return std::abs(across.dot(end.wide)) <= half_w - tube_radius + kSectionSlack * half_t &&
           std::abs(across.dot(v)) <= half_t - tube_radius + kSectionSlack * half_t;
  }
  const double radius = 0.5 * cable.diameter;
  return along <= kSectionSlack * radius &&
         across.norm() <= radius - tube_radius + kSectionSlack * radius;
}

const std::string& NameOf(const DrawnTube& tube, const HarnessDrawing& drawing) {
  return tube.is_cable ? drawing.cables[static_cast<size_t>(tube.index)].name
                       : drawing.solids[static_cast<size_t>(tube.index)].name;
}

// How many cables other than `tube` itself have an end within `tolerance` of `p`.
int CableEndsAt(const std::vector<DrawnCable>& cables, const Vec3& p, double tolerance,
                const DrawnTube& tube) {
  int count = 0;
  for (size_t c = 0; c < cables.size(); ++c) {
    const Eigen::Matrix3Xd& q = cables[c].centreline.points;
    if (q.cols() < 2 || (tube.is_cable && static_cast<size_t>(tube.index) == c)) continue;
    count += (q.col(0) - p).norm() <= tolerance || (q.col(q.cols() - 1) - p).norm() <= tolerance;
  }
  return count;
}

// Whether a cable other than `tube` ends at `tip` without also ending at `root`: a cable that
// spans the same stretch is the tube drawn once more (a core's route curve beside its sweep).
bool OtherCableEndsAt(const std::vector<DrawnCable>& cables, const Vec3& tip, const Vec3& root,
                      double tolerance, const DrawnTube& tube) {
  for (size_t c = 0; c < cables.size(); ++c) {
    const Eigen::Matrix3Xd& q = cables[c].centreline.points;
    if (q.cols() < 2 || (tube.is_cable && static_cast<size_t>(tube.index) == c)) continue;
    const Vec3 a = q.col(0), b = q.col(q.cols() - 1);
    const bool at_tip = (a - tip).norm() <= tolerance || (b - tip).norm() <= tolerance;
    const bool at_root = (a - root).norm() <= tolerance || (b - root).norm() <= tolerance;
    if (at_tip && !at_root) return true;
  }
  return false;
}

double ChainLength(const Eigen::Matrix3Xd& points) {
  double length = 0;
  for (Eigen::Index i = 1; i < points.cols(); ++i) length += (points.col(i) - points.col(i - 1)).norm();
  return length;
}

// A cable drawn as a bare route curve has no section to start a tail in. Its stripped cores
// are then told by how they are drawn: short curves (under half of it) that leave its end
// square to its end face, side by side in that face (several, at distinct points, parallel to
// its end tangent). The branches of a breakout start at one point instead, and a splice
// continues one route with one curve.
constexpr double kParallel = 0.985;  // cos 10 degrees

std::vector<size_t> BareCurveTails(const std::vector<DrawnTube>& candidates,
                                   const DrawnCable& parent, size_t parent_index,
                                   const CableEnd& end, const AbsorbedTubes& absorbed) {
  const double parent_length = ChainLength(parent.centreline.points);
  std::vector<size_t> tails;
  std::vector<Vec3> roots;
  for (size_t k = 0; k < candidates.size(); ++k) {
    const DrawnTube& t = candidates[k];
    if (absorbed.Marked(t) || (t.is_cable && static_cast<size_t>(t.index) == parent_index)) continue;
    const double length = ChainLength(t.centres);
    if (!(length < 0.5 * parent_length) || t.centres.cols() < 2) continue;
    for (const bool root_first : {true, false}) {
      const Eigen::Index n = t.centres.cols();
      const Vec3 root = t.centres.col(root_first ? 0 : n - 1);
      const Vec3 next = t.centres.col(root_first ? std::min<Eigen::Index>(3, n - 1)
                                                 : std::max<Eigen::Index>(n - 4, 0));
      const Vec3 d = root - end.point;
      const double along = d.dot(end.out);
      if (std::abs(along) > 0.05 * length || (d - along * end.out).norm() > 0.5 * length) continue;
      if ((next - root).normalized().dot(end.out) < kParallel) continue;
      tails.push_back(k);
      roots.push_back(root);
      break;
    }
  }
  if (tails.size() < 2) return {};
  for (size_t i = 0; i < roots.size(); ++i)
    for (size_t j = i + 1; j < roots.size(); ++j)
      if ((roots[i] - roots[j]).norm() < 1e-3 * parent_length) return {};
  return tails;
}

std::string TailLine(const DrawnTube& tube, const std::string& name, const std::string& cable) {
  char size[32] = "";
  if (tube.radius > 0) std::snprintf(size, sizeof size, "%.4g mm ", 2e3 * tube.radius);
  char line[240];
  std::snprintf(line, sizeof line,
                "'%s': a %s%s %.4g mm long out of the end of cable '%s' (a stripped core end): "
                "part of that cable, not a separate one",
                name.empty() ? "unnamed" : name.c_str(), size,
                tube.inner_radius > 0 ? "sleeve" : "core", 1e3 * ChainLength(tube.centres),
                cable.c_str());
  return line;
}

}  // namespace

void MergeCoreTails(const std::vector<DrawnTube>& tubes, double min_aspect,
                    double junction_tolerance, HarnessDrawing* drawing, AbsorbedTubes* absorbed) {
  const std::vector<DrawnCable>& cables = drawing->cables;
  // Candidates: the recovered tubes (cables or parts), then the cables that are no tube solid
  // (a core's route curve with its sweeps merged into it, or a bare curve).
  std::vector<DrawnTube> candidates;
  for (const DrawnTube& tube : tubes)
    if (tube.centres.cols() >= 2) candidates.push_back(tube);
  for (size_t c = 0; c < cables.size(); ++c) {
    if (cables[c].shape || cables[c].centreline.size() < 2) continue;
    DrawnTube curve;
    curve.is_cable = true;
    curve.index = static_cast<int>(c);
    curve.centres = cables[c].centreline.points;
    curve.radius = 0.5 * cables[c].diameter;
    curve.inner_radius = 0.5 * cables[c].inner_diameter;
    candidates.push_back(std::move(curve));
  }
  // Each candidate's cable and end, if it is a tail of one.
  struct Tail {
    size_t candidate = 0, cable = 0;
    bool at_start = true;
  };
  std::vector<Tail> found;
  for (size_t k = 0; k < candidates.size(); ++k) {
    const DrawnTube& tube = candidates[k];
    // A cable is a candidate as its tube and as a curve: once.
    const bool seen = std::any_of(found.begin(), found.end(), [&](const Tail& t) {
      const DrawnTube& o = candidates[t.candidate];
      return o.is_cable == tube.is_cable && o.index == tube.index;
    });
    if (absorbed->Marked(tube) || seen) continue;
    const double length = ChainLength(tube.centres);
    const Vec3 first = tube.centres.col(0), last = tube.centres.col(tube.centres.cols() - 1);
    for (size_t c = 0; c < cables.size(); ++c) {
      const DrawnCable& cable = cables[c];
      if (absorbed->CableMarked(c) || !(cable.diameter > 0) || cable.centreline.size() < 2) continue;
      if (tube.is_cable && static_cast<size_t>(tube.index) == c) continue;
      // A core fits the flat jacket's thickness, or beside another core in a round one.
      const double widest = cable.flat ? cable.flat->thickness * (1 + kSectionSlack)
                                       : kRoundCoreFraction * cable.diameter;
      if (!(2 * tube.radius <= widest)) continue;
      if (!(length < min_aspect * cable.diameter)) continue;
      // Shorter than the cable it would belong to: two tails side by side are not each other's.
      if (!(length < ChainLength(cable.centreline.points))) continue;
      std::optional<bool> tail_at_start;
      for (const bool at_start : {true, false}) {
        const CableEnd end = EndOf(cable, at_start);
        for (const bool root_first : {true, false}) {
          const Vec3& root = root_first ? first : last;
          const Vec3& tip = root_first ? last : first;
          // It runs out of the cable: its far end is clear of the end face by its diameter (a
          // tail may bend sideways right after the jacket), and free: a thinner tube whose far
          // end meets another cable's is a segment of a network (a bundle thinning at a splice
          // and running on to the next node), not a core end.
          if (InEndSection(cable, end, root, tube.radius) &&
              (tip - end.point).dot(end.out) > std::max(2 * tube.radius, 0.1 * length) &&
              CableEndsAt(cables, root, junction_tolerance, tube) < 2 &&
              !OtherCableEndsAt(cables, tip, root, junction_tolerance, tube))
            tail_at_start = at_start;
        }
      }
      if (!tail_at_start) continue;
      found.push_back({k, c, *tail_at_start});
      break;
    }
  }
  // A lone thin tube at a cable's end that is slender on its own is a cable continuing it as a
  // thinner one (a harness's leaf segment beyond a splice); alone and short, it is a wire's bare
  // conductor end, and beside other tails, a multi-core cable's stripped cores however long.
  for (const Tail& t : found) {
    const DrawnTube& tube = candidates[t.candidate];
    const int beside = static_cast<int>(std::count_if(found.begin(), found.end(), [&](const Tail& o) {
      return o.cable == t.cable && o.at_start == t.at_start;
    }));
    if (beside == 1 && ChainLength(tube.centres) >= min_aspect * 2 * tube.radius) continue;
    absorbed->Mark(tube, TailLine(tube, NameOf(tube, *drawing), cables[t.cable].name), drawing,
                   static_cast<int>(t.cable));
  }
  for (size_t c = 0; c < cables.size(); ++c) {
    const DrawnCable& parent = cables[c];
    if (absorbed->CableMarked(c) || parent.diameter > 0 || parent.shape || parent.centreline.size() < 2)
      continue;
    for (const bool at_start : {true, false}) {
      for (const size_t k : BareCurveTails(candidates, parent, c, EndOf(parent, at_start), *absorbed)) {
        const DrawnTube& tube = candidates[k];
        absorbed->Mark(tube, TailLine(tube, NameOf(tube, *drawing), parent.name), drawing,
                       static_cast<int>(c));
      }
    }
  }
}

}  // namespace cablefit::internal

namespace cablefit {

void AbsorbCoreTails(const std::vector<TubeSolid>& tube_solids, double min_aspect,
                     double junction_tolerance, HarnessDrawing* drawing) {
  // The cables themselves are candidates already (they have no CAD shape); the parts that are
  // short tubes join them.
  std::vector<internal::DrawnTube> tubes;
  for (const TubeSolid& solid : tube_solids) {
    internal::DrawnTube tube;
    tube.is_cable = false;
    tube.index = solid.solid;
    tube.skipped_note = solid.skipped_note;
    tube.centres = solid.centres;
    tube.radius = solid.radius;
    tubes.push_back(std::move(tube));
  }
  internal::AbsorbedTubes absorbed(*drawing);
  internal::MergeCoreTails(tubes, min_aspect, junction_tolerance, drawing, &absorbed);
  absorbed.RemoveFrom(drawing);
}

}  // namespace cablefit
