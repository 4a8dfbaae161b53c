#include "curve_routes.h"

#include <BRepAdaptor_Curve.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace cablefit {
namespace {

struct Link {
  TopoDS_Edge edge;
  int node[2];     // node at the curve's first / last parameter
  double length;   // [OCCT unit]
  bool used = false;
};

Eigen::Vector3d ToEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

int NodeFor(const Eigen::Vector3d& p, std::vector<Eigen::Vector3d>* nodes, double tolerance) {
  for (size_t i = 0; i < nodes->size(); ++i) {
    if (((*nodes)[i] - p).norm() < tolerance) return static_cast<int>(i);
  }
  nodes->push_back(p);
  return static_cast<int>(nodes->size()) - 1;
}

// Samples a chain of links (each walked forwards or backwards) at about `spacing`.
CurveRoute SampleChain(const std::vector<std::pair<const Link*, bool>>& chain, double spacing) {
  double total = 0;
  for (const auto& [link, forward] : chain) total += link->length;
  const double step = std::min(spacing, total / 16.0);
  std::vector<Eigen::Vector3d> pts;
  CurveRoute route;
  for (const auto& [link, forward] : chain) {
    BRepAdaptor_Curve curve(link->edge);
    const bool straight = curve.GetType() == GeomAbs_Line;
    const int n = straight ? 1 : std::max(2, static_cast<int>(std::ceil(link->length / step)));
    const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
    // Equal steps in arc length, not in the curve parameter (B-spline speed varies).
    std::vector<double> params(n + 1);
    for (int k = 0; k <= n; ++k) {
      if (k == 0 || k == n || straight) {
        params[k] = k == 0 ? t0 : t1;
      } else {
        GCPnts_AbscissaPoint at(curve, link->length * k / n, t0);
        params[k] = at.IsDone() ? at.Parameter() : t0 + (t1 - t0) * k / n;
      }
    }
    if (!forward) std::reverse(params.begin(), params.end());
    for (int k = pts.empty() ? 0 : 1; k <= n; ++k) {
      pts.push_back(ToEigen(curve.Value(params[k])));
      if (k > 0 && !straight) {
        const Eigen::Vector3d mid = ToEigen(curve.Value(0.5 * (params[k - 1] + params[k])));
        const Eigen::Vector3d chord_mid = 0.5 * (pts[pts.size() - 2] + pts.back());
        route.max_chord_error = std::max(route.max_chord_error, (mid - chord_mid).norm());
      }
    }
  }
  route.points.resize(3, static_cast<Eigen::Index>(pts.size()));
  for (size_t i = 0; i < pts.size(); ++i) route.points.col(static_cast<Eigen::Index>(i)) = pts[i];
  return route;
}

}  // namespace

bool IsClosedPlanar(const Eigen::Matrix3Xd& points) {
  if (points.cols() < 4) return false;
  const Eigen::Vector3d centroid = points.rowwise().mean();
  const Eigen::Matrix3Xd centred = points.colwise() - centroid;
  const double size = centred.colwise().norm().maxCoeff();
  if (!(size > 0)) return false;
  if ((points.col(0) - points.col(points.cols() - 1)).norm() > 1e-6 * size) return false;
  const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(centred, Eigen::ComputeThinU);
  const Eigen::Vector3d normal = svd.matrixU().col(2);
  return (normal.transpose() * centred).cwiseAbs().maxCoeff() <= 1e-4 * size;
}

std::vector<CurveRoute> ExtractCurveRoutes(const TopoDS_Shape& shape, double spacing,
                                           double tolerance) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::vector<Eigen::Vector3d> nodes;
  std::vector<Link> links;
  TopTools_MapOfShape seen;
  for (TopExp_Explorer ex(shape, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(ex.Current());
    if (!seen.Add(edge)) continue;
    const int index = edge_faces.FindIndex(edge);
    if (index > 0 && !edge_faces.FindFromIndex(index).IsEmpty()) continue;  // bounds a face
    BRepAdaptor_Curve curve(edge);
    const double length = GCPnts_AbscissaPoint::Length(curve);
    if (!(length > tolerance)) continue;  // degenerate
    Link link{edge, {0, 0}, length};
    link.node[0] = NodeFor(ToEigen(curve.Value(curve.FirstParameter())), &nodes, tolerance);
    link.node[1] = NodeFor(ToEigen(curve.Value(curve.LastParameter())), &nodes, tolerance);
    links.push_back(link);
  }
  std::vector<std::vector<int>> incident(nodes.size());
  for (size_t i = 0; i < links.size(); ++i) {
    incident[links[i].node[0]].push_back(static_cast<int>(i));
    incident[links[i].node[1]].push_back(static_cast<int>(i));
  }
  auto walk = [&](int start_node, int first_link) {
    std::vector<std::pair<const Link*, bool>> chain;
    int node = start_node, li = first_link;
    while (true) {
      Link& link = links[li];
      link.used = true;
      const bool forward = link.node[0] == node;
      chain.emplace_back(&link, forward);
      node = forward ? link.node[1] : link.node[0];
      if (incident[node].size() != 2) break;
      const int next = incident[node][0] == li ? incident[node][1] : incident[node][0];
      if (links[next].used) break;  // closed loop
      li = next;
    }
    return chain;
  };
  std::vector<CurveRoute> routes;
  for (size_t n = 0; n < nodes.size(); ++n) {
    if (incident[n].size() == 2) continue;
    for (int li : incident[n]) {
      if (!links[li].used) routes.push_back(SampleChain(walk(static_cast<int>(n), li), spacing));
    }
  }
  for (size_t li = 0; li < links.size(); ++li) {  // cycles without a branch or end point
    if (!links[li].used) {
      routes.push_back(SampleChain(walk(links[li].node[0], static_cast<int>(li)), spacing));
    }
  }
  return routes;
}

}  // namespace cablefit
