#include "diagnose/harness_scan_split.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cablefit/core/base/box_tree.h"
#include "cablefit/formats/scan_centerline_extractor.h"
#include "diagnose/diagnose_observation.h"

namespace cablefit::addin {
namespace {

// Distance of p to polyline c through a tree of its segments.
class SegmentIndex {
 public:
  explicit SegmentIndex(const Polyline& c) : c_(c) {
    std::vector<Eigen::AlignedBox3d> boxes;
    for (int i = 0; i + 1 < c.size(); ++i) {
      Eigen::AlignedBox3d b(Vec3(c.points.col(i)));
      b.extend(Vec3(c.points.col(i + 1)));
      boxes.push_back(b);
    }
    tree_ = BoxTree(boxes, 8);
  }
  // Distance [m] and arc length of the nearest point.
  double Distance(const Vec3& p, double* s = nullptr) const {
    double best_s = 0.0;
    const double d = tree_.Nearest(
        [&](const Eigen::AlignedBox3d& box) { return box.exteriorDistance(p); },
        [&](int i, double best) {
          const Vec3 a = c_.points.col(i), ab = c_.points.col(i + 1) - a;
          const double w = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
          const double di = (a + w * ab - p).norm();
          if (di < best) {
            best_s = c_.s[i] + w * (c_.s[i + 1] - c_.s[i]);
            return di;
          }
          return best;
        },
        std::numeric_limits<double>::infinity());
    if (s) *s = best_s;
    return d;
  }

 private:
  const Polyline& c_;
  BoxTree tree_;
};

// Where each junction is on the shapes: the end of a branch attached to it.
std::vector<Vec3> JunctionPositions(const NetworkSpec& spec, const std::vector<Polyline>& shapes) {
  std::vector<Vec3> out(spec.junctions.size(), Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (size_t b = 0; b < spec.branches.size(); ++b) {
    const Polyline& c = shapes[b];
    if (spec.branches[b].start_junction >= 0) out[static_cast<size_t>(spec.branches[b].start_junction)] = c.points.col(0);
    if (spec.branches[b].end_junction >= 0)
      out[static_cast<size_t>(spec.branches[b].end_junction)] = c.points.col(c.size() - 1);
  }
  return out;
}

}  // namespace

HarnessScanSplit SplitHarnessScan(const PointCloud& scan, const NetworkSpec& spec,
                                  const std::vector<Polyline>& shapes) {
  const size_t nb = spec.branches.size();
  std::vector<SegmentIndex> index;
  index.reserve(nb);
  double widest = 0.0;
  for (size_t b = 0; b < nb; ++b) {
    index.emplace_back(shapes[b]);
    widest = std::max(widest, spec.branches[b].material.diameter);
  }
  const std::vector<Vec3> junctions = JunctionPositions(spec, shapes);
  HarnessScanSplit out;
  out.branches.resize(nb);
  std::vector<std::vector<int>> members(nb);
  for (int i = 0; i < scan.size(); ++i) {
    const Vec3 p = scan.points.col(i);
    bool near_junction = false;
    for (const Vec3& j : junctions) near_junction = near_junction || (p - j).norm() < 1.5 * widest;
    if (near_junction) {
      ++out.left_out;
      continue;
    }
    int best = -1;
    double best_gap = std::numeric_limits<double>::infinity();
    for (size_t b = 0; b < nb; ++b) {
      const double gap = std::abs(index[b].Distance(p) - 0.5 * spec.branches[b].material.diameter);
      if (gap < best_gap) {
        best_gap = gap;
        best = static_cast<int>(b);
      }
    }
    members[static_cast<size_t>(best)].push_back(i);
  }
  for (size_t b = 0; b < nb; ++b) {
    PointCloud& c = out.branches[b];
    c.points.resize(3, static_cast<Eigen::Index>(members[b].size()));
    for (size_t k = 0; k < members[b].size(); ++k) c.points.col(static_cast<Eigen::Index>(k)) = scan.points.col(members[b][k]);
  }
  return out;
}

HarnessObservation ObserveHarnessScan(const HarnessScanSplit& split, const NetworkSpec& spec,
                                      const std::vector<Polyline>& shapes,
                                      std::vector<std::string>* problems) {
  HarnessObservation obs;
  for (size_t b = 0; b < spec.branches.size(); ++b) {
    const BranchSpec& br = spec.branches[b];
    const Polyline& shape = shapes[b];
    ShapeObservation o;
    try {
      ScanCenterlineOptions so;
      so.diameter = br.material.diameter;
      ScanGuide guide;
      const int n = shape.size();
      guide.start_position = shape.points.col(0);
      guide.start_tangent = shape.points.col(1) - shape.points.col(0);
      guide.end_position = shape.points.col(n - 1);
      guide.end_tangent = shape.points.col(n - 1) - shape.points.col(n - 2);
      guide.length = shape.s[n - 1] - shape.s[0];
      const ScanCenterline sc = ExtractScanCenterline(split.branches[b], so, guide);
      o = ObservationFromScan(sc);
      // Arc lengths along the branch as the fits parameterise it.
      const SegmentIndex along(shape);
      for (Eigen::Index i = 0; i < o.points.cols(); ++i) along.Distance(o.points.col(i), &o.s[i]);
    } catch (const std::exception& e) {
      if (problems) problems->push_back(br.name + ": no centre line traced from its " +
                                        std::to_string(split.branches[b].size()) + " scan points (" + e.what() + ")");
      o = ShapeObservation{};
      o.points.resize(3, 0);
    }
    obs.branches.push_back(o);
  }
  return obs;
}

}  // namespace cablefit::addin
