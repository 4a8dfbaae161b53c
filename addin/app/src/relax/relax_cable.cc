#include "cablefit/app/relax/relax_cable.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "cablefit/core/base/errors.h"
#include "relax/relax_route.h"

namespace cablefit::addin {
namespace {

using json::Json;
using json::NumberOrNull;
using json::ToJson;

// A length [m] for a message or note a person reads: in millimetres, like every human-facing
// length of the tool (the JSON fields stay in metres).
std::string Millimetres(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g mm", 1e3 * v);
  return buf;
}

// A support waiting to be placed; higher priority wins where two are too close to both act.
struct Candidate {
  SupportSpec spec;
  int priority = 0;  // 3 end, 2 harness.json, 1 automatic clip
  std::string origin;
};

// The support at an end of the route; `direction` (unit, along increasing s) where the drawing
// gives the end's direction exactly (a mesh tube's cap), else the route's tangent there.
SupportSpec EndSupport(const EndConfig& end, double s, const Polyline& route,
                       const Eigen::Matrix3Xd& normals, const std::optional<Vec3>& direction) {
  SupportSpec sp;
  sp.kind = end.kind;
  sp.s = s;
  sp.position = RoutePoint(route, s);
  sp.tangent = direction ? *direction : RouteTangent(route, s);
  sp.normal = NormalAt(route, normals, s);
  sp.normal = (sp.normal - sp.normal.dot(sp.tangent) * sp.tangent).normalized();
  sp.sliding = end.sliding;
  return sp;
}

// Keeps the candidates in priority order, dropping an automatic clip closer than `gap` to a
// kept support; two explicit supports that close are a set-up error.
std::vector<Candidate> Place(std::vector<Candidate> all, double gap,
                             std::vector<std::string>* notes) {
  std::stable_sort(all.begin(), all.end(),
                   [](const Candidate& a, const Candidate& b) { return a.priority > b.priority; });
  std::vector<Candidate> kept;
  for (const Candidate& c : all) {
    const auto clash = std::find_if(kept.begin(), kept.end(), [&](const Candidate& k) {
      return std::abs(k.spec.s - c.spec.s) < gap;
    });
    if (clash == kept.end()) {
      kept.push_back(c);
    } else if (c.priority <= 1) {
      notes->push_back(c.origin + " at s=" + Millimetres(c.spec.s) + " ignored: within " + Millimetres(gap) +
                       " of the " + clash->origin + " support");
    } else {
      throw InvalidInput(c.origin + " support at s=" + Millimetres(c.spec.s) + " is within " +
                         Millimetres(gap) + " of the " + clash->origin + " support at s=" +
                         Millimetres(clash->spec.s) + " (give one support there, or set the end)");
    }
  }
  std::sort(kept.begin(), kept.end(),
            [](const Candidate& a, const Candidate& b) { return a.spec.s < b.spec.s; });
  return kept;
}

// The drawn wide axis of a flat cable at every point of `route` (its cleaned centreline),
// square to the route.
Eigen::Matrix3Xd FlatNormals(const DrawnCable& drawn, const Polyline& route) {
  Eigen::Matrix3Xd normals(3, route.size());
  const RouteProjector projector(drawn.centreline);
  for (Eigen::Index i = 0; i < route.size(); ++i) {
    const double s = projector.NearestArcLength(route.points.col(i));
    const Vec3 axis = NormalAt(drawn.centreline, drawn.flat->wide_axes, s);
    const Vec3 tangent = RouteTangent(route, route.s[i]);
    normals.col(i) = (axis - axis.dot(tangent) * tangent).normalized();
  }
  return normals;
}

}  // namespace

MaterialSpec DefaultBundleMaterial(double d, double bore) {
  MaterialSpec m;
  m.diameter = d;
  const double second_moment = std::pow(d, 4) - std::pow(bore, 4);  // x pi / 64
  const double area = d * d - bore * bore;                          // x pi / 4
  m.bending_stiffness = kDefaultBundleModulus * std::numbers::pi * second_moment / 64;
  m.torsional_stiffness = m.bending_stiffness / 1.3;
  m.linear_density = kDefaultBundleDensity * std::numbers::pi * area / 4;
  m.axial_stiffness = kDefaultAxialModulus * std::numbers::pi * area / 4;
  return m;
}

MaterialSpec DefaultFlatMaterial(double w, double t, bool rounded_edges) {
  // Straight part a with two half-discs of radius r at its edges (r = 0: a rectangle).
  const double r = rounded_edges ? 0.5 * t : 0.0, a = w - 2 * r;
  const double pi = std::numbers::pi;
  const double area = a * t + pi * r * r;
  const double i_easy = a * t * t * t / 12 + pi * std::pow(r, 4) / 4;
  const double i_stiff = t * a * a * a / 12 + pi * r * r * a * a / 4 + 4.0 / 3 * a * r * r * r +
                         pi * std::pow(r, 4) / 4;
  MaterialSpec m;
  m.diameter = w;
  m.bending_stiffness = kDefaultBundleModulus * std::sqrt(i_easy * i_stiff);
  m.bending_ratio = i_stiff / i_easy;
  m.principal_angle = 0.5 * pi;
  const double j = w * t * t * t * (1.0 / 3 - 0.21 * t / w * (1 - std::pow(t / w, 4) / 12));
  m.torsional_stiffness = kDefaultBundleModulus / 2.6 * j;
  m.linear_density = kDefaultBundleDensity * area;
  m.axial_stiffness = kDefaultAxialModulus * area;
  return m;
}

// One function though long: the set-up is read top to bottom as harness.json's precedence
// (drawing, then the cable's entry, then defaults), each step using what the ones before decided.
CableSetup SetUpCable(const HarnessDrawing& drawing, int cable,
                      const std::vector<OrientedBox>& boxes, const HarnessConfig& config,
                      const JunctionEnds& junction_ends) {
  const DrawnCable& drawn = drawing.cables[cable];
  const CableConfig cc = config.For(drawn.name);
  CableSetup out;
  out.cable = cable;
  out.name = drawn.name;
  out.route = CleanRoute(drawn.centreline);
  const Polyline& route = out.route;
  // Support positions and arc lengths are placed on the drawing; a cable built longer or
  // shorter than drawn (harness.json "length") has its supports at the same fraction of its
  // length, so the difference is spread evenly along it.
  const double length = route.s[route.size() - 1];
  const double built_length = cc.length ? cc.length->For(length) : length;

  double diameter = cc.DiameterFor(drawn.diameter);
  if (!(diameter > 0)) {
    diameter = kDefaultDiameter;
    out.diameter_defaulted = true;
    out.notes.push_back("drawn as a bare curve without diameter: " + Millimetres(diameter) +
                        " assumed (set \"diameter\" in harness.json)");
  }
  // A drawn bore (hose, conduit) holds while the outer diameter is the drawn one.
  if (drawn.inner_diameter > 0 && drawn.inner_diameter < diameter) out.bore = drawn.inner_diameter;
  if (cc.material) {
    out.spec.material = *cc.material;
    out.material_source = cc.material_source;
  } else if (drawn.flat) {
    const FlatSection& f = *drawn.flat;
    out.spec.material = DefaultFlatMaterial(f.width, f.thickness, f.rounded_edges);
    out.material_defaulted = true;
    out.material_source = "default flat-cable estimate";
    out.notes.push_back("material not given: a flat " + Millimetres(f.width) + " x " +
                        Millimetres(f.thickness) + (f.rounded_edges ? " stadium" : " rectangle") +
                        " estimated like a PVC-insulated bundle over its section (E_eff = 75 MPa, "
                        "2000 kg/m^3), bending ratio " +
                        std::to_string(static_cast<int>(std::lround(out.spec.material.bending_ratio))) +
                        " between its edgewise and flatwise stiffness");
  } else {
    out.spec.material = DefaultBundleMaterial(diameter, out.bore);
    out.material_defaulted = true;
    out.material_source = "default bundle estimate";
    // The hollow-tube note differs from the solid one, so the report lists it per cable.
    out.notes.push_back(out.bore > 0
                            ? "material not given: a hollow tube (bore " + Millimetres(out.bore) +
                                  ") estimated like a PVC-insulated bundle over its wall (E_eff = "
                                  "75 MPa, GJ = EI/1.3, 2000 kg/m^3 over the annulus)"
                            : std::string(kDefaultMaterialNote));
  }
  if (drawn.flat) {
    out.flat_width = drawn.flat->width;
    out.flat_thickness = drawn.flat->thickness;
    out.notes.push_back("flat " + Millimetres(drawn.flat->width) + " x " +
                        Millimetres(drawn.flat->thickness) +
                        ": relaxed with its section's two bending stiffnesses, clamped as drawn");
  }
  out.spec.material.diameter = diameter;
  // A cable drawn taut between two supports has a tension only through its stretch: a material
  // without EA gets the bundle estimate's, which only matters where there is no slack.
  if (!(out.spec.material.axial_stiffness > 0)) {
    out.spec.material.axial_stiffness = DefaultBundleMaterial(diameter, out.bore).axial_stiffness;
  }
  out.spec.name = drawn.name;
  out.spec.length = built_length;
  for (const SleeveConfig& sl : cc.sleeves) {
    out.spec.sleeves.push_back({sl.from * built_length, sl.to * built_length,
                                sl.bending_stiffness, sl.torsional_stiffness, sl.linear_density});
  }
  out.drawn_length = length;
  if (built_length != length) {
    out.notes.push_back("built " + Millimetres(built_length) + " long (harness.json \"length\": " +
                        cc.length->ToString() + "), drawn " + Millimetres(length));
  }
  if (const std::string why = config.PreformedReason(drawn.name); !why.empty())
    out.notes.push_back(why);
  out.spec.gravity = cc.gravity.value_or(config.gravity);
  if (cc.min_bend_radius) {
    out.min_bend_radius_limit = *cc.min_bend_radius;
    out.notes.push_back("bend radius limit " + Millimetres(*cc.min_bend_radius) + " (" +
                        cc.min_bend_radius_source + ")");
  }

  // Twist-free frames along the drawing: clamps hold the drawn cross-section orientation, with
  // the start normal pointing as far "up" (against gravity) as the tangent allows.
  const Vec3 up =
      out.spec.gravity.norm() > 0 ? Vec3(-out.spec.gravity.normalized()) : Vec3::UnitZ();
  // A flat cable's material d1 is its wide axis as drawn: the clamps hold the section as the
  // drawing turns it.
  const Eigen::Matrix3Xd normals =
      drawn.flat ? FlatNormals(drawn, route) : TransportedNormals(route, up);

  std::vector<Candidate> candidates;
  const EndConfig start = cc.start.value_or(EndConfig{});
  const EndConfig end = cc.end.value_or(EndConfig{});
  if (!start.free && !junction_ends.start)
    candidates.push_back(
        {EndSupport(start, 0.0, route, normals, drawn.start_direction), 3, "start"});
  if (!end.free && !junction_ends.end)
    candidates.push_back({EndSupport(end, length, route, normals, drawn.end_direction), 3, "end"});
  for (const ExtraSupportConfig& e : cc.supports) {
    SupportSpec sp;
    sp.kind = e.kind;
    sp.sliding = e.sliding;
    if (e.s) {
      if (*e.s > length) {
        throw InvalidInput("harness.json support at s=" + Millimetres(*e.s) +
                           " lies beyond the cable (" + Millimetres(length) + ")");
      }
      sp.s = *e.s;
      sp.position = RoutePoint(route, sp.s);
    } else {
      sp.s = NearestArcLength(route, *e.point);
      sp.position = *e.point;
    }
    sp.tangent = RouteTangent(route, sp.s);
    sp.normal = NormalAt(route, normals, sp.s);
    candidates.push_back({sp, 2, "harness.json"});
  }
  if (cc.auto_clips.value_or(true)) {
    std::vector<std::string> names;
    for (const DrawnSolid& s : drawing.solids) names.push_back(s.name);
    for (const ClipSpan& span : FindClipSpans(route, boxes, names, 1e-6)) {
      SupportSpec sp;
      sp.kind = SupportKind::kClip;
      sp.s = 0.5 * (span.s_in + span.s_out);
      sp.position = RoutePoint(route, sp.s);
      sp.tangent = RouteTangent(route, sp.s);
      candidates.push_back({sp, 1, "clip '" + span.solid_name + "'"});
    }
  }
  const double gap = std::max(diameter, 1e-3 * length);
  for (const Candidate& c : Place(candidates, gap, &out.notes)) {
    out.spec.supports.push_back(c.spec);
    out.spec.supports.back().s *= built_length / length;
    out.support_origin.push_back(c.origin);
  }
  const bool in_network = junction_ends.start || junction_ends.end;
  if (out.spec.supports.empty() && !in_network) {
    throw InvalidInput("no supports: both ends are free and harness.json gives none");
  }
  if (in_network) out.junction = junction_ends.description;
  return out;
}

int OutputSamples(double length) {
  return std::clamp(static_cast<int>(std::ceil(length / 0.001)) + 1, 201, 2001);
}

void MeasureSpringbackAndSag(const Polyline& weightless, CableRelaxation* out) {
  CableRelaxation& r = *out;
  const Polyline shape = SampleCenterline(weightless, r.relaxed.s);
  const RouteProjector drawn(r.setup.route);
  double springback = 0.0, sag = 0.0;
  for (int i = 0; i < shape.size(); ++i) {
    double d = 0.0;
    drawn.NearestArcLength(shape.points.col(i), &d);
    springback = std::max(springback, d);
    sag = std::max(sag, (r.relaxed.points.col(i) - shape.points.col(i)).norm());
  }
  r.springback_max = springback;
  r.sag_max = sag;
  r.split_note.clear();
}

namespace {

// A second solve of the same set-up without gravity, from the same drawn route: a failure here
// never costs the relaxation itself, it only leaves the split unknown.
void SplitSpringbackAndSag(RodSimulator& sim, CableRelaxation* out) {
  CableRelaxation& r = *out;
  if (r.setup.spec.gravity.norm() == 0) {
    r.split_note = "no gravity: all of the deviation is springback";
    r.springback_max = r.max_deviation;
    r.sag_max = 0.0;
    return;
  }
  RodSpec weightless = r.setup.spec;
  weightless.gravity = Vec3::Zero();
  try {
    const SimulationResult sb = sim.Simulate(weightless, &r.setup.route);
    if (!sb.converged) {
      r.split_note = "not computed: the solve without gravity did not converge";
      return;
    }
    MeasureSpringbackAndSag(sb.solution.centerline, &r);
  } catch (const std::exception& e) {
    r.split_note = std::string("not computed: ") + e.what();
  }
}

}  // namespace

CableRelaxation RelaxCable(CableSetup setup, const SimulationOptions& options,
                           double min_bend_radius_factor) {
  const auto t0 = std::chrono::steady_clock::now();
  CableRelaxation r;
  r.setup = std::move(setup);
  const RodSpec& spec = r.setup.spec;
  RodSimulator sim(options);
  r.result = sim.Simulate(spec, &r.setup.route);
  const auto measured = std::chrono::steady_clock::now();
  MeasureRelaxation(min_bend_radius_factor, &r);
  if (r.result.converged) SplitSpringbackAndSag(sim, &r);
  const auto t1 = std::chrono::steady_clock::now();
  r.seconds = std::chrono::duration<double>(t1 - t0).count();
  r.measure_seconds = std::chrono::duration<double>(t1 - measured).count();
  return r;
}

void MeasureRelaxation(double min_bend_radius_factor, CableRelaxation* out) {
  CableRelaxation& r = *out;
  const RodSpec& spec = r.setup.spec;
  r.relaxed = SampleCenterline(r.result.solution.centerline,
                               UniformArcLengths(spec.length, OutputSamples(spec.length)));

  const int n = r.relaxed.size();
  r.deviation.resize(n);
  r.max_deviation = 0.0;
  double sum_sq = 0.0;
  const RouteProjector drawn(r.setup.route);
  for (int i = 0; i < n; ++i) {
    double d = 0.0;
    drawn.NearestArcLength(r.relaxed.points.col(i), &d);
    r.deviation[i] = d;
    sum_sq += d * d;
    if (d > r.max_deviation) {
      r.max_deviation = d;
      r.max_deviation_s = r.relaxed.s[i];
    }
  }
  r.rms_deviation = std::sqrt(sum_sq / n);
  MeasureBendAndTension(min_bend_radius_factor, out);
}

void MeasureBendAndTension(double min_bend_radius_factor, CableRelaxation* out) {
  CableRelaxation& r = *out;
  const RodSpec& spec = r.setup.spec;

  // Curvature from the turning of consecutive element tangents of the finest level.
  const RodSolution& sol = r.result.solution;
  double max_kappa = 0.0;
  for (size_t i = 0; i + 1 < sol.frames.size(); ++i) {
    const double ds =
        sol.frame_s[static_cast<Eigen::Index>(i + 1)] - sol.frame_s[static_cast<Eigen::Index>(i)];
    const Vec3& a = sol.frames[i].d3;
    const Vec3& b = sol.frames[i + 1].d3;
    const double kappa = std::atan2(a.cross(b).norm(), a.dot(b)) / ds;
    if (kappa > max_kappa) {
      max_kappa = kappa;
      r.min_bend_radius_s = 0.5 * (sol.frame_s[static_cast<Eigen::Index>(i)] +
                                   sol.frame_s[static_cast<Eigen::Index>(i + 1)]);
    }
  }
  r.min_bend_radius = max_kappa > 0 ? 1.0 / max_kappa : std::numeric_limits<double>::infinity();
  r.bend_limit = r.setup.min_bend_radius_limit > 0 ? r.setup.min_bend_radius_limit
                                                  : min_bend_radius_factor * spec.material.diameter;
  r.bend_flag = r.min_bend_radius < r.bend_limit;

  // Unknown (NaN) when the solution carries no internal force (a cable solved within a network).
  r.max_tension = sol.internal_force.cols() > 0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  for (Eigen::Index i = 0; i < sol.internal_force.cols(); ++i) {
    const double tension = sol.internal_force.col(i).dot(sol.frames[static_cast<size_t>(i)].d3);
    if (tension > r.max_tension) {
      r.max_tension = tension;
      r.max_tension_s = sol.frame_s[i];
    }
  }
  r.stretches.clear();
  r.taut = false;
  const SupportSpec* previous = nullptr;
  for (const SupportSpec& sp : spec.supports) {
    if (sp.sliding) continue;
    if (previous != nullptr && sp.s > previous->s) {
      CableRelaxation::Stretch st;
      st.s0 = previous->s;
      st.s1 = sp.s;
      st.chord = (sp.position - previous->position).norm();
      st.slack = st.chord > 0 ? (st.s1 - st.s0 - st.chord) / st.chord : 0.0;
      st.taut = st.slack < kTautSlack;
      r.taut = r.taut || st.taut;
      r.stretches.push_back(st);
    }
    previous = &sp;
  }
}

// The fields of the JSON in the order docs/cli.md lists them: a flat list reads best whole.
Json CableToJson(const CableRelaxation& r, const DrawnCable& drawn) {
  const CableSetup& su = r.setup;
  const RodSpec& spec = su.spec;
  const SimulationResult& res = r.result;
  Json j;
  j["name"] = su.name;
  j["source"] = ToString(drawn.source);
  j["length"] = spec.length;
  j["drawn_length"] = su.drawn_length;
  j["diameter"] = spec.material.diameter;
  j["diameter_defaulted"] = su.diameter_defaulted;
  j["inner_diameter"] = su.bore;  // bore of a hollow tube (hose, conduit), 0 for a solid one
  if (drawn.flat) {
    j["flat"] = {{"width", drawn.flat->width},
                 {"thickness", drawn.flat->thickness},
                 {"profile", drawn.flat->rounded_edges ? "stadium" : "rectangle"}};
  }
  j["material"] = {{"bending_stiffness", spec.material.bending_stiffness},
                   {"axial_stiffness", spec.material.axial_stiffness},
                   {"torsional_stiffness", spec.material.torsional_stiffness},
                   {"linear_density", spec.material.linear_density},
                   {"bending_ratio", spec.material.bending_ratio},
                   {"principal_angle", spec.material.principal_angle},
                   {"source", su.material_source},
                   {"defaulted", su.material_defaulted}};
  j["gravity"] = ToJson(spec.gravity);
  Json supports = Json::array();
  for (size_t k = 0; k < spec.supports.size(); ++k) {
    const SupportSpec& sp = spec.supports[k];
    Json s = {{"kind", ToString(sp.kind)},       {"s", sp.s},
              {"position", ToJson(sp.position)}, {"tangent", ToJson(sp.tangent.normalized())},
              {"sliding", sp.sliding},           {"origin", su.support_origin[k]}};
    // A clamp holds the section's orientation: its d1 (a flat cable's drawn wide axis).
    if (sp.kind == SupportKind::kClamp) s["normal"] = ToJson(sp.normal.normalized());
    if (k < res.solution.reactions.size()) {
      s["reaction"] = {{"force", ToJson(res.solution.reactions[k].force)},
                       {"moment", ToJson(res.solution.reactions[k].moment)}};
    }
    supports.push_back(s);
  }
  j["supports"] = supports;
  if (!su.junction.empty()) j["junction"] = su.junction;
  const Eigen::Index imax = std::min<Eigen::Index>(
      r.relaxed.size() - 1, static_cast<Eigen::Index>(std::lround(r.max_deviation_s / spec.length *
                                                                  (r.relaxed.size() - 1))));
  j["deviation"] = {
      {"max", r.max_deviation},
      {"rms", r.rms_deviation},
      {"max_at", {{"s", r.max_deviation_s}, {"point", ToJson(r.relaxed.points.col(imax))}}},
      {"measure", "distance of the relaxed centreline to the drawn route"},
      {"springback_max", r.springback_max ? Json(*r.springback_max) : Json(nullptr)},
      {"sag_max", r.sag_max ? Json(*r.sag_max) : Json(nullptr)},
      {"split", "springback: the set-up solved without gravity (the cable's own stiffness "
                "pulling it towards its natural shape), its largest distance to the drawn route; "
                "sag: the largest distance gravity adds to that shape at the same arc length"}};
  if (!r.split_note.empty()) j["deviation"]["split_note"] = r.split_note;
  const Polyline at =
      SampleCenterline(res.solution.centerline, Eigen::VectorXd::Constant(1, r.min_bend_radius_s));
  j["min_bend_radius"] = {{"radius", NumberOrNull(r.min_bend_radius)},
                          {"s", r.min_bend_radius_s},
                          {"point", ToJson(at.points.col(0))},
                          {"limit", r.bend_limit},
                          {"flag", r.bend_flag}};
  j["max_tension"] = {{"force", NumberOrNull(r.max_tension)}, {"s", r.max_tension_s}};
  Json stretches = Json::array();
  for (const CableRelaxation::Stretch& st : r.stretches) {
    stretches.push_back({{"from_s", st.s0}, {"to_s", st.s1}, {"chord", st.chord},
                         {"slack", st.slack}, {"taut", st.taut}});
  }
  j["stretches"] = stretches;
  j["taut"] = r.taut;
  j["taut_meaning"] = "a stretch between two position-holding supports has less than 0.5 % slack";
  j["twist_angle"] = NumberOrNull(res.solution.twist_angle);
  j["solver"] = {{"converged", res.converged},
                 {"stable", res.solution.summary.stable},
                 {"iterations", res.newton_iterations},
                 {"elements", res.level_elements.empty() ? 0 : res.level_elements.back()},
                 {"estimated_error", NumberOrNull(res.estimated_error)},
                 {"accuracy", res.accuracy},
                 {"accuracy_met", res.accuracy_met},
                 {"message", res.solution.summary.message},
                 {"seconds", r.seconds}};
  j["drawn_route"] = {{"points", su.route.size()},
                      {"fit_error", drawn.fit_error},
                      {"fit_error_meaning",
                       "how far the recovered centreline may be from the drawn one (chord "
                       "deviation of a curve's sampling, RMS circle-fit residual of a tube)"}};
  Json pts = Json::array();
  for (int i = 0; i < r.relaxed.size(); ++i) {
    pts.push_back(
        {r.relaxed.s[i], r.relaxed.points(0, i), r.relaxed.points(1, i), r.relaxed.points(2, i)});
  }
  j["relaxed_centreline"] = {{"columns", {"s", "x", "y", "z"}}, {"rows", pts}};
  j["notes"] = su.notes;
  return j;
}

}  // namespace cablefit::addin
