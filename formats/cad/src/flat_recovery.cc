#include "flat_recovery.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepTools.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <vector>

#include <Eigen/Eigenvalues>

namespace cablefit {
namespace {

using Eigen::Vector3d;

// The strip's tessellation for the cuts: linear deflection over the square root of an end
// face's area, angular deflection [rad].
constexpr double kCutRelativeDeflection = 0.1;
constexpr double kCutAngularDeflection = 0.5;

struct EndFace {
  TopoDS_Face face;
  double area = 0.0;
  Vector3d centre = Vector3d::Zero();
  Vector3d outward = Vector3d::Zero();
};

// A planar outline: centre of its extent, its wide axis, width and thickness.
struct Outline {
  Vector3d centre = Vector3d::Zero();
  Vector3d wide_axis = Vector3d::Zero();
  double width = 0.0, thickness = 0.0;
};

// Extent of `points` (3 x n, lying in the plane of normal `normal`) along their principal axes.
// `weights` (n) weight the spread, so that densely sampled arcs do not tilt the axes.
std::optional<Outline> OutlineOf(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& weights,
                                 const Vector3d& normal) {
  if (points.cols() < 4 || !(weights.sum() > 0)) return std::nullopt;
  const Vector3d mean = points * weights / weights.sum();
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    Vector3d d = points.col(i) - mean;
    d -= d.dot(normal) * normal;
    cov += weights[i] * d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Vector3d u = eig.eigenvectors().col(2);
  u = (u - u.dot(normal) * normal).normalized();
  const Vector3d v = normal.cross(u).normalized();
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const Vector3d d = points.col(i) - mean;
    u0 = std::min(u0, d.dot(u));
    u1 = std::max(u1, d.dot(u));
    v0 = std::min(v0, d.dot(v));
    v1 = std::max(v1, d.dot(v));
  }
  Outline o;
  o.centre = mean + 0.5 * (u0 + u1) * u + 0.5 * (v0 + v1) * v;
  o.wide_axis = u;
  o.width = u1 - u0;
  o.thickness = v1 - v0;
  return o;
}

// The triangles of a tessellated shape, bucketed on a grid so a plane cut visits only those
// near the cut's expected centre. Each keeps its face and its corners' surface parameters, so a
// cut's points are put back on the exact surface: a chord of the tessellation sticks out of a
// twisted face (a saddle) or cuts into a bent one, by up to the deflection.
class TriangleSoup {
 public:
  TriangleSoup(const TopoDS_Shape& shape, double cell) : cell_(cell) {
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
      const TopoDS_Face& face = TopoDS::Face(ex.Current());
      TopLoc_Location loc;
      const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
      if (tri.IsNull()) continue;
      const bool has_uv = tri->HasUVNodes();
      const int face_id = static_cast<int>(surfaces_.size());
      surfaces_.emplace_back(face);
      const gp_Trsf trsf = loc.Transformation();
      for (int i = 1; i <= tri->NbTriangles(); ++i) {
        int a, b, c;
        tri->Triangle(i).Get(a, b, c);
        Triangle t;
        t.face = has_uv ? face_id : -1;
        int k = 0;
        for (int n : {a, b, c}) {
          const gp_Pnt p = tri->Node(n).Transformed(trsf);
          t.corners.col(k) = Vector3d(p.X(), p.Y(), p.Z());
          if (has_uv) t.uv.col(k) = Eigen::Vector2d(tri->UVNode(n).X(), tri->UVNode(n).Y());
          ++k;
        }
        const int id = static_cast<int>(triangles_.size());
        triangles_.push_back(t);
        const Eigen::Vector3i lo = Cell(t.corners.rowwise().minCoeff()),
                              hi = Cell(t.corners.rowwise().maxCoeff());
        for (int x = lo.x(); x <= hi.x(); ++x)
          for (int y = lo.y(); y <= hi.y(); ++y)
            for (int z = lo.z(); z <= hi.z(); ++z) grid_[Key({x, y, z})].push_back(id);
      }
    }
  }

  bool empty() const { return triangles_.empty(); }

  // The cut of the surface by the plane (point, normal) within `radius` of `point`: the
  // segment end points and, per point, half its segment's length as weight.
  void Cut(const Vector3d& point, const Vector3d& normal, double radius, Eigen::Matrix3Xd* points,
           Eigen::VectorXd* weights) const {
    std::vector<Vector3d> pts;
    std::vector<double> w;
    const Eigen::Vector3i lo = Cell(point.array() - radius), hi = Cell(point.array() + radius);
    std::vector<int> ids;
    for (int x = lo.x(); x <= hi.x(); ++x)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int z = lo.z(); z <= hi.z(); ++z)
          if (auto it = grid_.find(Key({x, y, z})); it != grid_.end())
            ids.insert(ids.end(), it->second.begin(), it->second.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (int id : ids) {
      const Triangle& tr = triangles_[static_cast<size_t>(id)];
      const Eigen::Matrix3d& t = tr.corners;
      const Eigen::RowVector3d d = normal.transpose() * (t.colwise() - point);
      Vector3d ends[2];
      Eigen::Vector2d uvs[2];
      int n = 0;
      for (int e = 0; e < 3 && n < 2; ++e) {
        const int f = (e + 1) % 3;
        if ((d[e] < 0) != (d[f] < 0)) {
          const double along = d[e] / (d[e] - d[f]);
          ends[n] = t.col(e) + along * (t.col(f) - t.col(e));
          uvs[n++] = tr.uv.col(e) + along * (tr.uv.col(f) - tr.uv.col(e));
        }
      }
      if (n < 2 || (0.5 * (ends[0] + ends[1]) - point).norm() > radius) continue;
      // The segment's ends and middle; a coarse tessellation's segments span up to the angular
      // deflection of a round edge, whose extreme the middle brings 4 times closer.
      Vector3d cut[3] = {ends[0], 0.5 * (ends[0] + ends[1]), ends[1]};
      if (tr.face >= 0) {
        // The surface point of the chord point's parameters, moved into the cut plane: off
        // the chord mostly along the surface normal, which is what the extent needs.
        const Eigen::Vector2d at[3] = {uvs[0], 0.5 * (uvs[0] + uvs[1]), uvs[1]};
        for (int k = 0; k < 3; ++k) {
          const gp_Pnt q = surfaces_[static_cast<size_t>(tr.face)].Value(at[k].x(), at[k].y());
          Vector3d on(q.X(), q.Y(), q.Z());
          on -= normal.dot(on - point) * normal;
          if ((on - cut[k]).norm() < kMaxSurfaceCorrection * radius) cut[k] = on;
        }
      }
      // Weights: the segment's length, half of it on the middle.
      const double quarter = 0.25 * (ends[1] - ends[0]).norm();
      for (int k = 0; k < 3; ++k) {
        pts.push_back(cut[k]);
        w.push_back(k == 1 ? 2 * quarter : quarter);
      }
    }
    points->resize(3, static_cast<Eigen::Index>(pts.size()));
    weights->resize(static_cast<Eigen::Index>(pts.size()));
    for (size_t i = 0; i < pts.size(); ++i) {
      points->col(static_cast<Eigen::Index>(i)) = pts[i];
      (*weights)[static_cast<Eigen::Index>(i)] = w[i];
    }
  }

 private:
  Eigen::Vector3i Cell(const Vector3d& p) const {
    return (p / cell_).array().floor().cast<int>();
  }
  static long long Key(const Eigen::Vector3i& c) {
    return (static_cast<long long>(c.x() & 0x1fffff) << 42) |
           (static_cast<long long>(c.y() & 0x1fffff) << 21) | static_cast<long long>(c.z() & 0x1fffff);
  }

  struct Triangle {
    Eigen::Matrix3d corners;                             // 3 x 3 [OCCT unit]
    Eigen::Matrix<double, 2, 3> uv = Eigen::Matrix<double, 2, 3>::Zero();  // surface parameters
    int face = -1;                                       // into surfaces_; -1 without parameters
  };
  // A surface point further off the chord than this fraction of the search radius is a
  // parameter the interpolation got wrong (across a seam), not a correction.
  static constexpr double kMaxSurfaceCorrection = 0.05;

  double cell_;
  std::vector<BRepAdaptor_Surface> surfaces_;  // per tessellated face
  std::vector<Triangle> triangles_;
  std::unordered_map<long long, std::vector<int>> grid_;
};

// The outline of a planar face from its tessellation's boundary-weighted vertices.
std::optional<Outline> FaceOutline(const EndFace& end, double deflection) {
  BRepMesh_IncrementalMesh(end.face, deflection, false, 0.2, false);
  TopLoc_Location loc;
  const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(end.face, loc);
  if (tri.IsNull()) return std::nullopt;
  Eigen::Matrix3Xd pts(3, tri->NbNodes());
  const gp_Trsf trsf = loc.Transformation();
  for (int i = 1; i <= tri->NbNodes(); ++i) {
    const gp_Pnt p = tri->Node(i).Transformed(trsf);
    pts.col(i - 1) = Vector3d(p.X(), p.Y(), p.Z());
  }
  return OutlineOf(pts, Eigen::VectorXd::Ones(pts.cols()), end.outward);
}

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

std::optional<RecoveredFlat> RecoverFlatStrip(const TopoDS_Shape& shape,
                                              const FlatRecoveryOptions& options) {
  try {
    // Planar faces first: their areas are cheap, a B-spline face's is an integration, so the
    // whole area is only asked of a shape whose end faces pass.
    std::vector<EndFace> planar;
    std::vector<TopoDS_Face> curved;
    double planar_area = 0.0;
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
      const TopoDS_Face face = TopoDS::Face(ex.Current());
      const BRepAdaptor_Surface surface(face);
      if (surface.GetType() != GeomAbs_Plane) {
        curved.push_back(face);
        continue;
      }
      GProp_GProps props;
      BRepGProp::SurfaceProperties(face, props);
      planar_area += props.Mass();
      const gp_Dir n = surface.Plane().Axis().Direction();
      EndFace end{face, props.Mass(), Vector3d::Zero(), Vector3d(n.X(), n.Y(), n.Z())};
      if (face.Orientation() == TopAbs_REVERSED) end.outward = -end.outward;
      const gp_Pnt c = props.CentreOfMass();
      end.centre = Vector3d(c.X(), c.Y(), c.Z());
      planar.push_back(end);
    }
    if (planar.size() < 2) return std::nullopt;
    std::sort(planar.begin(), planar.end(),
              [](const EndFace& a, const EndFace& b) { return a.area < b.area; });
    // The end faces are a pair of equal planar faces, usually the two smallest; but a strip bent
    // flatwise and edgewise in turn has short straight stretches whose flat sides are smaller
    // than its ends, so the next pairs up are tried too (a side fails the outline or the march).
    double curved_area = -1.0;  // summed once, when a pair first needs it
    const auto from_ends = [&](const EndFace& first, const EndFace& last) -> std::optional<RecoveredFlat> {
      if (!(first.area > 0) || last.area > 1.2 * first.area) return std::nullopt;
      // A shape that is no flat strip after all is tessellated again for what it is (a part,
      // for contact), not kept at this strip's fine deflection.
      struct Cleaner {
        const TopoDS_Shape& shape;
        bool keep = false;
        ~Cleaner() {
          if (!keep) BRepTools::Clean(shape);
        }
      } cleaner{shape};
      // Fine enough that the outline's extent is within a few per cent of the section.
      const double deflection = 0.02 * std::sqrt(first.area);
      const std::optional<Outline> start = FaceOutline(first, deflection);
      const std::optional<Outline> stop = FaceOutline(last, deflection);
      if (!start || !stop || !(start->thickness > 0) ||
          start->width < options.min_width_ratio * start->thickness ||
          std::abs(stop->width - start->width) > 0.1 * start->width ||
          std::abs(stop->thickness - start->thickness) > 0.1 * start->thickness)
        return std::nullopt;
      // A rectangle fills its extent, a stadium 1 - (1 - pi/4) t / w of it; a cross or an L less.
      // The outer outline only: bores of cores drawn inside a jacket do not count.
      GProp_GProps outer;
      BRepGProp::SurfaceProperties(BRepBuilderAPI_MakeFace(BRepTools::OuterWire(first.face), true).Face(),
                                   outer);
      const double fill = outer.Mass() / (start->width * start->thickness);
      const double stadium_fill = 1 - (1 - std::numbers::pi / 4) * start->thickness / start->width;
      if (fill > 1.02 || fill < stadium_fill - 0.03) return std::nullopt;
      if (curved_area < 0) {
        curved_area = 0;
        for (const TopoDS_Face& face : curved) {
          GProp_GProps props;
          BRepGProp::SurfaceProperties(face, props);
          curved_area += props.Mass();
        }
      }
      const double total_area = planar_area + curved_area;
      if (first.area + last.area > 0.2 * total_area) return std::nullopt;

      // The cuts' points are put back on the exact surfaces (TriangleSoup), so the strip's own
      // tessellation can be 5 times coarser and its angular step 2.5 times: half the reading
      // time of tests/data/flat/flat_cables.step, and more accurate (a 10 x 2 mm strip turned
      // half a turn in 0.3 m reads 10.001 x 2.006 mm; the finer chords alone gave 2.069).
      BRepMesh_IncrementalMesh(shape, kCutRelativeDeflection * std::sqrt(first.area), false,
                               kCutAngularDeflection, false);
      const TriangleSoup soup(shape, start->width);
      if (soup.empty()) return std::nullopt;
      const double step = std::max(options.sample_spacing, 0.25 * start->thickness);
      const double radius = 0.75 * start->width + step;
      // The strip's length is at most its lateral area over the thinnest outline's perimeter.
      const double max_length = total_area / (2 * start->thickness) + 2 * step;
      std::vector<Vector3d> centres{start->centre}, axes{start->wide_axis};
      std::vector<double> widths{start->width}, thicknesses{start->thickness};
      Vector3d tangent = -first.outward;
      double length = 0.0;
      Eigen::Matrix3Xd pts;
      Eigen::VectorXd w;
      while (true) {
        const Vector3d& c = centres.back();
        if ((last.centre - c).norm() < 1.5 * step && (last.centre - c).dot(-last.outward) < 0.5 * step)
          break;
        if (length > max_length) return std::nullopt;
        // Predict along the last tangent, then cut again square to the step actually taken.
        std::optional<Outline> cut;
        Vector3d along = tangent;
        for (int pass = 0; pass < 2; ++pass) {
          soup.Cut(c + step * along, along, radius, &pts, &w);
          cut = OutlineOf(pts, w, along);
          if (!cut) break;
          along = (cut->centre - c).normalized();
        }
        if (!cut) {
          // No cut past the centre: the strip ended here, and it must be at the far end face.
          if ((last.centre - c).norm() < 3 * step) break;
          return std::nullopt;
        }
        if (std::abs(cut->width - start->width) > 0.15 * start->width ||
            std::abs(cut->thickness - start->thickness) > 0.3 * start->thickness)
          return std::nullopt;
        tangent = along;
        length += (cut->centre - c).norm();
        Vector3d axis = cut->wide_axis;
        if (axis.dot(axes.back()) < 0) axis = -axis;
        centres.push_back(cut->centre);
        axes.push_back(axis);
        widths.push_back(cut->width);
        thicknesses.push_back(cut->thickness);
      }
      Vector3d end_axis = stop->wide_axis;
      if (end_axis.dot(axes.back()) < 0) end_axis = -end_axis;
      if ((last.centre - centres.back()).norm() > 1e-9 * start->width) {
        centres.push_back(stop->centre);
        axes.push_back(end_axis);
      } else {
        axes.back() = end_axis;
      }
      if (centres.size() < 3) return std::nullopt;
      RecoveredFlat flat;
      flat.centres.resize(3, static_cast<Eigen::Index>(centres.size()));
      flat.wide_axes.resize(3, static_cast<Eigen::Index>(centres.size()));
      for (size_t i = 0; i < centres.size(); ++i) {
        flat.centres.col(static_cast<Eigen::Index>(i)) = centres[i];
        flat.wide_axes.col(static_cast<Eigen::Index>(i)) = axes[i];
      }
      flat.width = Median(widths);
      flat.thickness = Median(thicknesses);
      flat.rounded_edges = fill < 0.95;
      cleaner.keep = true;
      return flat;
    };
    constexpr size_t kEndPairsTried = 4;
    for (size_t k = 0; k + 1 < planar.size() && k < kEndPairsTried; ++k) {
      if (std::optional<RecoveredFlat> flat = from_ends(planar[k], planar[k + 1])) return flat;
    }
    return std::nullopt;
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

}  // namespace cablefit
