#include "cablefit/app/relax_tolerance.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "cablefit/app/relax_file.h"
#include "cablefit/app/relax_network.h"
#include "cablefit/app/report_html.h"
#include "cablefit/core/solver/centerline_sampling.h"

namespace cablefit::addin {
namespace {

// Points compared along the cable (relative arc length).
constexpr int kCompareSamples = 201;

void Solve(const CableRelaxation& nominal, const SimulationOptions& options, ToleranceCase* c) {
  const RodSpec& spec = nominal.setup.spec;
  const RodSpec varied = VariedSpec(spec, c->length, c->bending_stiffness, c->linear_density);
  RodSimulator sim(options);
  // From the nominal shape: the same branch, varied.
  const SimulationResult r = sim.Simulate(varied, &nominal.result.solution.centerline);
  c->converged = r.converged;
  if (!r.converged) return;
  const Polyline a = SampleCenterline(nominal.result.solution.centerline,
                                      UniformArcLengths(spec.length, kCompareSamples));
  const Polyline b =
      SampleCenterline(r.solution.centerline, UniformArcLengths(varied.length, kCompareSamples));
  const Eigen::VectorXd d = (a.points - b.points).colwise().norm();
  Eigen::Index k = 0;
  c->excursion = d.maxCoeff(&k);
  c->s = a.s[k];
  c->point = b.points.col(k);
  c->centreline = b;
}

}  // namespace

RodSpec VariedSpec(const RodSpec& spec, double length, double stiffness, double density) {
  RodSpec v = spec;
  const double f = 1.0 + length;
  v.length *= f;
  for (SupportSpec& sp : v.supports) sp.s *= f;
  for (PointLoadSpec& p : v.point_loads) p.s *= f;
  for (NaturalCurvatureSpec& n : v.natural_curvature) {
    n.s_start *= f;
    n.s_end *= f;
    n.ramp *= f;
  }
  v.material.bending_stiffness *= 1.0 + stiffness;
  v.material.torsional_stiffness *= 1.0 + stiffness;
  v.material.linear_density *= 1.0 + density;
  return v;
}

void RunFileTolerance(const HarnessConfig& config, const SimulationOptions& options,
                      RelaxedFile* f) {
  if (!config.tolerances) return;
  FileTolerance ft;
  ft.config = *config.tolerances;
  const ToleranceConfig& tc = ft.config;
  std::vector<RelaxGroup> groups;
  try {
    groups = GroupCables(f->drawing, SolidBoxes(f->drawing), config);
  } catch (const std::exception& e) {
    ft.problems.push_back(std::string("tolerances: ") + e.what());
  }
  // The corners: every sign combination of the varied quantities.
  const double amp[3] = {tc.length, tc.bending_stiffness, tc.linear_density};
  std::vector<std::array<double, 3>> corners = {{0, 0, 0}};
  for (int q = 0; q < 3; ++q) {
    if (amp[q] == 0) continue;
    std::vector<std::array<double, 3>> next;
    for (const auto& c : corners)
      for (double sign : {-1.0, 1.0}) {
        auto d = c;
        d[static_cast<size_t>(q)] = sign * amp[q];
        next.push_back(d);
      }
    corners = next;
  }
  for (size_t i = 0; i < f->cables.size(); ++i) {
    if (!f->cables[i]) continue;
    const CableRelaxation& nominal = *f->cables[i];
    bool network = false;
    for (const RelaxGroup& g : groups)
      if (g.network() && std::count(g.cables.begin(), g.cables.end(), static_cast<int>(i)) > 0)
        network = true;
    if (network) {
      ft.problems.push_back("tolerances: cable '" + nominal.setup.name +
                            "' is solved as a network (junction or contact): not varied yet");
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    CableTolerance ct;
    ct.cable = static_cast<int>(i);
    ct.name = nominal.setup.name;
    for (const auto& c : corners) {
      ToleranceCase tcase;
      tcase.length = c[0];
      tcase.bending_stiffness = c[1];
      tcase.linear_density = c[2];
      Solve(nominal, options, &tcase);
      ct.corners.push_back(tcase);
    }
    for (size_t k = 0; k < ct.corners.size(); ++k)
      if (ct.corners[k].converged &&
          (ct.worst_corner < 0 ||
           ct.corners[k].excursion > ct.corners[static_cast<size_t>(ct.worst_corner)].excursion))
        ct.worst_corner = static_cast<int>(k);
    // Interior check: fixed seed, so every run and thread count gives the same cases.
    std::mt19937 rng(25);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < kInteriorChecks; ++k) {
      const double a = u(rng), b = u(rng), c = u(rng);
      ToleranceCase tcase;
      tcase.length = a * tc.length;
      tcase.bending_stiffness = b * tc.bending_stiffness;
      tcase.linear_density = c * tc.linear_density;
      Solve(nominal, options, &tcase);
      ct.interior.push_back(tcase);
      const double worst =
          ct.worst_corner >= 0 ? ct.corners[static_cast<size_t>(ct.worst_corner)].excursion : 0.0;
      // Solver accuracy is the yardstick for "further".
      if (tcase.converged && tcase.excursion > worst + 10 * options.accuracy)
        ct.interior_within = false;
    }
    ct.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ft.cables.push_back(std::move(ct));
  }
  f->tolerance = std::move(ft);
}

namespace {

json::Json CaseJson(const ToleranceCase& c) {
  return {{"length", c.length},
          {"bending_stiffness", c.bending_stiffness},
          {"linear_density", c.linear_density},
          {"converged", c.converged},
          {"excursion", c.excursion},
          {"s", c.s},
          {"point", json::ToJson(c.point)}};
}

}  // namespace

json::Json CableToleranceToJson(const CableTolerance& t) {
  json::Json corners = json::Json::array(), interior = json::Json::array();
  for (const ToleranceCase& c : t.corners) corners.push_back(CaseJson(c));
  for (const ToleranceCase& c : t.interior) interior.push_back(CaseJson(c));
  json::Json j = {{"corners", corners},
                  {"interior_checks", interior},
                  {"interior_within_corners", t.interior_within},
                  {"seconds", t.seconds},
                  {"meaning",
                   "the cable solved at every corner of its tolerance box (signed fractions of "
                   "length, bending stiffness (EI and GJ) and linear density) from the nominal "
                   "shape; excursion [m] = largest distance to the nominal shape at the same "
                   "relative arc length, s on the nominal cable, point on the varied one; "
                   "interior_checks: pseudo-random points inside the box, to show the corners "
                   "bound it (interior_within_corners)"}};
  if (t.worst_corner >= 0) {
    const ToleranceCase& w = t.corners[static_cast<size_t>(t.worst_corner)];
    j["max_excursion"] = {{"excursion", w.excursion},
                          {"s", w.s},
                          {"point", json::ToJson(w.point)},
                          {"corner", t.worst_corner}};
  } else {
    j["max_excursion"] = nullptr;
  }
  return j;
}

std::vector<std::string> ToleranceLines(const FileTolerance& t) {
  std::vector<std::string> lines;
  for (const CableTolerance& c : t.cables) {
    char buf[512];
    if (c.worst_corner < 0) {
      std::snprintf(buf, sizeof buf, "tolerance: %s: no corner converged", c.name.c_str());
    } else {
      const ToleranceCase& w = c.corners[static_cast<size_t>(c.worst_corner)];
      std::snprintf(buf, sizeof buf,
                    "tolerance: %s: max excursion %.2f mm at s=%.0f mm (length %+.3g%%, EI %+.3g%%, "
                    "density %+.3g%%), %zu corners, %zu interior checks %s, %.3f s",
                    c.name.c_str(), 1e3 * w.excursion, 1e3 * w.s, 100 * w.length,
                    100 * w.bending_stiffness, 100 * w.linear_density, c.corners.size(),
                    c.interior.size(), c.interior_within ? "within" : "BEYOND THE CORNERS",
                    c.seconds);
    }
    lines.push_back(buf);
  }
  for (const std::string& p : t.problems) lines.push_back(p);
  return lines;
}

std::string ToleranceReportSection(const std::vector<RelaxedFile>& files) {
  std::ostringstream h;
  bool any = false;
  for (const RelaxedFile& f : files) {
    if (!f.tolerance) continue;
    if (!any) h << "<section class=\"card\"><h2>Tolerance envelope</h2><ul class=\"notes\">";
    any = true;
    for (const std::string& line : ToleranceLines(*f.tolerance))
      h << "<li>" << HtmlEscape(f.stem) << ": " << HtmlEscape(line) << "</li>";
  }
  if (!any) return "";
  h << "</ul><p>Per corner figures in the JSON's per-cable <code>tolerance</code>.</p></section>\n";
  return h.str();
}

}  // namespace cablefit::addin
