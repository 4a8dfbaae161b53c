#include "cablefit/core/network/clearance.h"

#include <algorithm>
#include <cmath>

#include "obstacle_distance.h"

namespace cablefit {

struct SolidClearance::Impl {
  explicit Impl(const TriangleMesh& mesh) : field({ObstacleSpec{"", mesh}}) {}
  ObstacleField field;
};

SolidClearance::SolidClearance(const TriangleMesh& mesh) : impl_(new Impl(mesh)) {}
SolidClearance::~SolidClearance() { delete impl_; }
SolidClearance::SolidClearance(SolidClearance&& o) noexcept : impl_(o.impl_) { o.impl_ = nullptr; }
SolidClearance& SolidClearance::operator=(SolidClearance&& o) noexcept {
  std::swap(impl_, o.impl_);
  return *this;
}

bool SolidClearance::empty() const { return impl_ == nullptr || impl_->field.empty(); }

ClearanceHit SolidClearance::ToTube(const Polyline& c, double radius, double s_from,
                                    double s_to) const {
  ClearanceHit best;
  if (empty()) return best;
  const double kEverywhere = std::numeric_limits<double>::infinity();
  for (int i = 0; i < c.size(); ++i) {
    if (c.s[i] < s_from || c.s[i] > s_to) continue;
    const Vec3 p = c.points.col(i);
    const ObstacleHit hit = impl_->field.Nearest(p, kEverywhere);
    if (hit.obstacle < 0) continue;
    const double clearance = hit.distance - radius;
    if (clearance < best.clearance) {
      best.clearance = clearance;
      best.s = c.s[i];
      best.point = p;
      best.other = hit.point;
    }
  }
  return best;
}

void ClosestSegmentParameters(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1,
                              double* s_out, double* t_out) {
  // Ericson (2005) sec. 5.1.9, ClosestPtSegmentSegment.
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr double kTiny = 1e-300;
  double s = 0, t = 0;
  if (a <= kTiny && e <= kTiny) {
    s = t = 0;
  } else if (a <= kTiny) {
    s = 0;
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kTiny) {
      t = 0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  *s_out = s;
  *t_out = t;
}

namespace {

// Runs of consecutive segments with their bounding box: a pair of runs farther apart than the
// best distance found so far cannot hold a closer pair of segments.
constexpr int kRun = 16;

struct Run {
  int begin, end;  // segments [begin, end): segment i joins samples i and i + 1
  Eigen::AlignedBox3d box;
};

std::vector<Run> Runs(const Polyline& c, double s_from, double s_to) {
  std::vector<Run> runs;
  for (int i = 0; i + 1 < c.size(); i += kRun) {
    Run r{i, std::min(i + kRun, c.size() - 1), {}};
    for (int k = r.begin; k <= r.end; ++k) r.box.extend(Vec3(c.points.col(k)));
    // Whole runs outside the kept arc-length range are dropped here, partial ones per segment.
    if (c.s[r.end] < s_from || c.s[r.begin] > s_to) continue;
    runs.push_back(r);
  }
  return runs;
}

}  // namespace

ClearanceHit TubeToTubeClearance(const Polyline& a, double ra, const TubeSkip& skip_a,
                                 const Polyline& b, double rb, const TubeSkip& skip_b) {
  ClearanceHit best;
  if (a.size() < 2 || b.size() < 2) return best;
  const double a_from = a.s[0] + skip_a.start, a_to = a.s[a.size() - 1] - skip_a.end;
  const double b_from = b.s[0] + skip_b.start, b_to = b.s[b.size() - 1] - skip_b.end;
  const std::vector<Run> ra_runs = Runs(a, a_from, a_to), rb_runs = Runs(b, b_from, b_to);
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const Run& x : ra_runs) {
    for (const Run& y : rb_runs) {
      const double gap = x.box.exteriorDistance(y.box);
      if (gap * gap > best_d2) continue;
      for (int i = x.begin; i < x.end; ++i) {
        for (int j = y.begin; j < y.end; ++j) {
          double u = 0, v = 0;
          ClosestSegmentParameters(a.points.col(i), a.points.col(i + 1), b.points.col(j),
                                   b.points.col(j + 1), &u, &v);
          const double sa = a.s[i] + u * (a.s[i + 1] - a.s[i]);
          const double sb = b.s[j] + v * (b.s[j + 1] - b.s[j]);
          // The closest point must lie in the kept part of both cables.
          if (sa < a_from || sa > a_to || sb < b_from || sb > b_to) continue;
          const Vec3 pa = a.points.col(i) + u * (a.points.col(i + 1) - a.points.col(i));
          const Vec3 pb = b.points.col(j) + v * (b.points.col(j + 1) - b.points.col(j));
          const double d2 = (pa - pb).squaredNorm();
          if (d2 < best_d2) {
            best_d2 = d2;
            best.s = sa;
            best.point = pa;
            best.other_s = sb;
            best.other = pb;
          }
        }
      }
    }
  }
  if (best_d2 < std::numeric_limits<double>::infinity())
    best.clearance = std::sqrt(best_d2) - ra - rb;
  return best;
}

TubeClearanceIndex::TubeClearanceIndex(std::vector<Tube> tubes) : tubes_(std::move(tubes)) {
  for (const Tube& t : tubes_) widest_ = std::max(widest_, t.radius);
  // Runs of consecutive segments are the tree's primitives: a harness's relaxed cables have a
  // million segments, and a tree over each of them cost more to walk than the pairs it spared.
  for (size_t t = 0; t < tubes_.size(); ++t) {
    const Polyline* c = tubes_[t].centreline;
    if (c == nullptr || c->size() < 2) continue;
    for (const Run& run : Runs(*c, c->s[0], c->s[c->size() - 1])) {
      runs_.push_back({static_cast<int>(t), run.begin, run.end});
      // Grown by the tube's radius: the gap to it bounds the clearance without assuming every
      // tube is as thick as a harness's trunk.
      Eigen::AlignedBox3d box = run.box;
      box.min().array() -= tubes_[t].radius;
      box.max().array() += tubes_[t].radius;
      boxes_.push_back(box);
    }
  }
  tree_ = BoxTree(boxes_, 4);
}

int TubeClearanceIndex::Nearest(int i, const PairSkip& skip, double* clearance) const {
  const Polyline& a = *tubes_[static_cast<size_t>(i)].centreline;
  const double ra = tubes_[static_cast<size_t>(i)].radius;
  int best_tube = -1;
  double best = std::numeric_limits<double>::infinity();
  if (a.size() >= 2) {
    // Tube i in runs of segments, each searched with the best of all runs so far.
    for (const Run& run : Runs(a, a.s[0], a.s[a.size() - 1])) {
      best = tree_.Nearest(
          // A lower bound of the surfaces' clearance: the gap between this run and the other
          // run's box grown by its radius, less this tube's radius; where they overlap, an
          // overlap as deep as the two tubes can be (with the widest tube for the other).
          [&](const Eigen::AlignedBox3d& box) {
            const double gap = box.exteriorDistance(run.box);
            return gap > 0 ? gap - ra : -ra - widest_;
          },
          [&](int k, double best_so_far) {
            const IndexedRun& other = runs_[static_cast<size_t>(k)];
            const int j = other.tube;
            if (j == i) return best_so_far;
            const Polyline& b = *tubes_[static_cast<size_t>(j)].centreline;
            const TubeSkip sa = skip(i, j), sb = skip(j, i);
            const double a_from = a.s[0] + sa.start, a_to = a.s[a.size() - 1] - sa.end;
            const double b_from = b.s[0] + sb.start, b_to = b.s[b.size() - 1] - sb.end;
            const double rb = tubes_[static_cast<size_t>(j)].radius;
            for (int seg = other.begin; seg < other.end; ++seg) {
              const double sb0 = b.s[seg], sb1 = b.s[seg + 1];
              // A segment wholly in the part left out (next to a shared end) has no point to give.
              if (sb1 < b_from || sb0 > b_to) continue;
              for (int s = run.begin; s < run.end; ++s) {
                if (a.s[s + 1] < a_from || a.s[s] > a_to) continue;
                double u = 0, v = 0;
                ClosestSegmentParameters(a.points.col(s), a.points.col(s + 1), b.points.col(seg),
                                         b.points.col(seg + 1), &u, &v);
                const double s_a = a.s[s] + u * (a.s[s + 1] - a.s[s]);
                const double s_b = sb0 + v * (sb1 - sb0);
                if (s_a < a_from || s_a > a_to || s_b < b_from || s_b > b_to) continue;
                const Vec3 pa = a.points.col(s) + u * (a.points.col(s + 1) - a.points.col(s));
                const Vec3 pb = b.points.col(seg) + v * (b.points.col(seg + 1) - b.points.col(seg));
                const double c = (pa - pb).norm() - ra - rb;
                if (c < best_so_far || (c == best_so_far && j < best_tube)) {
                  best_so_far = c;
                  best_tube = j;
                }
              }
            }
            return best_so_far;
          },
          best);
    }
  }
  if (clearance) *clearance = best;
  return best_tube;
}

std::vector<int> TubeClearanceIndex::Within(int i, double reach) const {
  const Polyline& a = *tubes_[static_cast<size_t>(i)].centreline;
  std::vector<int> out;
  if (a.size() < 2) return out;
  Eigen::AlignedBox3d whole;
  for (int k = 0; k < a.size(); ++k) whole.extend(Vec3(a.points.col(k)));
  const std::vector<Run> runs = Runs(a, a.s[0], a.s[a.size() - 1]);
  const double grow = tubes_[static_cast<size_t>(i)].radius + reach;  // boxes hold their radius
  auto near = [&](const Eigen::AlignedBox3d& box, const Eigen::AlignedBox3d& around) {
    return box.exteriorDistance(around) <= grow;
  };
  std::vector<char> seen(tubes_.size(), 0);
  tree_.ForEach([&](const Eigen::AlignedBox3d& box) { return near(box, whole); },
                [&](int k) {
                  const int j = runs_[static_cast<size_t>(k)].tube;
                  if (j == i || seen[static_cast<size_t>(j)]) return;
                  for (const Run& run : runs)
                    if (near(boxes_[static_cast<size_t>(k)], run.box)) {
                      seen[static_cast<size_t>(j)] = 1;
                      return;
                    }
                });
  for (size_t j = 0; j < seen.size(); ++j)
    if (seen[j]) out.push_back(static_cast<int>(j));
  return out;
}

}  // namespace cablefit
