#include "cablefit/app/relax_tolerance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cablefit/app/relax_file.h"
#include "cablefit/app/relax_network.h"
#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/solver/centerline_sampling.h"
#include "tolerance_search.h"

namespace cablefit::addin {
namespace {

// Elements of a network's repeated solves at most (the motion sweep's figure).
constexpr int kToleranceElements = 2000;
// A fixing moves at most this share of the way to its neighbouring support or cable end: the
// supports keep their order and the cable between them some length.
constexpr double kClipShiftShare = 0.45;

// RodSpec and BranchSpec alike: length, the arc lengths of everything on the cable, material.
template <class Spec>
void Vary(double length, double stiffness, double density, Spec* v) {
  const double f = 1.0 + length;
  v->length *= f;
  for (SupportSpec& sp : v->supports) sp.s *= f;
  for (PointLoadSpec& p : v->point_loads) p.s *= f;
  for (SleeveSpec& sl : v->sleeves) {
    sl.s_begin *= f;
    sl.s_end *= f;
  }
  for (NaturalCurvatureSpec& n : v->natural_curvature) {
    n.s_start *= f;
    n.s_end *= f;
    n.ramp *= f;
  }
  v->material.bending_stiffness *= 1.0 + stiffness;
  v->material.torsional_stiffness *= 1.0 + stiffness;
  v->material.linear_density *= 1.0 + density;
}

// Which entry of eps varies what.
struct Layout {
  int length = -1, stiffness = -1, density = -1;
  struct Clip {
    int branch = 0, support = 0;
    double tolerance = 0.0;  // [m]
  };
  std::vector<Clip> clips;  // entries base, base + 1, ...
  int base = 0;
  int k() const { return base + static_cast<int>(clips.size()); }
};

Layout QuantityLayout(const ToleranceConfig& tc) {
  Layout lay;
  if (tc.length > 0) lay.length = lay.base++;
  if (tc.bending_stiffness > 0) lay.stiffness = lay.base++;
  if (tc.linear_density > 0) lay.density = lay.base++;
  return lay;
}

// The fixings between a cable's ends whose place on it varies (not sliding ones: the cable
// runs through those anyway), with the tolerance each can take; a line in `problems` for each
// one that takes less than asked.
void AddClips(const std::vector<SupportSpec>& supports, double length, int branch,
              const ToleranceConfig& tc, const std::string& cable, Layout* lay,
              std::vector<std::string>* problems) {
  if (tc.clip_position <= 0) return;
  std::vector<double> all = {0.0, length};
  for (const SupportSpec& sp : supports) all.push_back(sp.s);
  std::sort(all.begin(), all.end());
  const double end_gap = 1e-9 * std::max(1.0, length);
  for (size_t i = 0; i < supports.size(); ++i) {
    const SupportSpec& sp = supports[i];
    if (sp.sliding || sp.s <= end_gap || sp.s >= length - end_gap) continue;
    const auto at = std::lower_bound(all.begin(), all.end(), sp.s);
    const double before = sp.s - *std::prev(at), after = *std::next(at) - sp.s;
    const double room = kClipShiftShare * std::min(before, after);
    Layout::Clip c{branch, static_cast<int>(i), std::min(tc.clip_position, room)};
    if (c.tolerance <= 0) continue;
    if (c.tolerance < tc.clip_position) {
      char buf[300];
      std::snprintf(buf, sizeof buf,
                    "tolerances: cable '%s': the support at s=%.0f mm is shifted by +-%.1f mm "
                    "only: the next support or end is %.1f mm away",
                    cable.c_str(), 1e3 * sp.s, 1e3 * c.tolerance, 1e3 * std::min(before, after));
      problems->push_back(buf);
    }
    lay->clips.push_back(c);
  }
}

double Entry(const Eigen::VectorXd& eps, int q, double amplitude) {
  return q >= 0 ? eps[q] * amplitude : 0.0;
}

// The case a cable of branch `branch` reports for eps.
ToleranceCase Describe(const Layout& lay, const ToleranceConfig& tc, int branch,
                       const Eigen::VectorXd& eps) {
  ToleranceCase c;
  c.length = Entry(eps, lay.length, tc.length);
  c.bending_stiffness = Entry(eps, lay.stiffness, tc.bending_stiffness);
  c.linear_density = Entry(eps, lay.density, tc.linear_density);
  for (size_t i = 0; i < lay.clips.size(); ++i)
    if (lay.clips[i].branch == branch)
      c.clip_shift.push_back(eps[lay.base + static_cast<int>(i)] * lay.clips[i].tolerance);
  return c;
}

void ListClips(const Layout& lay, int branch, const std::vector<SupportSpec>& supports,
               const std::vector<std::string>& origins, CableTolerance* ct) {
  for (const Layout::Clip& c : lay.clips) {
    if (c.branch != branch) continue;
    ct->clip_s.push_back(supports[static_cast<size_t>(c.support)].s);
    ct->clip_tolerance.push_back(c.tolerance);
    ct->clip_origin.push_back(static_cast<size_t>(c.support) < origins.size()
                                  ? origins[static_cast<size_t>(c.support)]
                                  : std::string(ToString(supports[static_cast<size_t>(c.support)].kind)));
  }
}

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Every cable of a network group varied together; one CableTolerance per group cable.
std::vector<CableTolerance> NetworkTolerance(const RelaxedFile& f, const RelaxGroup& group,
                                             const std::vector<OrientedBox>& boxes,
                                             const HarnessConfig& config,
                                             const SimulationOptions& options,
                                             std::vector<std::string>* problems) {
  const auto t0 = std::chrono::steady_clock::now();
  const ToleranceConfig& tc = *config.tolerances;
  const std::string label = GroupLabel(f.drawing, group);
  std::vector<CableSetup> setups;
  const NetworkSpec spec = GroupNetworkSpec(f.drawing, group, boxes, config, &setups);
  Layout lay = QuantityLayout(tc);
  for (size_t b = 0; b < spec.branches.size(); ++b)
    AddClips(spec.branches[b].supports, spec.branches[b].length, static_cast<int>(b), tc,
             spec.branches[b].name, &lay, problems);
  // Nominal and varied set-ups at one of the relax's levels: their difference is the
  // tolerance's, the level's own error cancels (how large it is is reported).
  NetworkOptions o = PlanNetworkRelax(spec, options).options;
  const CableRelaxation& first = *f.cables[static_cast<size_t>(group.cables[0])];
  o.refinement = RepeatedSolveLevel(first.result.level_elements, kToleranceElements);
  for (int c : group.cables)
    o.initial_routes.push_back(f.cables[static_cast<size_t>(c)]->result.solution.centerline);
  NetworkSolution nominal = SolveNetwork(spec, o);
  if (!nominal.converged()) {
    o.initial_routes.clear();
    nominal = SolveNetwork(spec, o);
  }
  if (!nominal.converged()) {
    problems->push_back("tolerances: network " + label +
                        ": the nominal set-up did not converge at the tolerance level (" +
                        nominal.summary.message + "): not varied");
    return {};
  }
  auto solve = [&](const Eigen::VectorXd& eps, std::vector<Polyline>* shapes, std::string* why) {
    NetworkSpec v = VariedNetworkSpec(spec, Entry(eps, lay.length, tc.length),
                                      Entry(eps, lay.stiffness, tc.bending_stiffness),
                                      Entry(eps, lay.density, tc.linear_density));
    for (size_t i = 0; i < lay.clips.size(); ++i) {
      const Layout::Clip& c = lay.clips[i];
      v.branches[static_cast<size_t>(c.branch)].supports[static_cast<size_t>(c.support)].s +=
          eps[lay.base + static_cast<int>(i)] * c.tolerance;
    }
    NetworkOptions warm = o;
    warm.initial_routes = nominal.branches;
    warm.initial_normals = nominal.element_normals;
    NetworkSolution s = SolveNetwork(v, warm);
    if (!s.converged()) {
      *why = s.summary.message;
      return false;
    }
    *shapes = std::move(s.branches);
    return true;
  };
  const ToleranceSearch search = SearchToleranceBox(lay.k(), nominal.branches, solve);
  std::vector<CableTolerance> out;
  for (size_t b = 0; b < group.cables.size(); ++b) {
    const int branch = static_cast<int>(b);
    const CableRelaxation& relaxed = *f.cables[static_cast<size_t>(group.cables[b])];
    CableTolerance ct;
    ct.cable = group.cables[b];
    ct.name = relaxed.setup.name;
    ct.network = label;
    ct.elements = nominal.num_elements;
    ct.quantities = lay.k();
    ListClips(lay, branch, spec.branches[b].supports, setups[b].support_origin, &ct);
    const Polyline& level = nominal.branches[b];
    MeasureCases(search, branch, level, 10 * options.accuracy,
                 [&](const Eigen::VectorXd& eps) { return Describe(lay, tc, branch, eps); }, &ct);
    if (relaxed.relaxed.size() > 1) {
      const Polyline at = SampleCenterline(level, relaxed.relaxed.s);
      ct.resolution_error = (at.points - relaxed.relaxed.points).colwise().norm().maxCoeff();
    }
    out.push_back(std::move(ct));
  }
  const double seconds = Seconds(t0);
  for (CableTolerance& ct : out) ct.seconds = seconds;
  return out;
}

}  // namespace

RodSpec VariedSpec(const RodSpec& spec, double length, double stiffness, double density) {
  RodSpec v = spec;
  Vary(length, stiffness, density, &v);
  return v;
}

NetworkSpec VariedNetworkSpec(const NetworkSpec& spec, double length, double stiffness,
                              double density) {
  NetworkSpec v = spec;
  for (BranchSpec& b : v.branches) Vary(length, stiffness, density, &b);
  return v;
}

CableTolerance SingleCableTolerance(const CableRelaxation& nominal, const ToleranceConfig& tc,
                                    const SimulationOptions& options,
                                    std::vector<std::string>* problems) {
  const auto t0 = std::chrono::steady_clock::now();
  const RodSpec& spec = nominal.setup.spec;
  Layout lay = QuantityLayout(tc);
  AddClips(spec.supports, spec.length, 0, tc, nominal.setup.name, &lay, problems);
  CableTolerance ct;
  ct.cable = nominal.setup.cable;
  ct.name = nominal.setup.name;
  ct.quantities = lay.k();
  ListClips(lay, 0, spec.supports, nominal.setup.support_origin, &ct);
  const Polyline& start = nominal.result.solution.centerline;
  auto solve = [&](const Eigen::VectorXd& eps, std::vector<Polyline>* shapes, std::string* why) {
    RodSpec v = VariedSpec(spec, Entry(eps, lay.length, tc.length),
                           Entry(eps, lay.stiffness, tc.bending_stiffness),
                           Entry(eps, lay.density, tc.linear_density));
    for (size_t i = 0; i < lay.clips.size(); ++i)
      v.supports[static_cast<size_t>(lay.clips[i].support)].s +=
          eps[lay.base + static_cast<int>(i)] * lay.clips[i].tolerance;
    RodSimulator sim(options);
    // From the nominal shape: the same branch, varied.
    SimulationResult r = sim.Simulate(v, &start);
    if (!r.converged) {
      *why = r.solution.summary.message;
      return false;
    }
    shapes->assign(1, std::move(r.solution.centerline));
    return true;
  };
  const ToleranceSearch search = SearchToleranceBox(lay.k(), {start}, solve);
  MeasureCases(search, 0, start, 10 * options.accuracy,
               [&](const Eigen::VectorXd& eps) { return Describe(lay, tc, 0, eps); }, &ct);
  ct.seconds = Seconds(t0);
  return ct;
}

void RunFileTolerance(const HarnessConfig& config, const SimulationOptions& options,
                      RelaxedFile* f) {
  if (!config.tolerances) return;
  FileTolerance ft;
  ft.config = *config.tolerances;
  std::vector<RelaxGroup> groups;
  const std::vector<OrientedBox> boxes = SolidBoxes(f->drawing);
  try {
    groups = GroupCables(f->drawing, boxes, config);
  } catch (const std::exception& e) {
    ft.problems.push_back(std::string("tolerances: ") + e.what());
  }
  std::vector<char> in_network(f->cables.size(), 0);
  for (const RelaxGroup& g : groups) {
    if (!g.network()) continue;
    bool relaxed = true;
    for (int c : g.cables) {
      in_network[static_cast<size_t>(c)] = 1;
      if (!f->cables[static_cast<size_t>(c)] || !f->cables[static_cast<size_t>(c)]->ok())
        relaxed = false;
    }
    if (!relaxed) {
      ft.problems.push_back("tolerances: network " + GroupLabel(f->drawing, g) +
                            ": not relaxed, not varied");
      continue;
    }
    try {
      for (CableTolerance& ct : NetworkTolerance(*f, g, boxes, config, options, &ft.problems))
        ft.cables.push_back(std::move(ct));
    } catch (const std::exception& e) {
      ft.problems.push_back("tolerances: network " + GroupLabel(f->drawing, g) + ": " + e.what());
    }
  }
  for (size_t i = 0; i < f->cables.size(); ++i) {
    if (!f->cables[i] || in_network[i]) continue;
    if (!f->cables[i]->ok()) {
      ft.problems.push_back("tolerances: cable '" + f->cables[i]->setup.name +
                            "': not relaxed, not varied");
      continue;
    }
    CableTolerance ct = SingleCableTolerance(*f->cables[i], ft.config, options, &ft.problems);
    ct.cable = static_cast<int>(i);
    ft.cables.push_back(std::move(ct));
  }
  std::sort(ft.cables.begin(), ft.cables.end(),
            [](const CableTolerance& a, const CableTolerance& b) { return a.cable < b.cable; });
  f->tolerance = std::move(ft);
}

}  // namespace cablefit::addin
