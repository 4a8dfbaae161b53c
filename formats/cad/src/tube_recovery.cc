#include "tube_recovery.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <algorithm>
#include <cmath>

#include "cablefit/formats/internal/circle_fit.h"

namespace cablefit {
namespace {

constexpr int kPointsPerSection = 12;
// A cross-section counts as a circle when its fit residual is below this fraction of the
// radius: OCCT's pipe surfaces are approximations good to ~1e-6 of the radius, far below it,
// while an ellipse of 1 % eccentricity or a rounded box are well above it.
constexpr double kCircleTolerance = 1e-3;

struct Section {
  Eigen::Vector3d centre;
  double radius;
  double residual;
};

struct LateralFace {
  std::vector<Section> sections;  // ordered along the face
  double area = 0.0;
};

// Fits the circle of the iso-curve at `along`, with the across parameter spanning [a0, a1].
internal::CircleFit SectionAt(const BRepAdaptor_Surface& surface, bool across_is_u, double along,
                              double a0, double a1) {
  Eigen::Matrix3Xd pts(3, kPointsPerSection);
  for (int i = 0; i < kPointsPerSection; ++i) {
    const double a = a0 + (a1 - a0) * i / (kPointsPerSection - 1.0);
    const gp_Pnt p = across_is_u ? surface.Value(a, along) : surface.Value(along, a);
    pts.col(i) << p.X(), p.Y(), p.Z();
  }
  return internal::FitCircle(pts);
}

// The angle [rad] the arc of a cross-section subtends: a tube's cross-section is a good part of
// a circle, while the iso-curve along a barely bent stretch (a torus of 600 m major radius drawn
// for an 18 mm run, seen in a FreeCAD export) is also circular but subtends almost nothing.
double SubtendedAngle(const BRepAdaptor_Surface& surface, bool across_is_u, double along, double a0,
                      double a1, const internal::CircleFit& fit) {
  double length = 0;
  gp_Pnt previous = across_is_u ? surface.Value(a0, along) : surface.Value(along, a0);
  for (int i = 1; i < kPointsPerSection; ++i) {
    const double a = a0 + (a1 - a0) * i / (kPointsPerSection - 1.0);
    const gp_Pnt p = across_is_u ? surface.Value(a, along) : surface.Value(along, a);
    length += p.Distance(previous);
    previous = p;
  }
  return fit.radius > 0 ? length / fit.radius : 0.0;
}

// A face split lengthwise into up to 16 strips still has cross-sections of 2 pi / 16.
constexpr double kMinSubtendedAngle = 0.35;

// Checks five iso-curves across: circles of one radius that subtend a real arc. Returns the
// radius, or 0 when this parameter direction is not the tube's cross-section.
double CircleFamilyRadius(const BRepAdaptor_Surface& surface, bool across_is_u, double b0,
                          double b1, double a0, double a1) {
  double r_first = 0;
  for (int k = 0; k < 5; ++k) {
    const double along = b0 + (b1 - b0) * k / 4.0;
    const internal::CircleFit fit = SectionAt(surface, across_is_u, along, a0, a1);
    if (!fit.ok || fit.rms_residual > kCircleTolerance * fit.radius) return 0;
    if (SubtendedAngle(surface, across_is_u, along, a0, a1, fit) < kMinSubtendedAngle) return 0;
    if (k == 0) r_first = fit.radius;
    // Constant radius tells the cross-sections of a tube from the parallels of a torus/sphere.
    if (std::abs(fit.radius - r_first) > kCircleTolerance * r_first) return 0;
  }
  return r_first;
}

std::optional<LateralFace> SampleLateralFace(const TopoDS_Face& face, double spacing) {
  BRepAdaptor_Surface surface(face);
  if (surface.GetType() == GeomAbs_Plane) return std::nullopt;
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  // Where the surface type says which direction is across (a cylinder's u, a torus's v), only
  // that one is tried; other surfaces (extrusions, revolutions, B-spline pipes) are measured.
  const GeomAbs_SurfaceType type = surface.GetType();
  const double radius_u = type == GeomAbs_Torus ? 0 : CircleFamilyRadius(surface, true, v0, v1, u0, u1);
  const double radius_v =
      type == GeomAbs_Cylinder ? 0 : CircleFamilyRadius(surface, false, u0, u1, v0, v1);
  if (radius_u <= 0 && radius_v <= 0) return std::nullopt;
  // Both directions circular (a sphere-like patch, a short torus piece): the cross-section is
  // the direction of the smaller circles, as a tube's radius is below its bend radius.
  const bool across_is_u = radius_u > 0 && (radius_v <= 0 || radius_u <= radius_v);
  const double radius = across_is_u ? radius_u : radius_v;
  const double b0 = across_is_u ? v0 : u0, b1 = across_is_u ? v1 : u1;
  const double a0 = across_is_u ? u0 : v0, a1 = across_is_u ? u1 : v1;
  // Estimate the face's length from a coarse pass, then sample at the requested spacing.
  double coarse_length = 0;
  Eigen::Vector3d previous = SectionAt(surface, across_is_u, b0, a0, a1).centre;
  for (int k = 1; k <= 16; ++k) {
    const Eigen::Vector3d c = SectionAt(surface, across_is_u, b0 + (b1 - b0) * k / 16.0, a0, a1).centre;
    coarse_length += (c - previous).norm();
    previous = c;
  }
  // The centres' chords cut a bend of radius R short by (h / R)^2 / 24 of its length: a
  // quarter of the tube's radius apart, a thin wire bent tightly stays well within 0.1 %.
  const double step = std::min(spacing, 0.25 * radius);
  const int n = std::clamp(static_cast<int>(std::ceil(coarse_length / step)) + 1, 8, 20000);
  LateralFace lateral;
  for (int k = 0; k < n; ++k) {
    const internal::CircleFit fit =
        SectionAt(surface, across_is_u, b0 + (b1 - b0) * k / (n - 1.0), a0, a1);
    if (!fit.ok || fit.rms_residual > kCircleTolerance * radius ||
        std::abs(fit.radius - radius) > kCircleTolerance * radius) {
      return std::nullopt;
    }
    lateral.sections.push_back({fit.centre, fit.radius, fit.rms_residual});
  }
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  lateral.area = props.Mass();
  return lateral;
}

double Distance(const Section& a, const Section& b) { return (a.centre - b.centre).norm(); }

// Chains the faces' section runs end to end into one route. Faces that split the tube
// lengthwise (two half-shells over the same stretch) produce the same run twice: drop repeats.
std::optional<std::vector<Section>> ChainRuns(std::vector<std::vector<Section>> runs, double tol) {
  std::vector<std::vector<Section>> unique;
  for (auto& run : runs) {
    const bool repeat = std::any_of(unique.begin(), unique.end(), [&](const auto& u) {
      return (Distance(run.front(), u.front()) < tol && Distance(run.back(), u.back()) < tol) ||
             (Distance(run.front(), u.back()) < tol && Distance(run.back(), u.front()) < tol);
    });
    if (!repeat) unique.push_back(std::move(run));
  }
  std::vector<Section> chain = std::move(unique.front());
  unique.erase(unique.begin());
  while (!unique.empty()) {
    bool attached = false;
    for (auto it = unique.begin(); it != unique.end() && !attached; ++it) {
      auto& run = *it;
      if (Distance(chain.back(), run.back()) < tol || Distance(chain.front(), run.front()) < tol) {
        std::reverse(run.begin(), run.end());
      }
      if (Distance(chain.back(), run.front()) < tol) {
        chain.insert(chain.end(), run.begin() + 1, run.end());
        attached = true;
      } else if (Distance(chain.front(), run.back()) < tol) {
        chain.insert(chain.begin(), run.begin(), run.end() - 1);
        attached = true;
      }
      if (attached) unique.erase(it);
    }
    if (!attached) return std::nullopt;  // disjoint or branched: not one route
  }
  return chain;
}

}  // namespace

std::optional<RecoveredTube> RecoverTube(const TopoDS_Shape& shape,
                                         const TubeRecoveryOptions& options) {
  try {
    struct RadiusGroup {
      double radius = 0;  // of the group's first face
      std::vector<std::vector<Section>> runs;
    };
    std::vector<RadiusGroup> groups;
    double lateral_area = 0, total_area = 0;
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
      const TopoDS_Face& face = TopoDS::Face(ex.Current());
      GProp_GProps props;
      BRepGProp::SurfaceProperties(face, props);
      total_area += props.Mass();
      std::optional<LateralFace> lateral = SampleLateralFace(face, options.sample_spacing);
      if (!lateral) continue;
      lateral_area += lateral->area;
      const double r = lateral->sections.front().radius;
      auto group = std::find_if(groups.begin(), groups.end(), [&](const RadiusGroup& g) {
        return std::abs(g.radius - r) <= 0.01 * g.radius;
      });
      if (group == groups.end()) group = groups.insert(groups.end(), RadiusGroup{r, {}});
      group->runs.push_back(std::move(lateral->sections));
    }
    if (groups.empty() || total_area <= 0) return std::nullopt;
    if (lateral_area < options.min_area_fraction * total_area) return std::nullopt;
    // One radius: a solid tube. Two: a hollow one (hose, conduit, sleeve), if both walls run
    // along the same centreline. More: a stepped or composite part, not a tube.
    if (groups.size() > 2) return std::nullopt;
    std::sort(groups.begin(), groups.end(),
              [](const RadiusGroup& a, const RadiusGroup& b) { return a.radius > b.radius; });
    auto chain_of = [](RadiusGroup& g) {
      return ChainRuns(std::move(g.runs), 0.01 * g.radius);
    };
    const double outer_radius = groups[0].radius;
    std::optional<std::vector<Section>> chain = chain_of(groups[0]);
    if (!chain || chain->size() < 2) return std::nullopt;
    double inner_radius = 0;
    if (groups.size() == 2) {
      const std::optional<std::vector<Section>> inner = chain_of(groups[1]);
      if (!inner || inner->size() < 2) return std::nullopt;
      const double tol = 0.1 * outer_radius;
      const bool same_ends =
          (Distance(inner->front(), chain->front()) < tol && Distance(inner->back(), chain->back()) < tol) ||
          (Distance(inner->front(), chain->back()) < tol && Distance(inner->back(), chain->front()) < tol);
      if (!same_ends) return std::nullopt;
      inner_radius = groups[1].radius;
    }
    double length = 0, residual2 = 0, radius_sum = 0;
    for (size_t i = 1; i < chain->size(); ++i) length += Distance((*chain)[i - 1], (*chain)[i]);
    if (Distance(chain->front(), chain->back()) < 0.01 * outer_radius) return std::nullopt;  // closed
    if (length < options.min_aspect * 2 * outer_radius) return std::nullopt;
    RecoveredTube tube;
    tube.centres.resize(3, static_cast<Eigen::Index>(chain->size()));
    for (size_t i = 0; i < chain->size(); ++i) {
      tube.centres.col(static_cast<Eigen::Index>(i)) = (*chain)[i].centre;
      residual2 += (*chain)[i].residual * (*chain)[i].residual;
      radius_sum += (*chain)[i].radius;
    }
    tube.radius = radius_sum / static_cast<double>(chain->size());
    tube.inner_radius = inner_radius;
    tube.rms_residual = std::sqrt(residual2 / static_cast<double>(chain->size()));
    return tube;
  } catch (const Standard_Failure&) {
    return std::nullopt;  // a face OCCT cannot evaluate is not a tube face we can use
  }
}

}  // namespace cablefit
