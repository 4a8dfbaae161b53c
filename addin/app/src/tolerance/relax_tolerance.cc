#include "cablefit/app/tolerance/relax_tolerance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cablefit/app/relax/relax_network.h"
#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/solver/centerline_sampling.h"
#include "tolerance/tolerance_search.h"

namespace cablefit::addin {
namespace {

// A fixing moves at most this share of the way to its neighbouring support or cable end: the
// supports keep their order and the cable between them some length.
constexpr double kClipShiftShare = 0.45;
// ... and at most this share of the slack of the cable it shortens (half of it shared with a
// neighbour that moves too): an inextensible cable pulled nearly taut is a corner the solver
// may not reach, and a harness nobody would build.
constexpr double kClipSlackShare = 0.5;

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
    double back = 0.0, ahead = 0.0;  // [m] the shift towards smaller s and towards larger s
    double Shift(double e) const { return e >= 0 ? e * ahead : e * back; }
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

bool Varied(const BranchSpec& b, size_t i) {
  const SupportSpec& sp = b.supports[i];
  const double end_gap = 1e-9 * std::max(1.0, b.length);
  return !sp.sliding && sp.s > end_gap && sp.s < b.length - end_gap;
}

// A support that holds the cable on one side of a fixing: the cable between them [m], where
// it is, whether it is a fixing that moves too.
struct Neighbour {
  double arc = 0.0;
  Vec3 position = Vec3::Zero();
  bool moves = false;
};

// The first supports reached from junction `j` along every branch but `from` (through
// junctions with bare branches between them), `arc` [m] of cable already behind.
void ThroughJunction(const NetworkSpec& net, int j, int from, double arc, std::vector<char>* seen,
                     std::vector<Neighbour>* out) {
  if (j < 0 || (*seen)[static_cast<size_t>(j)]) return;
  (*seen)[static_cast<size_t>(j)] = 1;
  for (size_t b = 0; b < net.branches.size(); ++b) {
    if (static_cast<int>(b) == from) continue;
    const BranchSpec& br = net.branches[b];
    const size_t n = br.supports.size();
    if (br.start_junction == j) {
      if (n > 0)
        out->push_back({arc + br.supports[0].s, br.supports[0].position, Varied(br, 0)});
      else
        ThroughJunction(net, br.end_junction, static_cast<int>(b), arc + br.length, seen, out);
    }
    if (br.end_junction == j) {
      if (n > 0)
        out->push_back({arc + br.length - br.supports[n - 1].s, br.supports[n - 1].position,
                        Varied(br, n - 1)});
      else
        ThroughJunction(net, br.start_junction, static_cast<int>(b), arc + br.length, seen, out);
    }
  }
}

// How far a fixing at `at` can move into the cable towards its neighbours on one side: `share`
// (of the shorter cable on either side: the supports keep their order, neither side doubles),
// and no more than half the slack of the cable it shortens to each neighbour (its length at
// the shortest length tolerance, less the two supports' distance; through junctions too),
// half of that again when the neighbour moves as well: a fixing taped further towards a
// connector than a straight (taut) stretch allows cannot be mounted, and every corner with it
// would be a harness that cannot be built.
double Room(double share, const Vec3& at, const std::vector<Neighbour>& side,
            const ToleranceConfig& tc) {
  double room = share;
  for (const Neighbour& n : side) {
    const double slack = std::max(0.0, (1.0 - tc.length) * n.arc - (at - n.position).norm());
    room = std::min(room, (n.moves ? 0.5 : 1.0) * kClipSlackShare * slack);
  }
  return room;
}

// The fixings between branch `b`'s ends whose place on it varies (not sliding ones: the cable
// runs through those anyway), with the range each can take; a line in `problems` for each one
// that takes less than asked.
void AddClips(const NetworkSpec& net, int b, const ToleranceConfig& tc, Layout* lay,
              std::vector<std::string>* problems) {
  if (tc.clip_position <= 0) return;
  const BranchSpec& br = net.branches[static_cast<size_t>(b)];
  const std::vector<SupportSpec>& supports = br.supports;
  // Supports are in increasing s (the rod and network specs require it).
  for (size_t i = 0; i < supports.size(); ++i) {
    if (!Varied(br, i)) continue;
    const SupportSpec& sp = supports[i];
    std::vector<Neighbour> before, after;
    std::vector<char> seen(net.junctions.size(), 0);
    if (i > 0)
      before.push_back({sp.s - supports[i - 1].s, supports[i - 1].position, Varied(br, i - 1)});
    else
      ThroughJunction(net, br.start_junction, b, sp.s, &seen, &before);
    if (i + 1 < supports.size())
      after.push_back({supports[i + 1].s - sp.s, supports[i + 1].position, Varied(br, i + 1)});
    else
      ThroughJunction(net, br.end_junction, b, br.length - sp.s, &seen, &after);
    const double arc_prev = i > 0 ? sp.s - supports[i - 1].s : sp.s;
    const double arc_next = i + 1 < supports.size() ? supports[i + 1].s - sp.s : br.length - sp.s;
    const double share = kClipShiftShare * std::min(arc_prev, arc_next);
    Layout::Clip c{b, static_cast<int>(i), 0.0, 0.0};
    c.back = std::min(tc.clip_position, Room(share, sp.position, before, tc));
    c.ahead = std::min(tc.clip_position, Room(share, sp.position, after, tc));
    if (c.back < tc.clip_position || c.ahead < tc.clip_position) {
      // Why, side by side: short (the share of the shorter cable) or nearly taut (its slack).
      auto reason = [&](double room) { return room < share ? "is nearly taut" : "is short"; };
      std::string why;
      if (c.back < tc.clip_position) why = std::string("the cable before it ") + reason(c.back);
      if (c.ahead < tc.clip_position)
        why += (why.empty() ? "the cable " : ", ") + std::string("after it ") + reason(c.ahead);
      char buf[400];
      if (c.back <= 0 && c.ahead <= 0)
        std::snprintf(buf, sizeof buf,
                      "tolerances: cable '%s': the support at s=%.0f mm is not shifted: %s",
                      br.name.c_str(), 1e3 * sp.s, why.c_str());
      else
        std::snprintf(buf, sizeof buf,
                      "tolerances: cable '%s': the support at s=%.0f mm is shifted by -%.1f/+%.1f "
                      "mm only: %s",
                      br.name.c_str(), 1e3 * sp.s, 1e3 * c.back, 1e3 * c.ahead, why.c_str());
      problems->push_back(buf);
    }
    if (c.back <= 0 && c.ahead <= 0) continue;
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
      c.clip_shift.push_back(lay.clips[i].Shift(eps[lay.base + static_cast<int>(i)]));
  return c;
}

void ListClips(const Layout& lay, int branch, const std::vector<SupportSpec>& supports,
               const std::vector<std::string>& origins, CableTolerance* ct) {
  for (const Layout::Clip& c : lay.clips) {
    if (c.branch != branch) continue;
    const size_t k = static_cast<size_t>(c.support);
    ct->clip_s.push_back(supports[k].s);
    ct->clip_range.push_back({-c.back, c.ahead});
    ct->clip_origin.push_back(k < origins.size() ? origins[k]
                                                 : std::string(ToString(supports[k].kind)));
  }
}

// The nominal shape as the start of a varied set-up whose supports hold the cable at other arc
// lengths: its points re-labelled by the piecewise-linear map taking each nominal support's arc
// length (and both ends) to the varied one's, so every support starts where it is held. A plain
// nominal start puts a fixing shifted by 20 mm 20 mm off its clip, more than Newton recovers
// from next to a nearly taut stretch.
Polyline RemappedStart(const Polyline& nominal, const std::vector<SupportSpec>& from, double from_length,
                       const std::vector<SupportSpec>& to, double to_length) {
  std::vector<double> a = {0.0}, b = {0.0};
  for (size_t i = 0; i < from.size() && i < to.size(); ++i) {
    if (from[i].s <= a.back() || to[i].s <= b.back() || from[i].s >= from_length ||
        to[i].s >= to_length)
      continue;
    a.push_back(from[i].s);
    b.push_back(to[i].s);
  }
  a.push_back(from_length);
  b.push_back(to_length);
  Polyline out = nominal;
  const double scale = from_length / std::max(1e-300, nominal.s[nominal.size() - 1] - nominal.s[0]);
  size_t k = 0;
  for (Eigen::Index j = 0; j < out.s.size(); ++j) {
    const double x = (nominal.s[j] - nominal.s[0]) * scale;
    while (k + 2 < a.size() && x > a[k + 1]) ++k;
    const double t = std::clamp((x - a[k]) / (a[k + 1] - a[k]), 0.0, 1.0);
    out.s[j] = b[k] + t * (b[k + 1] - b[k]);
  }
  return out;
}

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Long: the network's solve closure, the search and the per-branch measurement share the
// layout and the nominal shapes.
// Every cable of a network group varied together; one CableTolerance per group cable.
std::vector<CableTolerance> NetworkTolerance(const RelaxedHarness& f, const RelaxGroup& group,
                                             const std::vector<OrientedBox>& boxes,
                                             const HarnessConfig& config,
                                             const SimulationOptions& options, int threads,
                                             std::vector<std::string>* problems) {
  const auto t0 = std::chrono::steady_clock::now();
  const ToleranceConfig& tc = *config.tolerances;
  const std::string label = GroupLabel(f.drawing, group);
  std::vector<CableSetup> setups;
  const NetworkSpec spec = GroupNetworkSpec(f.drawing, group, boxes, config, &setups);
  Layout lay = QuantityLayout(tc);
  for (size_t b = 0; b < spec.branches.size(); ++b)
    AddClips(spec, static_cast<int>(b), tc, &lay, problems);
  // Nominal and varied set-ups at one of the relax's levels: their difference is the
  // tolerance's, the level's own error cancels (how large it is is reported).
  NetworkOptions o = PlanNetworkRelax(spec, options).options;
  const CableRelaxation& first = *f.cables[static_cast<size_t>(group.cables[0])];
  o.refinement = RepeatedSolveLevel(first.result.level_elements);
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
  auto varied = [&](const Eigen::VectorXd& eps) {
    NetworkSpec v = VariedNetworkSpec(spec, Entry(eps, lay.length, tc.length),
                                      Entry(eps, lay.stiffness, tc.bending_stiffness),
                                      Entry(eps, lay.density, tc.linear_density));
    for (size_t i = 0; i < lay.clips.size(); ++i) {
      const Layout::Clip& c = lay.clips[i];
      v.branches[static_cast<size_t>(c.branch)].supports[static_cast<size_t>(c.support)].s +=
          c.Shift(eps[lay.base + static_cast<int>(i)]);
    }
    return v;
  };
  auto solve = [&](const Eigen::VectorXd& eps, const Eigen::VectorXd& from,
                   const std::vector<Polyline>& start, std::vector<Polyline>* shapes,
                   std::string* why) {
    const NetworkSpec v = varied(eps), u = varied(from);
    NetworkOptions warm = o;
    for (size_t b = 0; b < v.branches.size(); ++b)
      warm.initial_routes.push_back(RemappedStart(start[b], u.branches[b].supports,
                                                  u.branches[b].length, v.branches[b].supports,
                                                  v.branches[b].length));
    // The nominal twist (read at the same relative arc length): close enough for a start.
    warm.initial_normals = nominal.element_normals;
    NetworkSolution s = SolveNetwork(v, warm);
    if (!s.converged()) {
      *why = s.summary.message;
      return false;
    }
    *shapes = std::move(s.branches);
    return true;
  };
  const ToleranceSearch search = SearchToleranceBox(lay.k(), nominal.branches, solve, threads);
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
                                    std::vector<std::string>* problems, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  const RodSpec& spec = nominal.setup.spec;
  Layout lay = QuantityLayout(tc);
  NetworkSpec alone;  // the cable as a network of one branch, free or held at its ends
  alone.branches.resize(1);
  alone.branches[0].name = nominal.setup.name;
  alone.branches[0].length = spec.length;
  alone.branches[0].supports = spec.supports;
  AddClips(alone, 0, tc, &lay, problems);
  CableTolerance ct;
  ct.cable = nominal.setup.cable;
  ct.name = nominal.setup.name;
  ct.quantities = lay.k();
  ListClips(lay, 0, spec.supports, nominal.setup.support_origin, &ct);
  const Polyline& start = nominal.result.solution.centerline;
  auto varied = [&](const Eigen::VectorXd& eps) {
    RodSpec v = VariedSpec(spec, Entry(eps, lay.length, tc.length),
                           Entry(eps, lay.stiffness, tc.bending_stiffness),
                           Entry(eps, lay.density, tc.linear_density));
    for (size_t i = 0; i < lay.clips.size(); ++i)
      v.supports[static_cast<size_t>(lay.clips[i].support)].s +=
          lay.clips[i].Shift(eps[lay.base + static_cast<int>(i)]);
    return v;
  };
  auto solve = [&](const Eigen::VectorXd& eps, const Eigen::VectorXd& from,
                   const std::vector<Polyline>& shape, std::vector<Polyline>* shapes,
                   std::string* why) {
    const RodSpec v = varied(eps), u = varied(from);
    RodSimulator sim(options);
    const Polyline begin = RemappedStart(shape[0], u.supports, u.length, v.supports, v.length);
    SimulationResult r = sim.Simulate(v, &begin);
    if (!r.converged) {
      *why = r.solution.summary.message;
      return false;
    }
    shapes->assign(1, std::move(r.solution.centerline));
    return true;
  };
  const ToleranceSearch search = SearchToleranceBox(lay.k(), {start}, solve, threads);
  MeasureCases(search, 0, start, 10 * options.accuracy,
               [&](const Eigen::VectorXd& eps) { return Describe(lay, tc, 0, eps); }, &ct);
  ct.seconds = Seconds(t0);
  return ct;
}

std::optional<FileTolerance> VaryHarnessTolerances(const HarnessConfig& config,
                                                   const SimulationOptions& options,
                                                   const RelaxedHarness& h, int threads) {
  if (!config.tolerances) return std::nullopt;
  FileTolerance ft;
  ft.config = *config.tolerances;
  std::vector<RelaxGroup> groups;
  const std::vector<OrientedBox> boxes = SolidBoxes(h.drawing);
  try {
    groups = GroupCables(h.drawing, boxes, config);
  } catch (const std::exception& e) {
    ft.problems.push_back(std::string("tolerances: ") + e.what());
  }
  std::vector<char> in_network(h.cables.size(), 0);
  for (const RelaxGroup& g : groups) {
    if (!g.network()) continue;
    bool relaxed = true;
    for (int c : g.cables) {
      in_network[static_cast<size_t>(c)] = 1;
      if (!h.cables[static_cast<size_t>(c)] || !h.cables[static_cast<size_t>(c)]->ok())
        relaxed = false;
    }
    if (!relaxed) {
      ft.problems.push_back("tolerances: network " + GroupLabel(h.drawing, g) +
                            ": not relaxed, not varied");
      continue;
    }
    try {
      for (CableTolerance& ct : NetworkTolerance(h, g, boxes, config, options, threads, &ft.problems))
        ft.cables.push_back(std::move(ct));
    } catch (const std::exception& e) {
      ft.problems.push_back("tolerances: network " + GroupLabel(h.drawing, g) + ": " + e.what());
    }
  }
  for (size_t i = 0; i < h.cables.size(); ++i) {
    if (!h.cables[i] || in_network[i]) continue;
    if (!h.cables[i]->ok()) {
      ft.problems.push_back("tolerances: cable '" + h.cables[i]->setup.name +
                            "': not relaxed, not varied");
      continue;
    }
    CableTolerance ct = SingleCableTolerance(*h.cables[i], ft.config, options, &ft.problems, threads);
    ct.cable = static_cast<int>(i);
    ft.cables.push_back(std::move(ct));
  }
  std::sort(ft.cables.begin(), ft.cables.end(),
            [](const CableTolerance& a, const CableTolerance& b) { return a.cable < b.cable; });
  return ft;
}

}  // namespace cablefit::addin
