#include "loose_faces.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>
#include <algorithm>
#include <numeric>
#include <optional>

#include "tube_recovery.h"

namespace cablefit::internal {
namespace {

std::vector<TopoDS_Shape> SewFaces(const std::vector<TopoDS_Shape>& faces) {
  std::vector<TopoDS_Shape> bodies;
  if (faces.empty()) return bodies;
  if (faces.size() == 1) return faces;
  BRepBuilderAPI_Sewing sewing(0.01);  // [OCCT unit = mm]
  for (const TopoDS_Shape& f : faces) sewing.Add(f);
  sewing.Perform();
  const TopoDS_Shape sewn = sewing.SewedShape();
  if (sewn.IsNull()) return faces;
  for (TopExp_Explorer ex(sewn, TopAbs_SHELL); ex.More(); ex.Next()) bodies.push_back(ex.Current());
  for (TopExp_Explorer ex(sewn, TopAbs_FACE, TopAbs_SHELL); ex.More(); ex.Next()) {
    bodies.push_back(ex.Current());
  }
  return bodies;
}

// Relative tolerances of the regrouping, as fractions of a wall's radius: the sections at the
// ends of two faces of one tube meet within the accuracy of a circle fit to an approximated
// surface (a few thousandths), different tubes of a bundle are two radii apart.
constexpr double kSameRadius = 0.01;
constexpr double kSamePoint = 0.05;
// An inner wall over the same stretch as an outer one: its ends within this of the outer's.
constexpr double kSameStretch = 0.1;

struct Wall {
  TubeFaceEnds ends;
  double area = 0.0;
};

// A planar face: the centroid of its area and its vertices [OCCT unit].
struct Plane {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> vertices;
};

struct Face {
  TopoDS_Shape shape;
  int style = 0;
  std::optional<Wall> wall;    // a tube's lateral face
  std::optional<Plane> plane;  // a planar face
  double area = 0.0;
};

Face MakeFace(const TopoDS_Shape& shape, int style) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(shape, props);
  Face face{shape, style, std::nullopt, std::nullopt, props.Mass()};
  const TopoDS_Face& f = TopoDS::Face(shape);
  if (BRepAdaptor_Surface(f).GetType() == GeomAbs_Plane) {
    Plane plane;
    const gp_Pnt c = props.CentreOfMass();
    plane.centroid = Eigen::Vector3d(c.X(), c.Y(), c.Z());
    for (TopExp_Explorer ex(f, TopAbs_VERTEX); ex.More(); ex.Next()) {
      const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(ex.Current()));
      plane.vertices.emplace_back(p.X(), p.Y(), p.Z());
    }
    face.plane = std::move(plane);
  } else if (const std::optional<TubeFaceEnds> ends = LateralFaceEnds(f)) {
    face.wall = Wall{*ends, face.area};
  }
  return face;
}

// Whether `plane` closes the end of a wall of `radius` at `centre`: its area's centroid there and
// no point of its boundary farther out than the wall (a disc, or an annulus around a bore).
bool IsCapAt(const Plane& plane, const Eigen::Vector3d& centre, double radius) {
  if ((plane.centroid - centre).norm() > kSamePoint * radius) return false;
  return std::all_of(plane.vertices.begin(), plane.vertices.end(), [&](const Eigen::Vector3d& p) {
    return (p - centre).norm() <= (1 + kSamePoint) * radius;
  });
}

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(static_cast<size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int Find(int i) {
    while (parent_[static_cast<size_t>(i)] != i) {
      parent_[static_cast<size_t>(i)] =
          parent_[static_cast<size_t>(parent_[static_cast<size_t>(i)])];
      i = parent_[static_cast<size_t>(i)];
    }
    return i;
  }
  void Join(int a, int b) { parent_[static_cast<size_t>(Find(a))] = Find(b); }

 private:
  std::vector<int> parent_;
};

bool Near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tolerance) {
  return (a - b).norm() <= tolerance;
}

// Groups the walls (indices into `faces`) into tubes and adds the caps: returns the group of
// each face, -1 for faces of no tube.
std::vector<int> TubeGroups(const std::vector<Face>& faces) {
  const int n = static_cast<int>(faces.size());
  std::vector<int> walls;
  for (int i = 0; i < n; ++i)
    if (faces[static_cast<size_t>(i)].wall) walls.push_back(i);
  const auto wall = [&](int i) -> const TubeFaceEnds& {
    return faces[static_cast<size_t>(i)].wall->ends;
  };
  const auto same_radius = [&](int i, int j) {
    return std::abs(wall(i).radius - wall(j).radius) <=
           kSameRadius * std::max(wall(i).radius, wall(j).radius);
  };
  UnionFind groups(n);
  // Halves and other repeats of one stretch; inner and outer walls of one stretch.
  for (size_t a = 0; a < walls.size(); ++a)
    for (size_t b = a + 1; b < walls.size(); ++b) {
      const TubeFaceEnds &p = wall(walls[a]), &q = wall(walls[b]);
      const double outer = std::max(p.radius, q.radius);
      const double tol = (same_radius(walls[a], walls[b]) ? kSamePoint : kSameStretch) * outer;
      if ((Near(p.start, q.start, tol) && Near(p.end, q.end, tol)) ||
          (Near(p.start, q.end, tol) && Near(p.end, q.start, tol)))
        groups.Join(walls[a], walls[b]);
    }
  // Stretches of one radius that continue one another where no third stretch ends.
  std::vector<std::pair<int, int>> continuations;
  for (const int i : walls) {
    for (const Eigen::Vector3d* end : {&wall(i).start, &wall(i).end}) {
      std::vector<int> meeting;  // groups of the walls of this radius ending here
      for (const int j : walls) {
        if (!same_radius(i, j)) continue;
        const double tol = kSamePoint * wall(j).radius;
        if (!Near(*end, wall(j).start, tol) && !Near(*end, wall(j).end, tol)) continue;
        const int g = groups.Find(j);
        if (std::find(meeting.begin(), meeting.end(), g) == meeting.end()) meeting.push_back(g);
      }
      if (meeting.size() == 2) continuations.emplace_back(meeting[0], meeting[1]);
    }
  }
  for (const auto& [a, b] : continuations) groups.Join(a, b);
  std::vector<int> group_of(static_cast<size_t>(n), -1);
  for (const int i : walls) group_of[static_cast<size_t>(i)] = groups.Find(i);
  // Caps: planar faces centred on a wall's end.
  for (int i = 0; i < n; ++i) {
    const Face& f = faces[static_cast<size_t>(i)];
    if (!f.plane) continue;
    for (const int j : walls) {
      if (IsCapAt(*f.plane, wall(j).start, wall(j).radius) ||
          IsCapAt(*f.plane, wall(j).end, wall(j).radius)) {
        group_of[static_cast<size_t>(i)] = group_of[static_cast<size_t>(j)];
        break;
      }
    }
  }
  return group_of;
}

void CollectGroups(const TopoDS_Shape& shape, int style, std::vector<LooseFaceGroup>* groups) {
  if (shape.ShapeType() == TopAbs_FACE) {
    groups->push_back({{shape}, style});
    return;
  }
  if (shape.ShapeType() != TopAbs_COMPOUND && shape.ShapeType() != TopAbs_COMPSOLID) return;
  LooseFaceGroup group{{}, style};
  for (TopoDS_Iterator it(shape); it.More(); it.Next()) {
    if (it.Value().ShapeType() == TopAbs_FACE) {
      group.faces.push_back(it.Value());
    } else {
      CollectGroups(it.Value(), style, groups);
    }
  }
  if (!group.faces.empty()) groups->push_back(std::move(group));
}

}  // namespace

void CollectLooseFaces(const TopoDS_Shape& shape, int style, std::vector<LooseFaceGroup>* groups) {
  CollectGroups(shape, style, groups);
}

std::vector<LooseBody> LooseFaceBodies(const std::vector<LooseFaceGroup>& groups) {
  std::vector<LooseBody> bodies;
  // Every face with its wall, if it is one; the caps are found against all walls.
  std::vector<Face> faces;
  std::vector<std::vector<int>> shells;  // per sewn shell made of walls and caps: its faces
  std::vector<std::pair<TopoDS_Shape, int>> sewn;
  for (const LooseFaceGroup& group : groups)
    for (TopoDS_Shape& shell : SewFaces(group.faces))
      sewn.emplace_back(std::move(shell), group.style);
  for (const auto& [shell, style] : sewn) {
    std::vector<int> members;
    for (TopExp_Explorer ex(shell, TopAbs_FACE); ex.More(); ex.Next()) {
      members.push_back(static_cast<int>(faces.size()));
      faces.push_back(MakeFace(ex.Current(), style));
    }
    shells.push_back(std::move(members));
  }
  const std::vector<int> group_of = TubeGroups(faces);
  // A shell with a face that is neither wall nor cap (a bracket with a bore) stays as sewn.
  std::vector<char> regrouped(faces.size(), 0);
  for (size_t s = 0; s < shells.size(); ++s) {
    const bool tube_faces = std::all_of(shells[s].begin(), shells[s].end(), [&](int f) {
      return group_of[static_cast<size_t>(f)] >= 0;
    });
    if (!tube_faces) {
      bodies.push_back({sewn[s].first, sewn[s].second});
      continue;
    }
    for (const int f : shells[s]) regrouped[static_cast<size_t>(f)] = 1;
  }
  std::vector<int> order;  // the regrouped tubes in the order of their first face
  std::vector<std::vector<int>> members(faces.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    if (!regrouped[f]) continue;
    const int g = group_of[f];
    if (members[static_cast<size_t>(g)].empty()) order.push_back(g);
    members[static_cast<size_t>(g)].push_back(static_cast<int>(f));
  }
  for (const int g : order) {
    TopoDS_Compound compound;
    BRep_Builder builder;
    builder.MakeCompound(compound);
    int style = faces[static_cast<size_t>(members[static_cast<size_t>(g)].front())].style;
    double largest = 0.0;
    for (const int f : members[static_cast<size_t>(g)]) {
      const Face& face = faces[static_cast<size_t>(f)];
      builder.Add(compound, face.shape);
      if (face.wall && face.area > largest) {
        largest = face.area;
        style = face.style;
      }
    }
    bodies.push_back({compound, style});
  }
  return bodies;
}

}  // namespace cablefit::internal
