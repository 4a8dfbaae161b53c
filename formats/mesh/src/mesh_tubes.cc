// RecoverTubes: per connected component, a mean-curvature-flow skeleton gives the topology and
// a first centreline; each route is then refined by cross-sections (the mesh cut by the plane
// normal to the route, a circle fitted to the cut), because the skeleton alone lies ~1.5 % of
// the diameter off the spine and stops short of the caps (docs/stack.md). The ends are carried
// out to the caps along the end tangents.
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/internal/tube_slices.h"
#include "cablefit/formats/mesh_file.h"
#include "concentric_layers.h"
#include "hollow_tubes.h"
#include "mcf_skeleton.h"
#include "skeleton_routes.h"
#include "vertex_weld.h"

namespace cablefit {
namespace {

// Lexicographic order of points with coordinates closer than `tolerance` [m] taken as equal:
// a route's direction and the order of a component's routes (their names) must not follow
// round-off, which differs between builds of the skeleton (an -O1 build named the branches of
// the branched-tubes sample the other way round).
bool CanonicalBefore(const Vec3& a, const Vec3& b, double tolerance) {
  for (int k = 0; k < 3; ++k) {
    if (a[k] < b[k] - tolerance) return true;
    if (a[k] > b[k] + tolerance) return false;
  }
  return false;
}

// A cross-section is a circle when its RMS residual is below this fraction of the radius; a
// faceted tube of 12 sides stays below it (its edges sag at most 3.4 % inside the circle), a
// square section does not (~8 %).
constexpr double kMaxSectionResidual = 0.05;
constexpr int kMinSectionPoints = 6;

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

struct Section {
  Vec3 centre;
  double radius = 0;
  double residual = 0;
  bool ok = false;
};

// Cuts the triangles by the plane through `p` normal to `t` (unit), keeps the cut points within
// `reach` of `p`, and fits a circle in the plane (Kasa's algebraic fit, then again without
// points off by more than 20 % of the radius).
// The faces near a point, from a uniform grid of cells `cell` wide: a cross-section looks at the
// faces within its reach only (a 60k-triangle tube spent most of its read time cutting every
// face at every station). A face is listed in every cell its bounding box touches.
class FaceGrid {
 public:
  FaceGrid(const TriangleMesh& mesh, double cell) : cell_(cell), stamp_(mesh.faces.cols(), -1) {
    for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) {
      Vec3 lo = mesh.vertices.col(mesh.faces(0, f)), hi = lo;
      for (int k = 1; k < 3; ++k) {
        lo = lo.cwiseMin(mesh.vertices.col(mesh.faces(k, f)));
        hi = hi.cwiseMax(mesh.vertices.col(mesh.faces(k, f)));
      }
      const Key a = KeyOf(lo), b = KeyOf(hi);
      for (std::int64_t x = a[0]; x <= b[0]; ++x)
        for (std::int64_t y = a[1]; y <= b[1]; ++y)
          for (std::int64_t z = a[2]; z <= b[2]; ++z) cells_[{x, y, z}].push_back(static_cast<int>(f));
    }
  }
  // Faces with a cell within `reach` of `p`, each once, in ascending order (so the fit sees the
  // same points in the same order whatever the grid).
  std::vector<int> Near(const Vec3& p, double reach) {
    ++query_;
    std::vector<int> faces;
    const Key a = KeyOf(p - Vec3::Constant(reach)), b = KeyOf(p + Vec3::Constant(reach));
    for (std::int64_t x = a[0]; x <= b[0]; ++x)
      for (std::int64_t y = a[1]; y <= b[1]; ++y)
        for (std::int64_t z = a[2]; z <= b[2]; ++z) {
          const auto it = cells_.find({x, y, z});
          if (it == cells_.end()) continue;
          for (int f : it->second) {
            if (stamp_[static_cast<size_t>(f)] == query_) continue;
            stamp_[static_cast<size_t>(f)] = query_;
            faces.push_back(f);
          }
        }
    std::sort(faces.begin(), faces.end());
    return faces;
  }

 private:
  using Key = std::array<std::int64_t, 3>;
  Key KeyOf(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / cell_)),
            static_cast<std::int64_t>(std::floor(p.y() / cell_)),
            static_cast<std::int64_t>(std::floor(p.z() / cell_))};
  }
  double cell_;
  std::map<Key, std::vector<int>> cells_;
  std::vector<std::int64_t> stamp_;
  std::int64_t query_ = 0;
};

Section CrossSection(const TriangleMesh& mesh, FaceGrid& grid, const Vec3& p, const Vec3& t,
                     double reach) {
  const Vec3 e1 = t.unitOrthogonal(), e2 = t.cross(e1);
  std::vector<Eigen::Vector2d> cut;
  for (const int f : grid.Near(p, reach)) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.vertices.col(mesh.faces(k, f));
      const Vec3 b = mesh.vertices.col(mesh.faces((k + 1) % 3, f));
      const double da = (a - p).dot(t), db = (b - p).dot(t);
      // Each edge is cut once from each of its two faces; the duplicates weigh every point
      // equally, so they do not bias the fit.
      if ((da < 0) == (db < 0) || da == db) continue;
      const Vec3 x = a + (b - a) * (da / (da - db));
      if ((x - p).norm() > reach) continue;
      cut.emplace_back((x - p).dot(e1), (x - p).dot(e2));
    }
  }
  Section s;
  std::vector<bool> keep(cut.size(), true);
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  double r = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const int m = static_cast<int>(std::count(keep.begin(), keep.end(), true));
    if (m < kMinSectionPoints) return s;
    Eigen::MatrixX3d a(m, 3);
    Eigen::VectorXd b(m);
    for (size_t i = 0, row = 0; i < cut.size(); ++i) {
      if (!keep[i]) continue;
      a.row(static_cast<Eigen::Index>(row)) << 2 * cut[i].x(), 2 * cut[i].y(), 1.0;
      b(static_cast<Eigen::Index>(row++)) = cut[i].squaredNorm();
    }
    const Eigen::Vector3d abc = a.colPivHouseholderQr().solve(b);
    const double r2 = abc(2) + abc.head<2>().squaredNorm();
    if (!(r2 > 0)) return s;
    c = abc.head<2>();
    r = std::sqrt(r2);
    for (size_t i = 0; i < cut.size(); ++i) keep[i] = std::abs((cut[i] - c).norm() - r) < 0.2 * r;
  }
  double sum = 0;
  int m = 0;
  for (size_t i = 0; i < cut.size(); ++i) {
    if (!keep[i]) continue;
    const double d = (cut[i] - c).norm() - r;
    sum += d * d;
    ++m;
  }
  if (m < kMinSectionPoints) return s;
  s.centre = p + c.x() * e1 + c.y() * e2;
  s.radius = r;
  s.residual = std::sqrt(sum / m);
  s.ok = s.residual < kMaxSectionResidual * r;
  return s;
}

// Points at equal arc-length steps along a polyline (3 x n).
std::vector<Vec3> Resample(const std::vector<Vec3>& pts, double step) {
  std::vector<double> s(pts.size(), 0.0);
  for (size_t i = 1; i < pts.size(); ++i) s[i] = s[i - 1] + (pts[i] - pts[i - 1]).norm();
  const int n = std::max(2, static_cast<int>(std::ceil(s.back() / step)) + 1);
  std::vector<Vec3> out;
  size_t j = 0;
  for (int k = 0; k < n; ++k) {
    const double target = s.back() * k / (n - 1);
    while (j + 2 < pts.size() && s[j + 1] < target) ++j;
    const double span = s[j + 1] - s[j];
    const double w = span > 0 ? std::clamp((target - s[j]) / span, 0.0, 1.0) : 0.0;
    out.push_back((1 - w) * pts[j] + w * pts[j + 1]);
  }
  return out;
}

// A tube's route never turns back on itself from one station to the next (a cable bends over
// radii, not about a point). Where a skeleton folds (at a step in the tube's radius, where a
// core's insulation ends, it can leave an overlapping Z, and the route then doubles back by a
// few millimetres), the points behind the route's progress are dropped.
std::vector<Vec3> WithoutFoldBacks(const std::vector<Vec3>& pts) {
  std::vector<Vec3> out;
  for (const Vec3& p : pts) {
    if (!out.empty() && !((p - out.back()).norm() > 0)) continue;
    if (out.size() >= 2 && !((p - out.back()).dot(out.back() - out[out.size() - 2]) > 0)) continue;
    out.push_back(p);
  }
  return out.size() >= 2 ? out : pts;  // a route of one point stays as it was (no tube)
}

// Unit tangents by chords over about `window` either side (the skeleton zig-zags locally).
std::vector<Vec3> Tangents(const std::vector<Vec3>& pts, double step, double window) {
  const int n = static_cast<int>(pts.size());
  const int w = std::max(1, static_cast<int>(std::round(window / step)));
  std::vector<Vec3> t(n);
  for (int i = 0; i < n; ++i) {
    t[i] = (pts[std::min(i + w, n - 1)] - pts[std::max(i - w, 0)]).normalized();
  }
  return t;
}

// A tube's end: its point and, where the end is a flat cap, the cap's outward normal.
struct TubeEnd {
  Vec3 point;
  std::optional<Vec3> normal;
};

// The end of a tube beyond `end` in direction `out` (unit): the area centroid of the cap, i.e. of
// the faces near the end that face along `out` (the centre of a flat disc cap, even if `out` is
// a few degrees off), and their area-weighted normal: the cable's axis there, exact however
// coarse the tessellation, where the route's last slices are not (their cuts reach into the
// cap). Without such faces (a rounded or ragged end), the point as far along `out` as the mesh
// reaches within 1.5 radii of the axis, and no normal.
TubeEnd CapEnd(const TriangleMesh& mesh, const Vec3& end, const Vec3& out, double radius) {
  Vec3 weighted = Vec3::Zero(), normal = Vec3::Zero();
  double area = 0, reach = 0;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) {
    const Vec3 a = mesh.vertices.col(mesh.faces(0, f)), b = mesh.vertices.col(mesh.faces(1, f)),
               c = mesh.vertices.col(mesh.faces(2, f));
    for (const Vec3& v : {a, b, c}) {
      const Vec3 d = v - end;
      const double along = d.dot(out);
      if (along > 0 && along < 4 * radius && (d - along * out).norm() < 1.5 * radius) {
        reach = std::max(reach, along);
      }
    }
    const Vec3 centroid = (a + b + c) / 3, d = centroid - end;
    const double along = d.dot(out);
    if (along < -radius || along > 4 * radius || (d - along * out).norm() > 1.2 * radius) continue;
    const Vec3 n = (b - a).cross(c - a);  // |n| = 2 * area
    if (n.norm() <= 0 || n.normalized().dot(out) < 0.9) continue;
    weighted += 0.5 * n.norm() * centroid;
    normal += 0.5 * n;
    area += 0.5 * n.norm();
  }
  if (area > 0.5 * M_PI * radius * radius) {
    // A flat cap: its faces' normals agree (a domed or stepped end's do not, and its centroid
    // normal would be no axis).
    const double flatness = normal.norm() / area;
    if (flatness > 1.0 - 1e-6) return {weighted / area, normal.normalized()};
    return {weighted / area, std::nullopt};
  }
  return {end + reach * out, std::nullopt};
}

// Puts the end of `pts` (its front when `front`; points about half a radius apart) on the cap
// `cap`. Where the cap is flat, the last three radii become a cubic Hermite arc from the route
// there to the cap's centre along the cap's normal: the slices near a cap reach into it, and a
// coarse tessellation's slice centres scatter enough that a tangent taken from them is off by
// milliradians, which a clamp there would turn into millimetres of sag.
void EndAtCap(const TubeEnd& cap, double radius, bool front, std::vector<Vec3>* pts) {
  if (front) std::reverse(pts->begin(), pts->end());
  if (cap.normal) {
    const Vec3 n = *cap.normal;
    while (pts->size() > 3 && (cap.point - pts->back()).dot(n) < 3.0 * radius) pts->pop_back();
    const size_t k = pts->size() - 1;
    const Vec3 p0 = (*pts)[k];
    const double chord = (cap.point - p0).norm();
    Vec3 t0 = ((*pts)[k] - (*pts)[k - 2]).normalized();
    if (!(t0.dot(n) > 0.5)) t0 = n;  // no usable direction inside: the cap's
    const int m = std::max(2, static_cast<int>(std::ceil(chord / (0.5 * radius))));
    for (int i = 1; i < m; ++i) {
      const double u = static_cast<double>(i) / m, u2 = u * u, u3 = u2 * u;
      pts->push_back((2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * chord * t0 +
                     (-2 * u3 + 3 * u2) * cap.point + (u3 - u2) * chord * n);
    }
  }
  pts->push_back(cap.point);
  if (front) std::reverse(pts->begin(), pts->end());
}

// Every edge shared by exactly two faces (the skeleton helper says the same, later and dearer).
bool IsClosedSurface(const TriangleMesh& mesh) {
  std::vector<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces(k, f), b = mesh.faces((k + 1) % 3, f);
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2) return false;
    i = j;
  }
  return !edges.empty();
}

// A solid whose area lies almost all on a few planes (a box, a plate, a bracket bent from sheet)
// has no circular sections: said without the skeleton, which costs seconds on such a shape
// (remeshed to 15k triangles, a flow with no axis to contract to). A 12-sided tube, the
// coarsest the section test accepts, spreads its area over 14 directions.
constexpr int kFlatDirections = 8;
constexpr double kFlatShare = 0.9;
constexpr double kSameDirection = 0.996;  // cos 5 degrees
bool MostlyOnFewPlanes(const TriangleMesh& mesh) {
  struct Direction {
    Vec3 normal;
    double area;
  };
  std::vector<std::pair<double, Vec3>> faces;
  double total = 0;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) {
    const Vec3 a = mesh.vertices.col(mesh.faces(0, f)), b = mesh.vertices.col(mesh.faces(1, f)),
               c = mesh.vertices.col(mesh.faces(2, f));
    const Vec3 n = (b - a).cross(c - a);
    if (!(n.norm() > 0)) continue;
    faces.push_back({0.5 * n.norm(), n.normalized()});
    total += 0.5 * n.norm();
  }
  std::stable_sort(faces.begin(), faces.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<Direction> directions;
  for (const auto& [area, normal] : faces) {
    auto it = std::find_if(directions.begin(), directions.end(),
                           [&](const Direction& d) { return d.normal.dot(normal) > kSameDirection; });
    if (it != directions.end()) {
      it->area += area;
      continue;
    }
    if (directions.size() >= 64) return false;  // curved: many directions
    directions.push_back({normal, area});
  }
  std::sort(directions.begin(), directions.end(),
            [](const Direction& x, const Direction& y) { return x.area > y.area; });
  double top = 0;
  for (size_t k = 0; k < directions.size() && k < kFlatDirections; ++k) top += directions[k].area;
  return total > 0 && top >= kFlatShare * total;
}

std::vector<MeshTube> TubesOfComponent(const TriangleMesh& mesh, int component) {
  if (!IsClosedSurface(mesh)) throw InvalidInput("the mesh is not a closed surface");
  if (MostlyOnFewPlanes(mesh)) {
    throw InvalidInput("component " + std::to_string(component) +
                       " is not a tube (flat faces: a box, plate or bracket)");
  }
  const CurveSkeleton skeleton = ComputeMcfSkeletonInHelper(mesh, SkeletonSecondsFor(mesh));
  // A first radius from the skeleton's correspondences: the median vertex-to-node distance.
  std::vector<double> distances;
  for (size_t n = 0; n < skeleton.vertex_points.size(); ++n) {
    for (const Vec3& q : skeleton.vertex_points[n]) {
      distances.push_back((q - skeleton.nodes.col(static_cast<Eigen::Index>(n))).norm());
    }
  }
  const double r0 = Median(distances);
  if (!(r0 > 0)) throw InvalidInput("component " + std::to_string(component) + " is not a tube (no skeleton)");
  const std::vector<SkeletonRoute> routes = SplitSkeleton(skeleton, 3 * r0);
  FaceGrid grid(mesh, 2 * r0);
  std::vector<MeshTube> tubes;
  for (const SkeletonRoute& route : routes) {
    std::vector<Vec3> pts;
    for (int n : route.nodes) pts.push_back(skeleton.nodes.col(n));
    const bool closed = route.nodes.front() == route.nodes.back();
    const double step = 0.5 * r0;
    for (int pass = 0; pass < 2; ++pass) {  // pass 2 re-cuts normal to the refined route
      std::vector<Vec3> stations = Resample(WithoutFoldBacks(pts), step);
      const std::vector<Vec3> tangents = Tangents(stations, step, 2 * r0);
      std::vector<Vec3> refined;
      std::vector<Section> sections;
      std::vector<char> circular;
      for (size_t i = 0; i < stations.size(); ++i) {
        const Section s = CrossSection(mesh, grid, stations[i], tangents[i], 2 * r0);
        if (s.ok) sections.push_back(s);
        // Near a branch point the cut is no circle: keep the skeleton's point there.
        refined.push_back(s.ok ? s.centre : stations[i]);
        circular.push_back(s.ok ? 1 : 0);
      }
      const double ok_fraction = static_cast<double>(sections.size()) / stations.size();
      if (ok_fraction < 0.6 || closed) {
        throw InvalidInput("component " + std::to_string(component) +
                           " is not a tube (cross-sections are not circles, or it is closed)");
      }
      pts = refined;
      if (pass == 1) {
        std::vector<double> radii, residuals;
        for (const Section& s : sections) {
          radii.push_back(s.radius);
          residuals.push_back(s.residual * s.residual);
        }
        double radius = Median(radii);
        // The cuts go through the facets, inside the surface, and a coarse tessellation's facets
        // wander about the axis: the vertices lie on the surface itself. Known-radius fits to
        // the vertices in a slab about each centre (the scan tracer's slice fit) put the route
        // on the axis, and their free radii give the tube's radius.
        {
          Eigen::Matrix3Xd centres(3, static_cast<Eigen::Index>(pts.size()));
          for (size_t i = 0; i < pts.size(); ++i) centres.col(static_cast<Eigen::Index>(i)) = pts[i];
          const internal::TubeSlices slices = internal::FitTubeSlices(mesh.vertices, radius, radius, &centres);
          // Where the cut was no circle (a branch point, where the branches' routes meet at
          // the skeleton's point) the route stays as it was.
          for (size_t i = 0; i < pts.size(); ++i)
            if (circular[i]) pts[i] = centres.col(static_cast<Eigen::Index>(i));
          if (slices.radius > 0) radius = slices.radius;
        }
        pts = WithoutFoldBacks(pts);
        const int n = static_cast<int>(pts.size());
        // Carry free ends out to the caps, where the skeleton stops short.
        std::optional<Vec3> front_out, back_out;  // a flat cap's outward normal at each end
        if (route.start_is_end) {
          const Vec3 out = (pts[0] - pts[std::min(4, n - 1)]).normalized();
          const TubeEnd cap = CapEnd(mesh, pts[0], out, radius);
          front_out = cap.normal;
          EndAtCap(cap, radius, /*front=*/true, &pts);
        }
        if (route.finish_is_end) {
          const int m = static_cast<int>(pts.size());
          const Vec3 out = (pts[m - 1] - pts[std::max(0, m - 5)]).normalized();
          const TubeEnd cap = CapEnd(mesh, pts[m - 1], out, radius);
          back_out = cap.normal;
          EndAtCap(cap, radius, /*front=*/false, &pts);
        }
        MeshTube tube;
        tube.component = component;
        tube.diameter = 2 * radius;
        tube.fit_error = std::sqrt(std::accumulate(residuals.begin(), residuals.end(), 0.0) /
                                   static_cast<double>(residuals.size()));
        if (CanonicalBefore(pts.back(), pts.front(), 0.1 * r0)) {
          std::reverse(pts.begin(), pts.end());
          std::swap(front_out, back_out);
        }
        if (front_out) tube.start_direction = -*front_out;
        if (back_out) tube.end_direction = *back_out;
        tube.centreline.points.resize(3, static_cast<Eigen::Index>(pts.size()));
        for (size_t i = 0; i < pts.size(); ++i) tube.centreline.points.col(static_cast<Eigen::Index>(i)) = pts[i];
        tube.centreline.ParameteriseByChords(0.0);
        if (route.start_is_end && route.finish_is_end &&
            tube.centreline.ChordLength() < 2 * tube.diameter) {
          throw InvalidInput("component " + std::to_string(component) +
                             " is not a tube (shorter than two diameters)");
        }
        tubes.push_back(std::move(tube));
      }
    }
  }
  if (tubes.empty()) throw InvalidInput("component " + std::to_string(component) + " is not a tube");
  // Named in this order (<name>#k): by where they start, not by the skeleton's node numbering.
  std::stable_sort(tubes.begin(), tubes.end(), [&](const MeshTube& a, const MeshTube& b) {
    const Vec3 a0 = a.centreline.points.col(0), b0 = b.centreline.points.col(0);
    if (CanonicalBefore(a0, b0, 0.1 * r0)) return true;
    if (CanonicalBefore(b0, a0, 0.1 * r0)) return false;
    return CanonicalBefore(a.centreline.points.rightCols<1>(), b.centreline.points.rightCols<1>(),
                           0.1 * r0);
  });
  return tubes;
}

// A hollow tube: its outer wall and its bore, each capped and read as a solid tube, must be
// one coaxial tube each, the bore inside the wall.
std::optional<MeshTube> HollowTube(const TriangleMesh& mesh, int component) {
  if (internal::EulerCharacteristic(mesh) != 0) return std::nullopt;
  std::vector<MeshTube> walls;
  for (const TriangleMesh& wall : internal::CappedWalls(mesh)) {
    try {
      std::vector<MeshTube> tubes = TubesOfComponent(wall, component);
      if (tubes.size() != 1) return std::nullopt;
      walls.push_back(std::move(tubes.front()));
    } catch (const InvalidInput&) {
      return std::nullopt;
    }
  }
  if (walls.size() != 2) return std::nullopt;
  if (walls[0].diameter < walls[1].diameter) std::swap(walls[0], walls[1]);
  MeshTube& outer = walls[0];
  const MeshTube& bore = walls[1];
  const double radius = 0.5 * outer.diameter;
  for (int i = 0; i < bore.centreline.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < outer.centreline.size(); ++j)
      nearest = std::min(nearest, (bore.centreline.points.col(i) - outer.centreline.points.col(j)).norm());
    if (nearest > 0.25 * radius + outer.centreline.ChordLength() / outer.centreline.size())
      return std::nullopt;
  }
  if (!(bore.diameter < 0.98 * outer.diameter)) return std::nullopt;
  outer.inner_diameter = bore.diameter;
  return std::move(outer);
}

// The volume a closed surface bounds, negative when its faces point inwards (a bore drawn as a
// closed surface of its own, facing the hollow it bounds).
double SignedVolume(const TriangleMesh& mesh) {
  double six_v = 0;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f)
    six_v += mesh.vertices.col(mesh.faces(0, f))
                 .dot(mesh.vertices.col(mesh.faces(1, f)).cross(mesh.vertices.col(mesh.faces(2, f))));
  return six_v / 6;
}

// Whether every point of `inner`'s centreline lies within a quarter of `outer`'s radius of
// `outer`'s centreline (plus its sampling chord): the two run along one axis.
bool Coaxial(const MeshTube& inner, const MeshTube& outer) {
  const double chord = outer.centreline.ChordLength() / std::max(1, outer.centreline.size());
  for (int i = 0; i < inner.centreline.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < outer.centreline.size(); ++j)
      nearest = std::min(nearest, (inner.centreline.points.col(i) - outer.centreline.points.col(j)).norm());
    if (nearest > 0.25 * 0.5 * outer.diameter + chord) return false;
  }
  return true;
}

// Component `component` of `diameter` [m] drawn inside `outer` around its axis: its layer. A
// surface facing inwards bounds the hollow (the bore of a hose drawn as two shells); a layer that
// fits the bore fills it.
void AddLayer(double diameter, int component, bool cavity, MeshTube* outer) {
  if (cavity) {
    if (outer->inner_diameter == 0) outer->inner_diameter = diameter;
    return;
  }
  outer->layers.push_back(diameter);
  outer->layer_components.push_back(component);
  if (outer->inner_diameter > 0 && diameter >= 0.9 * outer->inner_diameter)
    outer->inner_diameter = 0;
}

// A cable drawn as concentric closed surfaces (a coax: conductor, dielectric, jacket, each a
// shell of its own) is one cable of the outer diameter: each tube lying along the axis of a
// wider one of another component, within it, is that tube's layer. Its bore, if it has one,
// is filled by the layer that fits it; an inner surface facing inwards is its bore.
void MergeConcentricLayers(std::vector<MeshTube>* tubes, const std::vector<char>& cavity) {
  std::vector<size_t> order(tubes->size());
  std::iota(order.begin(), order.end(), 0);
  // Widest first, so that every layer goes to the outermost tube around it.
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return (*tubes)[a].diameter > (*tubes)[b].diameter; });
  std::vector<char> absorbed(tubes->size(), 0);
  for (size_t oi = 0; oi < order.size(); ++oi) {
    MeshTube& outer = (*tubes)[order[oi]];
    if (absorbed[order[oi]]) continue;
    for (size_t ii = oi + 1; ii < order.size(); ++ii) {
      const MeshTube& inner = (*tubes)[order[ii]];
      if (absorbed[order[ii]] || inner.component == outer.component ||
          !(inner.diameter < 0.98 * outer.diameter) || !Coaxial(inner, outer))
        continue;
      absorbed[order[ii]] = 1;
      AddLayer(inner.diameter, inner.component, cavity[static_cast<size_t>(inner.component)],
               &outer);
      for (size_t k = 0; k < inner.layers.size(); ++k) {
        outer.layers.push_back(inner.layers[k]);
        outer.layer_components.push_back(inner.layer_components[k]);
      }
    }
  }
  std::vector<MeshTube> kept;
  for (size_t k = 0; k < tubes->size(); ++k)
    if (!absorbed[k]) kept.push_back(std::move((*tubes)[k]));
  *tubes = std::move(kept);
}

}  // namespace

// Solids exported together that touch along a surface (a coax's conductor, dielectric and
// jacket as three solids, each meshed on its own) leave that surface twice, once facing each
// way; welded, its edges have four faces and nothing is a closed surface. The doubled faces are
// the inside of one body: without them the layers are the one closed surface around them all.
TriangleMesh WithoutDoubledFaces(const TriangleMesh& mesh) {
  std::map<std::array<int, 3>, int> count;
  const auto key = [&](Eigen::Index f) {
    std::array<int, 3> k = {mesh.faces(0, f), mesh.faces(1, f), mesh.faces(2, f)};
    std::sort(k.begin(), k.end());
    return k;
  };
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) ++count[key(f)];
  std::vector<Eigen::Index> kept;
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f)
    if (count[key(f)] % 2 == 1) kept.push_back(f);
  if (kept.size() == static_cast<size_t>(mesh.faces.cols())) return mesh;
  TriangleMesh out;
  out.vertices = mesh.vertices;
  out.faces.resize(3, static_cast<Eigen::Index>(kept.size()));
  for (size_t i = 0; i < kept.size(); ++i) out.faces.col(static_cast<Eigen::Index>(i)) = mesh.faces.col(kept[i]);
  return out;
}

MeshContents RecoverMeshContents(const TriangleMesh& mesh, double min_aspect) {
  // Touching solids meshed one by one: where their tessellations of the surface they share agree
  // (every face doubled), they are the one closed surface around them all; where they do not, each
  // is its own closed surface, and ConnectedComponents tells them apart at their common rims.
  const TriangleMesh welded = internal::WeldNearVertices(mesh);
  TriangleMesh around = WithoutDoubledFaces(welded);
  if (!IsClosedSurface(around)) around = welded;
  const std::vector<TriangleMesh> components = ConnectedComponents(around);
  std::vector<char> cavity(components.size());
  for (size_t c = 0; c < components.size(); ++c) cavity[c] = SignedVolume(components[c]) < 0;
  // Per component: its tubes, or the part it is. The widest first, so that a layer drawn inside
  // a tube already read is known as one without a skeleton of its own.
  std::vector<std::vector<MeshTube>> tubes_of(components.size());
  std::vector<std::optional<MeshPart>> part_of(components.size());
  std::vector<size_t> order(components.size());
  std::iota(order.begin(), order.end(), 0);
  const auto size_of = [&](size_t c) {
    const TriangleMesh& m = components[c];
    return (m.vertices.rowwise().maxCoeff() - m.vertices.rowwise().minCoeff()).norm();
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return size_of(a) > size_of(b); });
  for (const size_t c : order) {
    const int component = static_cast<int>(c);
    bool layer = false;
    for (const size_t h : order) {
      for (MeshTube& host : tubes_of[h]) {
        const std::optional<double> diameter =
            internal::ConcentricLayerDiameter(components[c], host);
        if (!diameter || !(*diameter < 0.98 * host.diameter)) continue;
        AddLayer(*diameter, component, cavity[c], &host);
        layer = true;
        break;
      }
      if (layer) break;
    }
    if (layer) continue;
    // A surface with a hole through it (a hose, a conduit): its own skeleton is a loop through the
    // wall, no route; its walls are read instead, without the skeleton it would cost first.
    if (internal::EulerCharacteristic(components[c]) == 0 && IsClosedSurface(components[c])) {
      if (std::optional<MeshTube> hollow = HollowTube(components[c], component);
          hollow && hollow->centreline.ChordLength() >= min_aspect * hollow->diameter) {
        tubes_of[c].push_back(std::move(*hollow));
        continue;
      }
    }
    try {
      std::vector<MeshTube> more = TubesOfComponent(components[c], component);
      if (more.size() == 1) {
        const double length = more.front().centreline.ChordLength();
        const double diameter = more.front().diameter;
        if (length < min_aspect * diameter) {
          char why[160];
          std::snprintf(why, sizeof why,
                        " is a short stout solid (%.3g mm long, %.3g mm across, under %g "
                        "diameters): a part, not a cable",
                        1e3 * length, 1e3 * diameter, min_aspect);
          part_of[c] =
              MeshPart{component, components[c], "component " + std::to_string(component) + why,
                       more.front().centreline, diameter};
          continue;
        }
      }
      tubes_of[c] = std::move(more);
    } catch (const InvalidInput& e) {
      if (std::optional<MeshTube> hollow = HollowTube(components[c], component);
          hollow && hollow->centreline.ChordLength() >= min_aspect * hollow->diameter) {
        tubes_of[c].push_back(std::move(*hollow));
      } else {
        part_of[c] = MeshPart{component, components[c], e.what(), {}, 0.0};
      }
    }
  }
  MeshContents out;
  for (size_t c = 0; c < components.size(); ++c) {
    for (MeshTube& t : tubes_of[c]) out.tubes.push_back(std::move(t));
    if (part_of[c]) out.parts.push_back(std::move(*part_of[c]));
  }
  MergeConcentricLayers(&out.tubes, cavity);
  return out;
}

std::vector<MeshTube> RecoverTubes(const TriangleMesh& mesh) {
  MeshContents contents = RecoverMeshContents(mesh, 0.0);
  if (!contents.parts.empty()) throw InvalidInput(contents.parts.front().reason);
  return std::move(contents.tubes);
}

}  // namespace cablefit
