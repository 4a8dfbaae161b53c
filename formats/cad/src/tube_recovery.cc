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
#include <vector>

#include "cablefit/formats/internal/circle_fit.h"

namespace cablefit {
namespace {

constexpr int kPointsPerSection = 12;
// How a face's cross-sections must look for it to be a tube's lateral face (fractions of the
// face's radius, the median of its round sections). An analytic surface (cylinder, torus, cone,
// sphere) is exact: its sections are circles of one radius (a changing radius means a cone or a
// sphere, no tube). Any other surface may be an approximation of a swept circle: polynomial
// B-splines (one cubic span per half circle: 2e-3 of the radius off round), and the sweeps of
// cablefit's early STEP writers, whose high-degree pipe surfaces are exact where their
// approximation held and ring where it failed: a 3 mm wire's radius off by up to 36 % over 40 %
// of its length, a 9 mm cable's swinging by +-20 % over three quarters of it, a 6 mm conduit's
// sections up to 6 % off round and 1.9 times as wide over its last quarter. Such a face is a
// tube face when most of it is near its radius (clean) and nearly all of it roughly round
// sections of about that size (their centres are the route). A flat cable's section (at least
// 1.5 times as wide as thick: 14 % off round) and a square's (12 %) are far from round either
// way; a cone whose radius changes by more than a tenth is no tube.
struct Roundness {
  double clean_residual;  // circle-fit RMS residual of a clean section
  double clean_radius;    // distance of a clean section's radius from the face's
  double min_clean;       // fraction of the sections that are clean
  double rough_residual;  // residual of a section that still has a usable centre
  double max_ratio;       // a rough section is at most this many times wider or narrower
};
constexpr Roundness kExactRoundness{1e-2, 1e-2, 0.95, 1e-2, 1.01};
constexpr Roundness kApproximatedRoundness{1e-2, 0.1, 0.5, 0.05, 1.5};
// Section runs of one tube's faces meet within this fraction of its radius: the centres of the
// same section fitted on two faces' arcs differ by about the circle residual, and two different
// tubes (touching cores) are two radii apart.
constexpr double kRunJoinTolerance = 0.05;

struct Section {
  Eigen::Vector3d centre;
  double radius;
  double residual;
};

struct LateralFace {
  std::vector<Section> sections;  // ordered along the face
  double area = 0.0;
  double min_radius = 0.0, max_radius = 0.0;  // of its sections' circles
  double arc = 0.0;  // [rad] the angle its sections subtend: 2 pi for a whole tube, pi for a half
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

// Up to this fraction of a face's sections may have no usable centre (rough sections included
// for an exact surface): a face split where it is not sampled well is not spoilt by one station.
constexpr double kMaxOffSections = 0.05;

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

Roundness RoundnessOf(GeomAbs_SurfaceType type) {
  const bool exact = type == GeomAbs_Cylinder || type == GeomAbs_Torus || type == GeomAbs_Cone ||
                     type == GeomAbs_Sphere;
  return exact ? kExactRoundness : kApproximatedRoundness;
}

// The sections of one face judged against its radius: the clean ones and the rough ones (clean
// included) whose centres are usable.
struct SectionCounts {
  double radius = 0.0;  // median of the sections round within clean_residual; 0 without any
  int clean = 0, rough = 0;
};

SectionCounts CountSections(const std::vector<internal::CircleFit>& fits, const Roundness& round) {
  SectionCounts counts;
  std::vector<double> radii;
  for (const internal::CircleFit& fit : fits)
    if (fit.ok && fit.rms_residual <= round.clean_residual * fit.radius)
      radii.push_back(fit.radius);
  if (radii.empty()) return counts;
  counts.radius = Median(radii);
  for (const internal::CircleFit& fit : fits) {
    const double r = counts.radius;
    counts.clean += fit.ok && fit.rms_residual <= round.clean_residual * r &&
                    std::abs(fit.radius - r) <= round.clean_radius * r;
    counts.rough += fit.ok && fit.rms_residual <= round.rough_residual * r &&
                    fit.radius * round.max_ratio >= r && fit.radius <= round.max_ratio * r;
  }
  return counts;
}

bool IsTubeFace(const SectionCounts& counts, int n, const Roundness& round) {
  return counts.radius > 0 && counts.clean >= round.min_clean * n &&
         n - counts.rough <= kMaxOffSections * n;
}

// A tube's section centres advance with the tube: along the face they travel at least this
// fraction of the length of the face's line along (its outer fibre round a bend of the tightest
// radius, one tube radius, is twice the centre's path). A flat strip's route curves are round
// too, but their centres sit at the bend's centre.
constexpr double kMinCentreTravel = 0.3;

// The length of the face's iso-curve along, in the middle of the across range.
double LengthAlong(const BRepAdaptor_Surface& surface, bool across_is_u, double b0, double b1,
                   double a_middle) {
  double length = 0;
  gp_Pnt previous = across_is_u ? surface.Value(a_middle, b0) : surface.Value(b0, a_middle);
  for (int k = 1; k <= 16; ++k) {
    const double b = b0 + (b1 - b0) * k / 16.0;
    const gp_Pnt p = across_is_u ? surface.Value(a_middle, b) : surface.Value(b, a_middle);
    length += p.Distance(previous);
    previous = p;
  }
  return length;
}

// Checks nine iso-curves across: sections of a tube face (constant radius tells the
// cross-sections of a tube from the parallels of a torus/sphere) that subtend a real arc and
// whose centres advance along the face. Returns the face's radius, or 0 when this parameter
// direction is not the tube's cross-section.
double CircleFamilyRadius(const BRepAdaptor_Surface& surface, bool across_is_u, double b0,
                          double b1, double a0, double a1, const Roundness& round) {
  constexpr int kIsos = 9;
  std::vector<internal::CircleFit> fits;
  double travel = 0;
  for (int k = 0; k < kIsos; ++k) {
    const double along = b0 + (b1 - b0) * k / (kIsos - 1.0);
    internal::CircleFit fit = SectionAt(surface, across_is_u, along, a0, a1);
    if (fit.ok && SubtendedAngle(surface, across_is_u, along, a0, a1, fit) < kMinSubtendedAngle)
      fit.ok = false;
    if (k > 0) travel += (fit.centre - fits.back().centre).norm();
    fits.push_back(fit);
  }
  // Nine samples: one of them may be off where a face of hundreds allows 5 %.
  const SectionCounts counts = CountSections(fits, round);
  const bool tube =
      counts.radius > 0 && counts.clean >= std::min(round.min_clean * kIsos, kIsos - 1.0) &&
      counts.rough >= kIsos - 1 &&
      travel >= kMinCentreTravel * LengthAlong(surface, across_is_u, b0, b1, 0.5 * (a0 + a1));
  return tube ? counts.radius : 0;
}

// Which parameter of a face runs across a tube (its iso-curves there are the sections).
struct Across {
  bool is_u = true;
  double radius = 0.0;  // of the sections, from nine of them
  Roundness round;
  double a0 = 0, a1 = 0;  // the across parameter's range
  double b0 = 0, b1 = 0;  // the along parameter's range
};

std::optional<Across> AcrossOf(const BRepAdaptor_Surface& surface, const TopoDS_Face& face) {
  if (surface.GetType() == GeomAbs_Plane) return std::nullopt;
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  // Where the surface type says which direction is across (a cylinder's u, a torus's v), only
  // that one is tried; other surfaces (extrusions, revolutions, B-spline pipes) are measured.
  const GeomAbs_SurfaceType type = surface.GetType();
  const Roundness round = RoundnessOf(type);
  const double radius_u =
      type == GeomAbs_Torus ? 0 : CircleFamilyRadius(surface, true, v0, v1, u0, u1, round);
  const double radius_v =
      type == GeomAbs_Cylinder ? 0 : CircleFamilyRadius(surface, false, u0, u1, v0, v1, round);
  if (radius_u <= 0 && radius_v <= 0) return std::nullopt;
  // Both directions circular (a sphere-like patch, a short torus piece): the cross-section is
  // the direction of the smaller circles, as a tube's radius is below its bend radius.
  Across across;
  across.is_u = radius_u > 0 && (radius_v <= 0 || radius_u <= radius_v);
  across.radius = across.is_u ? radius_u : radius_v;
  across.round = round;
  across.b0 = across.is_u ? v0 : u0, across.b1 = across.is_u ? v1 : u1;
  across.a0 = across.is_u ? u0 : v0, across.a1 = across.is_u ? u1 : v1;
  return across;
}

std::optional<LateralFace> SampleLateralFace(const TopoDS_Face& face, double spacing) {
  BRepAdaptor_Surface surface(face);
  const std::optional<Across> across_of = AcrossOf(surface, face);
  if (!across_of) return std::nullopt;
  const bool across_is_u = across_of->is_u;
  const double family_radius = across_of->radius;
  const Roundness round = across_of->round;
  const double b0 = across_of->b0, b1 = across_of->b1, a0 = across_of->a0, a1 = across_of->a1;
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
  const double step = std::min(spacing, 0.25 * family_radius);
  const int n = std::clamp(static_cast<int>(std::ceil(coarse_length / step)) + 1, 8, 20000);
  std::vector<internal::CircleFit> fits;
  for (int k = 0; k < n; ++k)
    fits.push_back(SectionAt(surface, across_is_u, b0 + (b1 - b0) * k / (n - 1.0), a0, a1));
  const SectionCounts counts = CountSections(fits, round);
  if (!IsTubeFace(counts, n, round)) return std::nullopt;
  const double radius = counts.radius;
  LateralFace lateral;
  lateral.min_radius = lateral.max_radius = radius;
  for (const internal::CircleFit& fit : fits) {
    if (!fit.ok || fit.rms_residual > round.rough_residual * radius ||
        fit.radius * round.max_ratio < radius || fit.radius > round.max_ratio * radius)
      continue;
    // A section's own radius where it is within a hundredth of the face's, else the face's (the
    // mean of a ringing approximation's radii is not the cable's). Its residual: its distance
    // from a circle of the face's radius about its centre.
    const bool own = std::abs(fit.radius - radius) <= kExactRoundness.clean_radius * radius;
    lateral.sections.push_back(
        {fit.centre, own ? fit.radius : radius, std::hypot(fit.rms_residual, fit.radius - radius)});
    lateral.min_radius = std::min(lateral.min_radius, fit.radius);
    lateral.max_radius = std::max(lateral.max_radius, fit.radius);
  }
  if (lateral.sections.size() < 2) return std::nullopt;
  const double middle = 0.5 * (b0 + b1);
  lateral.arc = SubtendedAngle(surface, across_is_u, middle, a0, a1,
                               SectionAt(surface, across_is_u, middle, a0, a1));
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  lateral.area = props.Mass();
  return lateral;
}

double Distance(const Section& a, const Section& b) { return (a.centre - b.centre).norm(); }

// A face's run of sections and the angle they subtend.
struct Run {
  std::vector<Section> sections;
  double arc = 0.0;  // [rad]
};

// The faces' section runs chained end to end into one route, and whether the route's wall is
// drawn twice. Faces that split the tube lengthwise (two half-shells over the same stretch)
// produce the same run twice: repeats are dropped, their angles added up. A stretch whose runs
// cover the circle twice over is a surface two bodies share (a conductor and the bore of its
// insulation, drawn as surfaces each): `twice`.
struct Chain {
  std::vector<Section> sections;
  bool twice = false;
};

std::optional<Chain> ChainRuns(std::vector<Run> runs, double tol) {
  std::vector<Run> unique;
  for (Run& run : runs) {
    const auto repeat = std::find_if(unique.begin(), unique.end(), [&](const Run& u) {
      const std::vector<Section>& a = run.sections;
      const std::vector<Section>& b = u.sections;
      return (Distance(a.front(), b.front()) < tol && Distance(a.back(), b.back()) < tol) ||
             (Distance(a.front(), b.back()) < tol && Distance(a.back(), b.front()) < tol);
    });
    if (repeat == unique.end()) {
      unique.push_back(std::move(run));
    } else {
      repeat->arc += run.arc;
    }
  }
  Chain chain;
  chain.twice =
      std::all_of(unique.begin(), unique.end(), [](const Run& u) { return u.arc > 3 * M_PI; });
  std::vector<Section>& route = chain.sections;
  route = std::move(unique.front().sections);
  unique.erase(unique.begin());
  while (!unique.empty()) {
    bool attached = false;
    for (auto it = unique.begin(); it != unique.end() && !attached; ++it) {
      std::vector<Section>& run = it->sections;
      if (Distance(route.back(), run.back()) < tol || Distance(route.front(), run.front()) < tol) {
        std::reverse(run.begin(), run.end());
      }
      if (Distance(route.back(), run.front()) < tol) {
        route.insert(route.end(), run.begin() + 1, run.end());
        attached = true;
      } else if (Distance(route.front(), run.back()) < tol) {
        route.insert(route.begin(), run.begin(), run.end() - 1);
        attached = true;
      }
      if (attached) unique.erase(it);
    }
    if (!attached) return std::nullopt;  // disjoint or branched: not one route
  }
  return chain;
}

}  // namespace

std::optional<TubeFaceEnds> LateralFaceEnds(const TopoDS_Face& face) {
  try {
    const BRepAdaptor_Surface surface(face);
    const std::optional<Across> across = AcrossOf(surface, face);
    if (!across) return std::nullopt;
    const internal::CircleFit start =
        SectionAt(surface, across->is_u, across->b0, across->a0, across->a1);
    const internal::CircleFit end =
        SectionAt(surface, across->is_u, across->b1, across->a0, across->a1);
    if (!start.ok || !end.ok) return std::nullopt;
    return TubeFaceEnds{start.centre, end.centre, across->radius};
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

std::optional<RecoveredTube> RecoverTube(const TopoDS_Shape& shape,
                                         const TubeRecoveryOptions& options) {
  try {
    struct RadiusGroup {
      double radius = 0;  // of the group's first face
      std::vector<Run> runs;
      double min_radius = 0, max_radius = 0;  // of all its sections' circles
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
        return std::abs(g.radius - r) <= kExactRoundness.clean_radius * g.radius;
      });
      if (group == groups.end())
        group = groups.insert(groups.end(),
                              RadiusGroup{r, {}, lateral->min_radius, lateral->max_radius});
      group->runs.push_back({std::move(lateral->sections), lateral->arc});
      group->min_radius = std::min(group->min_radius, lateral->min_radius);
      group->max_radius = std::max(group->max_radius, lateral->max_radius);
    }
    if (groups.empty() || total_area <= 0) return std::nullopt;
    // One radius: a solid tube. Two: a hollow one (hose, conduit, sleeve), if both walls run
    // along the same centreline. More: a stepped or composite part, not a tube.
    if (groups.size() > 2) return std::nullopt;
    std::sort(groups.begin(), groups.end(),
              [](const RadiusGroup& a, const RadiusGroup& b) { return a.radius > b.radius; });
    // Besides its lateral faces a tube has its two end caps and little else. A tube shorter than
    // two diameters (a segment between two close nodes of a harness network) is mostly caps: the
    // caps' area is allowed whatever the fraction.
    const double caps_area = 2 * M_PI * groups[0].radius * groups[0].radius;
    if (total_area - lateral_area >
        std::max((1 - options.min_area_fraction) * total_area, 1.05 * caps_area))
      return std::nullopt;
    auto chain_of = [](RadiusGroup& g) {
      return ChainRuns(std::move(g.runs), kRunJoinTolerance * g.radius);
    };
    const double outer_radius = groups[0].radius;
    const std::optional<Chain> outer = chain_of(groups[0]);
    if (!outer || outer->sections.size() < 2) return std::nullopt;
    const std::vector<Section>* chain = &outer->sections;
    double inner_radius = 0;
    if (groups.size() == 2) {
      const std::optional<Chain> inner_chain = chain_of(groups[1]);
      if (!inner_chain || inner_chain->sections.size() < 2) return std::nullopt;
      const std::vector<Section>* inner = &inner_chain->sections;
      const double tol = 0.1 * outer_radius;
      const bool same_ends =
          (Distance(inner->front(), chain->front()) < tol && Distance(inner->back(), chain->back()) < tol) ||
          (Distance(inner->front(), chain->back()) < tol && Distance(inner->back(), chain->front()) < tol);
      if (!same_ends) return std::nullopt;
      // A bore drawn twice is filled: its wall is also the surface of what fills it.
      if (!inner_chain->twice) inner_radius = groups[1].radius;
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
    tube.min_section_radius = groups[0].min_radius;
    tube.max_section_radius = groups[0].max_radius;
    tube.rms_residual = std::sqrt(residual2 / static_cast<double>(chain->size()));
    return tube;
  } catch (const Standard_Failure&) {
    return std::nullopt;  // a face OCCT cannot evaluate is not a tube face we can use
  }
}

}  // namespace cablefit
