#include "cablefit/app/relax/relax_network.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"
#include "cablefit/core/network/network_simulator.h"
#include "cablefit/app/base/batch_pool.h"
#include "relax/relax_route.h"

namespace cablefit::addin {
namespace {

// The network solved again without gravity, on one level (the split explains a deviation, it
// needs no extrapolated accuracy); a failure only leaves the split unknown.
void SplitSpringbackAndSag(const NetworkSpec& spec, const NetworkOptions& opt,
                           const NetworkSolution& loaded, GroupRelaxation* out) {
  const auto unknown = [&](const std::string& why) {
    for (CableRelaxation& r : out->cables) r.split_note = "not computed: " + why;
  };
  for (const CableRelaxation& r : out->cables)
    if (!r.result.converged) return unknown("the network did not converge");
  try {
    const NetworkSimulation sim = SimulateWithoutGravity(spec, opt, loaded.branches, loaded.element_normals);
    if (!sim.converged) return unknown("the solve without gravity did not converge");
    ParallelFor(static_cast<int>(out->cables.size()), UsableCores(), [&](int b) {
      MeasureSpringbackAndSag(sim.centerlines[static_cast<size_t>(b)], &out->cables[static_cast<size_t>(b)]);
    });
  } catch (const std::exception& e) {
    unknown(e.what());
  }
}

using json::Json;
using json::NumberOrNull;
using json::ToJson;

int Find(std::vector<int>& root, int i) {
  while (root[i] != i) i = root[i] = root[root[i]];
  return i;
}

// Solids a cable could touch: not one it passes through or ends in (clips, housings), and
// within reach of its route (a quarter of its length around its bounding box, enough for sag).
std::vector<int> ObstaclesNear(const HarnessDrawing& d, const std::vector<OrientedBox>& boxes,
                               int cable) {
  const Polyline& route = d.cables[cable].centreline;
  Eigen::AlignedBox3d reach;
  for (int i = 0; i < route.size(); ++i) reach.extend(Vec3(route.points.col(i)));
  const double margin = 0.25 * route.ChordLength();
  reach.min().array() -= margin;
  reach.max().array() += margin;
  std::vector<int> out;
  for (size_t k = 0; k < d.solids.size(); ++k) {
    const TriangleMesh& mesh = d.solids[k].mesh;
    if (mesh.faces.cols() == 0 || k >= boxes.size()) continue;
    bool inside = false;
    for (int i = 0; i < route.size() && !inside; ++i) inside = boxes[k].Contains(route.points.col(i));
    if (inside) continue;
    Eigen::AlignedBox3d box;
    for (int v = 0; v < mesh.vertices.cols(); ++v) box.extend(Vec3(mesh.vertices.col(v)));
    if (box.intersects(reach)) out.push_back(static_cast<int>(k));
  }
  return out;
}

int CableIndex(const HarnessDrawing& d, const std::string& name, const std::string& junction) {
  for (size_t c = 0; c < d.cables.size(); ++c)
    if (d.cables[c].name == name) return static_cast<int>(c);
  throw InvalidInput("harness.json junction '" + junction + "' names cable '" + name +
                     "', which the drawing does not have");
}

// A network's levels are each solved from the drawing (contact sets and all), so each costs a
// cold solve; the estimate falls about 16x per level on smooth shapes. At most four levels, and
// a third or fourth only while its element count stays within kMaxNetworkElements (a long
// harness's first level already has up to total length / 1 cm elements).
constexpr int kMaxNetworkLevels = 4;
constexpr double kMaxNetworkElements = 12000;

// Element frames (tangents only) of a node polyline, for the bend radius. d1 and d2 are not
// known here (NaN), so that nothing takes them for the material frame (WrittenWideAxes).
void FramesFromNodes(const Polyline& nodes, RodSolution* sol) {
  const int ne = nodes.size() - 1;
  sol->frame_s.resize(ne);
  sol->frames.resize(ne);
  const Vec3 unknown = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  for (int j = 0; j < ne; ++j) {
    sol->frame_s[j] = 0.5 * (nodes.s[j] + nodes.s[j + 1]);
    const Vec3 t = nodes.points.col(j + 1) - nodes.points.col(j);
    sol->frames[j].d1 = sol->frames[j].d2 = unknown;
    sol->frames[j].d3 = t.norm() > 0 ? Vec3(t.normalized()) : Vec3::UnitX();
  }
}

}  // namespace

std::string GroupLabel(const HarnessDrawing& drawing, const RelaxGroup& group) {
  std::string out;
  for (int c : group.cables) out += (out.empty() ? "" : ", ") + drawing.cables[c].name;
  return out;
}

std::vector<RelaxGroup> GroupCables(const HarnessDrawing& drawing,
                                    const std::vector<OrientedBox>& boxes,
                                    const HarnessConfig& config) {
  const int nc = static_cast<int>(drawing.cables.size());
  std::vector<RelaxGroup::Junction> junctions;
  // Declared junctions first; an end they use is not also part of a found one.
  std::vector<std::array<char, 2>> used(nc, {0, 0});
  for (const JunctionConfig& jc : config.junctions) {
    RelaxGroup::Junction j{jc.name, {}, jc.compliance, jc.mass, true};
    for (const JunctionConfig::End& e : jc.ends) {
      const int c = CableIndex(drawing, e.cable, jc.name);
      if (used[c][e.at_start ? 0 : 1])
        throw InvalidInput("harness.json junction '" + jc.name + "' uses the " +
                           (e.at_start ? "start" : "end") + " of cable '" + e.cable +
                           "', which another junction already joins");
      used[c][e.at_start ? 0 : 1] = 1;
      j.ends.push_back({c, e.at_start});
    }
    junctions.push_back(j);
  }
  int found = 0;
  for (const CableJunction& cj : drawing.junctions) {
    // Two ends that only touch are separate cables unless declared; a file's node joins them.
    if (cj.ends.size() < 3 && !cj.joined) continue;
    ++found;
    const std::string name = !cj.name.empty()      ? cj.name
                             : cj.ends.size() >= 3 ? "breakout " + std::to_string(found)
                                                   : "splice " + std::to_string(found);
    RelaxGroup::Junction j{name, {}, config.junction_compliance, config.junction_mass, false};
    for (const CableJunction::End& e : cj.ends)
      if (!used[e.cable][e.at_start ? 0 : 1]) j.ends.push_back(e);
    if (j.ends.size() >= 2) junctions.push_back(j);
  }
  std::vector<int> root(nc);
  std::iota(root.begin(), root.end(), 0);
  for (const RelaxGroup::Junction& j : junctions)
    for (const CableJunction::End& e : j.ends) root[Find(root, e.cable)] = Find(root, j.ends[0].cable);
  std::map<int, RelaxGroup> by_root;
  for (int c = 0; c < nc; ++c) by_root[Find(root, c)].cables.push_back(c);
  for (const RelaxGroup::Junction& j : junctions) by_root[Find(root, j.ends[0].cable)].junctions.push_back(j);
  std::vector<RelaxGroup> groups;
  for (auto& [r, g] : by_root) {
    std::vector<char> seen(drawing.solids.size(), 0);
    for (int c : g.cables)
      for (int k : ObstaclesNear(drawing, boxes, c)) seen[k] = 1;
    // A solid one group cable passes through is a clip of that cable, not an obstacle.
    for (int c : g.cables)
      for (size_t k = 0; k < drawing.solids.size() && k < boxes.size(); ++k)
        for (int i = 0; i < drawing.cables[c].centreline.size(); ++i)
          if (boxes[k].Contains(drawing.cables[c].centreline.points.col(i))) seen[k] = 0;
    for (size_t k = 0; k < seen.size(); ++k)
      if (seen[k]) g.obstacles.push_back(static_cast<int>(k));
    for (int c : g.cables) g.preformed |= !config.PreformedReason(drawing.cables[c].name).empty();
    groups.push_back(std::move(g));
  }
  return groups;
}

NetworkRelaxPlan PlanNetworkRelax(const NetworkSpec& spec, const SimulationOptions& options) {
  double total = 0.0;
  for (const BranchSpec& b : spec.branches) total += b.length;
  NetworkRelaxPlan out;
  out.options.statics = options.statics;
  // When the direct solve from the drawing fails, bring gravity in by continuation at once: the
  // supports already sit where the drawing has them, so continuing in their poses alone would
  // only repeat the failed solve (60 Newton iterations of a 183-segment harness).
  out.options.statics.ramp_loads = true;
  out.options.element_length = std::clamp(total / 1500, 0.002, 0.01);
  out.plan.accuracy = options.accuracy;
  out.plan.min_levels = 2;
  out.plan.max_levels = 2;
  out.plan.stop_when_out_of_reach = true;
  const double first_level_elements = total / out.options.element_length;
  while (out.plan.max_levels < kMaxNetworkLevels &&
         first_level_elements * (1 << out.plan.max_levels) <= kMaxNetworkElements)
    ++out.plan.max_levels;
  return out;
}

NetworkSimulation SimulateWithoutGravity(const NetworkSpec& spec, const NetworkOptions& options,
                                         const std::vector<Polyline>& loaded,
                                         const std::vector<Eigen::Matrix3Xd>& loaded_normals) {
  NetworkSpec weightless = spec;
  weightless.gravity = Vec3::Zero();
  RefinementPlan plan;
  plan.min_levels = plan.max_levels = 1;
  NetworkOptions opt = options;
  opt.refinement = 0;
  opt.initial_routes = loaded;
  opt.initial_normals = loaded_normals;
  return SimulateNetwork(weightless, plan, opt);
}

int RepeatedSolveLevel(const std::vector<int>& level_elements) {
  constexpr int kMaxElements = 2000;
  int level = 0;
  for (size_t k = 1; k < level_elements.size() && level_elements[k] <= kMaxElements; ++k)
    level = static_cast<int>(k);
  return level;
}

NetworkSpec GroupNetworkSpec(const HarnessDrawing& drawing, const RelaxGroup& group,
                             const std::vector<OrientedBox>& boxes, const HarnessConfig& config,
                             std::vector<CableSetup>* setups) {
  const int nb = static_cast<int>(group.cables.size());
  std::map<int, int> branch_of;
  for (int b = 0; b < nb; ++b) branch_of[group.cables[b]] = b;
  NetworkSpec spec;
  spec.name = GroupLabel(drawing, group);
  std::vector<JunctionEnds> ends(static_cast<size_t>(nb));
  for (const RelaxGroup::Junction& j : group.junctions)
    for (const CableJunction::End& e : j.ends) {
      JunctionEnds& at = ends[static_cast<size_t>(branch_of[e.cable])];
      (e.at_start ? at.start : at.end) = true;
      at.description = "solved as one network with the cables it meets at " + j.name;
    }
  // Each cable's set-up (its drawn route's frames, supports) is its own: on every core.
  setups->assign(static_cast<size_t>(nb), CableSetup{});
  ParallelFor(nb, UsableCores(), [&](int b) {
    (*setups)[static_cast<size_t>(b)] =
        SetUpCable(drawing, group.cables[static_cast<size_t>(b)], boxes, config, ends[static_cast<size_t>(b)]);
  });
  for (int b = 0; b < nb; ++b) {
    const CableSetup& su = (*setups)[static_cast<size_t>(b)];
    BranchSpec br;
    br.name = su.name;
    br.length = su.spec.length;
    br.material = su.spec.material;
    br.sleeves = su.spec.sleeves;
    br.supports = su.spec.supports;
    br.route = su.route;
    br.preformed = !config.PreformedReason(su.name).empty();
    spec.gravity = su.spec.gravity;
    spec.branches.push_back(br);
  }
  for (const RelaxGroup::Junction& j : group.junctions) {
    spec.junctions.push_back({j.name, j.compliance, j.mass});
    const int ji = static_cast<int>(spec.junctions.size()) - 1;
    for (const CableJunction::End& e : j.ends)
      (e.at_start ? spec.branches[branch_of[e.cable]].start_junction
                  : spec.branches[branch_of[e.cable]].end_junction) = ji;
  }
  for (int k : group.obstacles) spec.obstacles.push_back({drawing.solids[k].name, drawing.solids[k].mesh});
  return spec;
}

RodSolution BranchSolution(const NetworkSpec& spec, const NetworkSolution& solution, int branch) {
  RodSolution out;
  out.summary = solution.summary;
  out.centerline = solution.branches[static_cast<size_t>(branch)];
  FramesFromNodes(out.centerline, &out);
  out.internal_force = solution.internal_force[static_cast<size_t>(branch)];
  out.twist_angle = std::numeric_limits<double>::quiet_NaN();
  size_t first = 0;
  for (int k = 0; k < branch; ++k) first += spec.branches[static_cast<size_t>(k)].supports.size();
  for (size_t k = 0; k < spec.branches[static_cast<size_t>(branch)].supports.size(); ++k)
    out.reactions.push_back(solution.reactions[first + k]);
  return out;
}

// Long because it is one recipe over shared state (spec, plan, levels, the finest solution):
// solve, measure each branch, split springback and sag, then the notes and the group's JSON.
GroupRelaxation RelaxNetworkGroup(const HarnessDrawing& drawing, const RelaxGroup& group,
                                  const std::vector<OrientedBox>& boxes,
                                  const HarnessConfig& config, const SimulationOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const int nb = static_cast<int>(group.cables.size());
  std::map<int, int> branch_of;
  for (int b = 0; b < nb; ++b) branch_of[group.cables[b]] = b;
  std::vector<CableSetup> setups;
  const NetworkSpec spec = GroupNetworkSpec(drawing, group, boxes, config, &setups);

  // Refined until the estimate meets the accuracy, as a single cable is (SimulateNetwork).
  double min_d = std::numeric_limits<double>::infinity();
  for (const BranchSpec& b : spec.branches) min_d = std::min(min_d, b.material.diameter);
  const NetworkRelaxPlan planned = PlanNetworkRelax(spec, options);
  const NetworkOptions& opt = planned.options;
  const RefinementPlan& plan = planned.plan;
  const NetworkSimulation sim = SimulateNetwork(spec, plan, opt);
  const NetworkSolution& fine = sim.finest;
  const bool converged = sim.converged;
  const double error = sim.estimated_error;
  GroupRelaxation out;
  const auto measured = std::chrono::steady_clock::now();
  out.cables.resize(static_cast<size_t>(nb));
  ParallelFor(nb, UsableCores(), [&](int b) {
    CableRelaxation& r = out.cables[static_cast<size_t>(b)];
    r.setup = setups[static_cast<size_t>(b)];
    SimulationResult& res = r.result;
    res.converged = converged;
    res.newton_iterations = sim.newton_iterations;
    res.level_elements = sim.level_elements;
    res.solution = BranchSolution(spec, fine, b);
    res.solution.centerline = sim.centerlines[static_cast<size_t>(b)];  // extrapolated; frames of the finest level
    MeasureRelaxation(config.min_bend_radius_factor, &r);
  });
  SplitSpringbackAndSag(spec, opt, fine, &out);
  const double measure_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - measured).count();
  for (CableRelaxation& r : out.cables) r.measure_seconds = measure_seconds;
  // Contact is held at nodes: over a sharp edge the stretch between two nodes can cut the
  // corner. Said on every cable in contact rather than hidden in max_penetration.
  if (fine.max_penetration > 0.01 * min_d) {
    char note[256];
    std::snprintf(note, sizeof note,
                  "contact is held at nodes: between two of them the cable cuts up to %.2f mm "
                  "(%.0f %% of the thinnest diameter) into a solid, e.g. over a sharp edge",
                  fine.max_penetration * 1e3, 100 * fine.max_penetration / min_d);
    std::vector<char> touching(out.cables.size(), 0);
    for (const ContactLoad& c : fine.contacts)
      if (c.branch >= 0 && c.branch < static_cast<int>(touching.size())) touching[c.branch] = 1;
    for (size_t b = 0; b < out.cables.size(); ++b)
      if (touching[b]) out.cables[b].setup.notes.push_back(note);
  }
  for (int k : fine.attached_obstacles) {
    const std::string note = "solid '" + drawing.solids[group.obstacles[k]].name +
                             "': the drawing runs the cable into it, so it is taken as the part "
                             "the cable is fitted to there (a flange, a connector), not as a "
                             "surface it can rest on";
    for (CableRelaxation& r : out.cables) r.setup.notes.push_back(note);
  }
  if (!sim.refinement_failure.empty()) {
    const std::string note = "a finer discretisation than the " +
                             std::to_string(sim.level_elements.back()) +
                             " elements used did not converge (" + sim.refinement_failure +
                             "), so the result comes from the coarser ones";
    for (CableRelaxation& r : out.cables) r.setup.notes.push_back(note);
  }
  for (CableRelaxation& r : out.cables) {
    r.result.estimated_error = error;
    r.result.accuracy_met = converged && error <= std::max(options.accuracy, 1e-4 * min_d);
    r.result.accuracy = options.accuracy;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (CableRelaxation& r : out.cables) r.seconds = seconds;

  Json cables = Json::array();
  for (int c : group.cables) cables.push_back(drawing.cables[c].name);
  Json junctions = Json::array();
  for (size_t j = 0; j < spec.junctions.size() && j < fine.junctions.size(); ++j) {
    const JunctionLoads& jl = fine.junctions[j];
    Json loads = Json::array();
    for (size_t k = 0; k < jl.force.size(); ++k)
      loads.push_back({{"cable", drawing.cables[group.cables[jl.branch[k]]].name},
                       {"end", jl.branch_end[k] == 0 ? "start" : "end"},
                       {"force", ToJson(jl.force[k])},
                       {"moment", ToJson(jl.moment[k])}});
    const int any_branch = branch_of[group.junctions[j].ends[0].cable];
    const bool at_start = group.junctions[j].ends[0].at_start;
    const Polyline& p = fine.branches[any_branch];
    junctions.push_back({{"name", group.junctions[j].name},
                         {"declared", group.junctions[j].declared},
                         {"position", ToJson(at_start ? Vec3(p.points.col(0)) : Vec3(p.points.rightCols<1>()))},
                         {"branch_loads", loads},
                         {"force_residual", jl.force_residual.norm()},
                         {"moment_residual", jl.moment_residual.norm()},
                         {"compliance", group.junctions[j].compliance},
                         {"mass", group.junctions[j].mass}});
  }
  Json contacts = Json::array();
  for (const ContactLoad& c : fine.contacts)
    contacts.push_back({{"cable", drawing.cables[group.cables[c.branch]].name},
                        {"s", c.s},
                        {"solid", drawing.solids[group.obstacles[c.obstacle]].name},
                        {"point", ToJson(c.point)},
                        {"force", ToJson(c.force)}});
  // What each level cost, so a slow harness shows where its time went.
  auto level_json = [](int elements, const StaticsSummary& sum) {
    return Json{{"elements", elements},
                {"iterations", sum.iterations},
                {"continuation_steps", sum.continuation_steps},
                {"seconds", sum.seconds}};
  };
  Json levels = Json::array();
  for (size_t l = 0; l < sim.level_summaries.size() && l < sim.level_elements.size(); ++l)
    levels.push_back(level_json(sim.level_elements[l], sim.level_summaries[l]));
  out.json = {{"cables", cables},
              {"junctions", junctions},
              {"contacts", contacts},
              {"max_penetration", fine.max_penetration},
              {"elements", fine.num_elements},
              {"converged", converged},
              {"stable", fine.summary.stable},
              {"estimated_error", NumberOrNull(error)},
              {"levels", levels},
              {"coarse_start", level_json(sim.coarse_start_elements, sim.coarse_start)},
              {"message", fine.summary.message},
              {"seconds", seconds}};
  return out;
}

std::vector<OrientedBox> SolidBoxes(const HarnessDrawing& drawing) {
  std::vector<OrientedBox> boxes;
  for (const DrawnSolid& s : drawing.solids) {
    OrientedBox box;  // a solid without tessellation holds nothing (empty box)
    if (s.mesh.vertices.cols() > 0) box = BoundingBoxOf(s.mesh);
    boxes.push_back(box);
  }
  return boxes;
}

namespace {

// A network that did not converge as one: each of its cables relaxed on its own, with the ends
// it has at junctions clamped where the drawing has them (the other cables hold a junction
// there), so one stretch that cannot be solved leaves every other with a result.
void RelaxCablesOneByOne(const HarnessDrawing& drawing, const RelaxGroup& group,
                         const std::vector<OrientedBox>& boxes, const HarnessConfig& config,
                         const SimulationOptions& options, std::string why,
                         GroupOutcome* out) {
  // `why` by value: the caller's reason may be a message of one of the cables cleared here.
  out->cables.clear();
  const size_t n = group.cables.size();
  const std::string note = "the network of " + std::to_string(n) + (n == 1 ? " cable" : " cables") +
                           " did not converge as one (" + why +
                           "): relaxed on its own, its ends at junctions held as drawn";
  for (int c : group.cables) {
    try {
      CableSetup setup = SetUpCable(drawing, c, boxes, config);
      setup.notes.push_back(note);
      CableRelaxation r = RelaxCable(std::move(setup), options, config.min_bend_radius_factor);
      out->measure_seconds += r.measure_seconds;
      if (r.result.converged) {
        out->cables.push_back(std::move(r));
      } else {
        out->cable_problems.emplace_back(
            c, "the solver did not converge: " + r.result.solution.summary.message);
      }
    } catch (const Cancelled&) {
      throw;
    } catch (...) {
      out->cable_problems.emplace_back(c, ErrorText(std::current_exception()));
    }
  }
}

}  // namespace

GroupOutcome RelaxGroupCables(const HarnessDrawing& drawing, const RelaxGroup& group,
                              const std::vector<OrientedBox>& boxes, const HarnessConfig& config,
                              const SimulationOptions& options) {
  GroupOutcome out;
  try {
    if (group.network()) {
      GroupRelaxation g;
      try {
        g = RelaxNetworkGroup(drawing, group, boxes, config, options);
      } catch (const Cancelled&) {
        throw;
      } catch (...) {
        // A network that cannot even be set up (a branch too short to join two supports) is
        // still a set of cables that can each be tried alone.
        RelaxCablesOneByOne(drawing, group, boxes, config, options,
                            ErrorText(std::current_exception()), &out);
        return out;
      }
      out.cables = std::move(g.cables);
      out.network = std::move(g.json);
      if (!out.cables.empty()) out.measure_seconds = out.cables.front().measure_seconds;
      for (const CableRelaxation& r : out.cables) {
        if (r.result.converged) continue;
        RelaxCablesOneByOne(drawing, group, boxes, config, options,
                            r.result.solution.summary.message, &out);
        return out;
      }
    } else {
      CableSetup setup = SetUpCable(drawing, group.cables.front(), boxes, config);
      out.cables.push_back(RelaxCable(std::move(setup), options, config.min_bend_radius_factor));
      out.measure_seconds = out.cables.back().measure_seconds;
    }
    for (const CableRelaxation& r : out.cables)
      if (!r.result.converged && out.problem.empty())
        out.problem = "the solver did not converge: " + r.result.solution.summary.message;
  } catch (...) {
    out.problem = ErrorText(std::current_exception());
  }
  return out;
}

}  // namespace cablefit::addin
