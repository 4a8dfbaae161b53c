#include "cablefit/app/relax_motion.h"

#include <fnmatch.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

#include "cablefit/app/relax_clearance.h"
#include "cablefit/app/relax_file.h"
#include "cablefit/app/relax_motion_pictures.h"
#include "cablefit/app/relax_network.h"
#include "cablefit/app/report_html.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/solver/motion_sweep.h"
#include "relax_motion_network.h"

namespace cablefit::addin {
namespace {

using json::Json;
using Clock = std::chrono::steady_clock;

// Points of each pose's shape in the JSON: enough to draw it, few enough for 100s of poses.
constexpr int kPoseShapeSamples = 51;

// Parameter as the user wrote it: degrees for a rotation, metres for a translation.
double Shown(const MotionConfig& m, double q) {
  return m.kind == MotionConfig::Kind::kRotation ? q * 180 / M_PI : q;
}
const char* ShownUnit(const MotionConfig& m) {
  return m.kind == MotionConfig::Kind::kRotation ? "deg"
         : m.kind == MotionConfig::Kind::kPoses  ? "pose"
                                                  : "m";
}

// The set-up's support index a moving support names; -1 with `why` when there is none.
int SupportIndex(const CableSetup& setup, const MotionConfig::MovingSupport& ms, std::string* why) {
  const int n = static_cast<int>(setup.spec.supports.size());
  if (ms.index >= 0) {
    if (ms.index < n) return ms.index;
    *why = "support " + std::to_string(ms.index) + " does not exist (cable '" + setup.name +
           "' has " + std::to_string(n) + ")";
    return -1;
  }
  for (int k = 0; k < n; ++k)
    if (setup.support_origin[static_cast<size_t>(k)] == ms.at) return k;
  *why = "cable '" + setup.name + "' has no support at its " + ms.at + " (it is free or joined)";
  return -1;
}

// Pose measures from a solved pose.
Json HitJson(const MotionConfig& c, const MotionPose& p, int index, double value) {
  return {{"pose", index}, {"q", Shown(c, p.q)}, {"value", json::NumberOrNull(value)}};
}

double LargestReaction(const MotionPose& p, int* support) {
  double best = 0.0;
  *support = -1;
  for (size_t k = 0; k < p.reactions.size(); ++k)
    if (p.reactions[k].force.norm() > best) {
      best = p.reactions[k].force.norm();
      *support = static_cast<int>(k);
    }
  return best;
}

TriangleMesh MovedMesh(const TriangleMesh& mesh, const Eigen::Isometry3d& t) {
  TriangleMesh out = mesh;
  out.vertices = (t.linear() * mesh.vertices).colwise() + t.translation();
  return out;
}

// The drawing's solids the motion moves (indices); a pattern matching none is a problem line.
std::vector<int> MovingSolids(const HarnessDrawing& drawing, const MotionConfig& config,
                              std::vector<std::string>* problems) {
  std::vector<int> out;
  for (size_t p = 0; p < config.solids.size(); ++p) {
    bool any = false;
    for (size_t k = 0; k < drawing.solids.size(); ++k)
      if (::fnmatch(config.solids[p].c_str(), drawing.solids[k].name.c_str(), 0) == 0) {
        any = true;
        if (std::find(out.begin(), out.end(), static_cast<int>(k)) == out.end())
          out.push_back(static_cast<int>(k));
      }
    if (!any)
      problems->push_back("motion.solids[" + std::to_string(p) + "]: no solid '" +
                          config.solids[p] + "' in this input");
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Support k of a cable is attached to the solid: a clip found on it, or a cable end held in it
// (the support lies in the solid's box, as clips are found).
bool AttachedTo(const CableSetup& setup, size_t k, const std::string& solid,
                const OrientedBox& box) {
  const std::string& origin = setup.support_origin[k];
  if (origin == "clip '" + solid + "'") return true;
  return (origin == "start" || origin == "end") && box.half_extent.prod() > 0 &&
         box.Contains(setup.spec.supports[k].position);
}

}  // namespace

double BackToStart(const CableMotion& cm, bool there_and_back) {
  if (!there_and_back || !cm.completed || cm.poses.size() < 2)
    return std::numeric_limits<double>::quiet_NaN();
  return (cm.poses.front().centreline.points - cm.poses.back().centreline.points)
      .colwise()
      .norm()
      .maxCoeff();
}

MotionPose MeasurePose(const CableRelaxation& relaxed, const SweepPose& p, double factor) {
  CableRelaxation r;
  r.setup = relaxed.setup;
  r.result = p.result;
  MeasureBendAndTension(factor, &r);
  MotionPose m;
  m.q = p.q;
  m.converged = p.converged;
  m.stable = p.stable;
  m.escaped_unstable = p.escaped_unstable;
  m.jumped = p.jumped;
  m.step = p.step;
  m.min_bend_radius = r.min_bend_radius;
  m.min_bend_radius_s = r.min_bend_radius_s;
  m.bend_flag = r.bend_flag;
  m.max_tension = r.max_tension;
  m.max_tension_s = r.max_tension_s;
  m.reactions = p.result.solution.reactions;
  m.newton_iterations = p.result.newton_iterations;
  const double length = relaxed.setup.spec.length;
  m.centreline = SampleCenterline(p.result.solution.centerline,
                                  UniformArcLengths(length, OutputSamples(length)));
  return m;
}


namespace {

// A cable nothing of the motion holds: its relaxed equilibrium at every pose.
CableMotion HeldStill(const CableRelaxation& relaxed, int cable, const std::vector<double>& q,
                      const HarnessConfig& config) {
  CableMotion cm;
  cm.cable = cable;
  cm.name = relaxed.setup.name;
  cm.held_still = true;
  SweepPose p;
  p.converged = relaxed.result.converged;
  p.stable = relaxed.result.solution.summary.stable;
  p.result = relaxed.result;
  // One shape at every pose: measured once.
  const MotionPose still = MeasurePose(relaxed, p, config.min_bend_radius_factor);
  for (double x : q) {
    cm.poses.push_back(still);
    cm.poses.back().q = x;
  }
  cm.completed = true;
  cm.back_to_start = BackToStart(cm, config.motion->there_and_back);
  return cm;
}

// Where arc length `s` of a swept cable is at every pose.
MotionTrack TrackPoint(const CableMotion& cm, const MotionConfig::TrackedPoint& tp) {
  MotionTrack t;
  t.cable = tp.cable;
  const Polyline& first = cm.poses.front().centreline;
  t.s = std::clamp(tp.s, first.s[0], first.s[first.size() - 1]);
  t.points.resize(3, static_cast<Eigen::Index>(cm.poses.size()));
  Eigen::VectorXd at(1);
  at[0] = t.s;
  for (size_t i = 0; i < cm.poses.size(); ++i) {
    t.points.col(static_cast<Eigen::Index>(i)) =
        SampleCenterline(cm.poses[i].centreline, at).points.col(0);
    if (i == 0) continue;
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    t.travel += (t.points.col(k) - t.points.col(k - 1)).norm();
    const double d = (t.points.col(k) - t.points.col(0)).norm();
    if (d > t.excursion) {
      t.excursion = d;
      t.excursion_pose = static_cast<int>(i);
    }
  }
  return t;
}

}  // namespace

void RunFileMotion(const HarnessConfig& config, const SimulationOptions& options, RelaxedFile* f) {
  if (!config.motion) return;
  const auto t0 = Clock::now();
  FileMotion fm;
  fm.config = *config.motion;
  fm.q = fm.config.Poses();
  // Which supports of which cable move.
  std::map<int, std::vector<int>> moving;  // drawing cable -> support indices
  std::map<int, std::map<int, std::vector<int>>> network_moving;  // group -> the same
  const std::vector<OrientedBox> solid_boxes = SolidBoxes(f->drawing);
  std::vector<RelaxGroup> groups;
  try {
    groups = GroupCables(f->drawing, solid_boxes, config);
  } catch (const std::exception& e) {
    fm.problems.push_back(std::string("motion: ") + e.what());
  }
  // A support of a cable moves; a cable of a network moves with its whole group.
  auto add_moving = [&](int cable, int index) {
    int network = -1;
    for (size_t g = 0; g < groups.size(); ++g)
      if (groups[g].network() &&
          std::count(groups[g].cables.begin(), groups[g].cables.end(), cable) > 0)
        network = static_cast<int>(g);
    std::vector<int>& list = network >= 0 ? network_moving[network][cable] : moving[cable];
    if (std::find(list.begin(), list.end(), index) == list.end()) list.push_back(index);
  };
  for (size_t k = 0; k < fm.config.supports.size(); ++k) {
    const MotionConfig::MovingSupport& ms = fm.config.supports[k];
    const std::string where = "motion.moving[" + std::to_string(k) + "]: ";
    int cable = -1;
    for (size_t i = 0; i < f->drawing.cables.size(); ++i)
      if (f->drawing.cables[i].name == ms.cable) cable = static_cast<int>(i);
    if (cable < 0) {
      fm.problems.push_back(where + "no cable '" + ms.cable + "' in this input");
      continue;
    }
    if (!f->cables[static_cast<size_t>(cable)]) {
      fm.problems.push_back(where + "cable '" + ms.cable + "' was not relaxed");
      continue;
    }
    std::string why;
    const int index = SupportIndex(f->cables[static_cast<size_t>(cable)]->setup, ms, &why);
    if (index < 0) {
      fm.problems.push_back(where + why);
      continue;
    }
    add_moving(cable, index);
  }
  // Moving solids carry the supports attached to them.
  fm.moving_solids = MovingSolids(f->drawing, fm.config, &fm.problems);
  for (int k : fm.moving_solids) fm.moving_solid_names.push_back(f->drawing.solids[static_cast<size_t>(k)].name);
  for (size_t c = 0; c < f->cables.size(); ++c) {
    if (!f->cables[c]) continue;
    const CableSetup& setup = f->cables[c]->setup;
    for (size_t k = 0; k < setup.spec.supports.size(); ++k)
      for (int solid : fm.moving_solids)
        if (AttachedTo(setup, k, f->drawing.solids[static_cast<size_t>(solid)].name,
                       solid_boxes[static_cast<size_t>(solid)]))
          add_moving(static_cast<int>(c), static_cast<int>(k));
  }
  // Sweep each cable (its own rod: the cables of a motion do not touch each other's solve).
  SweepOptions sweep_options;
  sweep_options.simulation = options;
  const MotionConfig& mc = fm.config;
  for (const auto& [cable, supports] : moving) {
    const CableRelaxation& relaxed = *f->cables[static_cast<size_t>(cable)];
    CableMotion cm;
    cm.cable = cable;
    cm.name = relaxed.setup.name;
    cm.moving = supports;
    const auto c0 = Clock::now();
    try {
      const SweepSummary s = SweepRod(
          relaxed.setup.spec, &relaxed.setup.route, supports, [&mc](double q) { return mc.At(q); },
          fm.q, sweep_options);
      cm.branch_lost_pose = s.branch_lost_pose;
      cm.completed = s.completed;
      cm.message = s.message;
      for (const SweepPose& p : s.poses)
        cm.poses.push_back(MeasurePose(relaxed, p, ConfigOf(*f, config).min_bend_radius_factor));
    } catch (const std::exception& e) {
      cm.message = e.what();
    }
    cm.back_to_start = BackToStart(cm, mc.there_and_back);
    cm.seconds = std::chrono::duration<double>(Clock::now() - c0).count();
    fm.cables.push_back(std::move(cm));
  }
  // Networks: every cable of the group moves with the supports that move, and with the solids
  // it rests on that move.
  for (size_t g = 0; g < groups.size(); ++g)
    for (int k : groups[g].obstacles)
      if (groups[g].network() &&
          std::count(fm.moving_solids.begin(), fm.moving_solids.end(), k) > 0)
        network_moving[static_cast<int>(g)];  // swept, with or without moving supports
  for (const auto& [g, group_moving] : network_moving) {
    const bool any_failed = std::any_of(
        groups[static_cast<size_t>(g)].cables.begin(), groups[static_cast<size_t>(g)].cables.end(),
        [&](int c) { return !f->cables[static_cast<size_t>(c)]; });
    if (any_failed) {
      fm.problems.push_back("network " + GroupLabel(f->drawing, groups[static_cast<size_t>(g)]) +
                            ": not swept, a cable of it was not relaxed");
      continue;
    }
    for (CableMotion& cm :
         SweepNetworkGroupMotion(*f, groups[static_cast<size_t>(g)], group_moving, solid_boxes,
                                 config, options, fm.q, fm.moving_solids))
      fm.cables.push_back(std::move(cm));
  }
  // With solids moving, the cables nothing moves keep their relaxed shape at every pose: listed
  // too, so that their clearance to the moving solids is measured pose by pose.
  if (!fm.moving_solids.empty())
    for (size_t c = 0; c < f->cables.size(); ++c) {
      if (!f->cables[c] || std::any_of(fm.cables.begin(), fm.cables.end(), [&](const CableMotion& m) {
            return m.cable == static_cast<int>(c);
          }))
        continue;
      fm.cables.push_back(HeldStill(*f->cables[c], static_cast<int>(c), fm.q, config));
    }
  std::stable_sort(fm.cables.begin(), fm.cables.end(),
                   [](const CableMotion& a, const CableMotion& b) { return a.cable < b.cable; });
  // Clearance of every swept pose to the solids (the moving ones where the motion has them) and
  // the other cables at that pose.
  std::vector<SolidClearance> geometry;
  geometry.reserve(f->drawing.solids.size());
  for (const DrawnSolid& s : f->drawing.solids) geometry.emplace_back(s.mesh);
  std::vector<ClearanceSolid> solids;
  for (size_t k = 0; k < f->drawing.solids.size(); ++k)
    solids.push_back({f->drawing.solids[k].name, &geometry[k],
                      config.SolidMinClearance(f->drawing.solids[k].name)});
  const std::vector<OrientedBox> boxes = ClearanceBoxes(f->drawing);
  for (size_t i = 0; i < fm.q.size(); ++i) {
    // The moving solids where the motion has them at this pose.
    std::vector<SolidClearance> moved;
    moved.reserve(fm.moving_solids.size());
    std::vector<ClearanceSolid> solids_here = solids;
    for (int k : fm.moving_solids) {
      moved.emplace_back(MovedMesh(f->drawing.solids[static_cast<size_t>(k)].mesh, mc.At(fm.q[i])));
      solids_here[static_cast<size_t>(k)].geometry = &moved.back();
    }
    for (CableMotion& cm : fm.cables) {
      if (i >= cm.poses.size()) continue;
      const CableRelaxation& relaxed = *f->cables[static_cast<size_t>(cm.cable)];
      MotionPose& pose = cm.poses[i];
      const ClearanceCable me =
          ClearanceCableOf(relaxed, &pose.centreline, f->drawing, boxes, config);
      std::vector<ClearancePair> pairs = MeasureClearances({me}, solids_here);
      for (size_t j = 0; j < f->cables.size(); ++j) {
        if (!f->cables[j] || static_cast<int>(j) == cm.cable) continue;
        const Polyline* other = &f->cables[j]->relaxed;
        for (const CableMotion& om : fm.cables)
          if (om.cable == static_cast<int>(j) && i < om.poses.size())
            other = &om.poses[i].centreline;
        const ClearanceCable them =
            ClearanceCableOf(*f->cables[j], other, f->drawing, boxes, config);
        for (ClearancePair& p : MeasureClearances({me, them}, {})) pairs.push_back(p);
      }
      for (const ClearancePair& p : pairs) {
        if (p.rests_on || !(p.hit.clearance < pose.clearance.clearance)) continue;
        pose.clearance = p.hit;
        pose.clearance_to = (p.other_is_solid ? "solid '" : "cable '") + p.other + "'";
        pose.clearance_required = p.required;
      }
    }
  }
  // The tracked points' paths.
  for (size_t k = 0; k < fm.config.tracks.size(); ++k) {
    const MotionConfig::TrackedPoint& tp = fm.config.tracks[k];
    const CableMotion* swept = nullptr;
    for (const CableMotion& cm : fm.cables)
      if (cm.name == tp.cable) swept = &cm;
    if (!swept || swept->poses.empty()) {
      fm.problems.push_back("motion.track[" + std::to_string(k) + "]: cable '" + tp.cable +
                            "' is not moved by this motion (or not in this input)");
      continue;
    }
    fm.tracks.push_back(TrackPoint(*swept, tp));
  }
  fm.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  f->motion = std::move(fm);
}

Json CableMotionToJson(const CableMotion& m, const MotionConfig& c) {
  Json poses = Json::array();
  int worst_bend = -1, worst_tension = -1, worst_reaction = -1, worst_clearance = -1;
  double largest_reaction = -1;
  int largest_reaction_support = -1;
  for (size_t i = 0; i < m.poses.size(); ++i) {
    const MotionPose& p = m.poses[i];
    const int k = static_cast<int>(i);
    Json reactions = Json::array();
    for (const SupportReaction& r : p.reactions)
      reactions.push_back(
          {{"s", r.s}, {"force", json::ToJson(r.force)}, {"moment", json::ToJson(r.moment)}});
    Json pj = {
        {"q", Shown(c, p.q)},
        {"converged", p.converged},
        {"stable", p.stable},
        {"branch_lost", p.escaped_unstable || p.jumped},
        {"min_bend_radius",
         {{"radius", json::NumberOrNull(p.min_bend_radius)},
          {"s", p.min_bend_radius_s},
          {"flag", p.bend_flag}}},
        {"max_tension", {{"force", json::NumberOrNull(p.max_tension)}, {"s", p.max_tension_s}}},
        {"reactions", reactions},
        {"step", p.step},
        {"iterations", p.newton_iterations}};
    // The shape at a few points per pose (the relaxed cable's own centreline has ~1 per mm).
    Json rows = Json::array();
    const Polyline shape = SampleCenterline(
        p.centreline,
        UniformArcLengths(p.centreline.s[p.centreline.size() - 1], kPoseShapeSamples));
    for (int k = 0; k < shape.size(); ++k)
      rows.push_back({shape.s[k], shape.points(0, k), shape.points(1, k), shape.points(2, k)});
    pj["centreline"] = {{"columns", {"s", "x", "y", "z"}}, {"rows", rows}};
    if (p.escaped_unstable || p.jumped)
      pj["how"] = p.escaped_unstable ? "unstable equilibrium" : "jump";
    if (p.clearance.found()) {
      pj["clearance"] = {
          {"clearance", p.clearance.clearance},
          {"to", p.clearance_to},
          {"s", p.clearance.s},
          {"point", json::ToJson(p.clearance.point)},
          {"required", p.clearance_required},
          {"violation", p.clearance_required > 0 && p.clearance.clearance < p.clearance_required}};
    }
    poses.push_back(pj);
    if (worst_bend < 0 ||
        p.min_bend_radius < m.poses[static_cast<size_t>(worst_bend)].min_bend_radius)
      worst_bend = k;
    if (std::isfinite(p.max_tension) &&
        (worst_tension < 0 ||
         p.max_tension > m.poses[static_cast<size_t>(worst_tension)].max_tension))
      worst_tension = k;
    int support = -1;
    const double reaction = LargestReaction(p, &support);
    if (reaction > largest_reaction) {
      largest_reaction = reaction;
      largest_reaction_support = support;
      worst_reaction = k;
    }
    if (p.clearance.found() &&
        (worst_clearance < 0 ||
         p.clearance.clearance < m.poses[static_cast<size_t>(worst_clearance)].clearance.clearance))
      worst_clearance = k;
  }
  Json worst = Json::object();
  if (worst_bend >= 0) {
    const MotionPose& p = m.poses[static_cast<size_t>(worst_bend)];
    worst["min_bend_radius"] = HitJson(c, p, worst_bend, p.min_bend_radius);
  }
  if (worst_tension >= 0) {
    const MotionPose& p = m.poses[static_cast<size_t>(worst_tension)];
    worst["max_tension"] = HitJson(c, p, worst_tension, p.max_tension);
  }
  if (worst_reaction >= 0) {
    worst["max_support_force"] =
        HitJson(c, m.poses[static_cast<size_t>(worst_reaction)], worst_reaction, largest_reaction);
    worst["max_support_force"]["support"] = largest_reaction_support;
  }
  if (worst_clearance >= 0) {
    const MotionPose& p = m.poses[static_cast<size_t>(worst_clearance)];
    worst["min_clearance"] = HitJson(c, p, worst_clearance, p.clearance.clearance);
    worst["min_clearance"]["to"] = p.clearance_to;
  }
  Json lost = nullptr;
  if (m.branch_lost_pose >= 0) {
    const MotionPose& p = m.poses[static_cast<size_t>(m.branch_lost_pose)];
    lost = {{"pose", m.branch_lost_pose},
            {"q", Shown(c, p.q)},
            {"how", p.escaped_unstable ? "unstable equilibrium" : "jump"}};
  }
  Json moving = Json::array();
  for (int k : m.moving) moving.push_back(k);
  Json network = nullptr;
  if (!m.network.empty())
    network = {{"cables", m.network},
               {"elements", m.elements},
               {"resolution_error", json::NumberOrNull(m.resolution_error)}};
  return {{"name", c.name},           {"moving_supports", moving},
          {"completed", m.completed}, {"message", m.message},
          {"poses", poses},           {"worst", worst},
          {"stability_lost", lost},   {"back_to_start", json::NumberOrNull(m.back_to_start)},
          {"network", network},       {"held_still", m.held_still},
          {"seconds", m.seconds}};
}

namespace {

Json TracksJson(const FileMotion& m) {
  Json out = Json::array();
  for (const MotionTrack& t : m.tracks) {
    Json points = Json::array();
    for (Eigen::Index k = 0; k < t.points.cols(); ++k) points.push_back(json::ToJson(Vec3(t.points.col(k))));
    out.push_back({{"cable", t.cable},
                   {"s", t.s},
                   {"points", points},
                   {"travel", t.travel},
                   {"excursion",
                    {{"distance", t.excursion},
                     {"pose", t.excursion_pose},
                     {"q", Shown(m.config, m.q[static_cast<size_t>(t.excursion_pose)])}}}});
  }
  return out;
}

}  // namespace

Json FileMotionToJson(const FileMotion& m) {
  Json q = Json::array();
  for (double x : m.q) q.push_back(Shown(m.config, x));
  Json swept = Json::array();
  for (const CableMotion& c : m.cables) swept.push_back(c.name);
  Json j = {{"name", m.config.name},
            {"kind", m.config.KindName()},
            {"parameter_unit", ShownUnit(m.config)},
            {"axis", m.config.kind == MotionConfig::Kind::kPoses ? Json(nullptr)
                                                                  : json::ToJson(m.config.axis)},
            {"parameters", q},
            {"there_and_back", m.config.there_and_back},
            {"cables", swept},
            {"moving_solids", m.moving_solid_names},
            {"tracks", TracksJson(m)},
            {"problems", m.problems},
            {"seconds", m.seconds},
            {"meaning",
             "the supports listed in harness.json follow the motion (the drawing is parameter 0), "
             "and so do the solids listed (moving_solids) with the supports attached to them; "
             "other solids stay where drawn; each pose is solved from the previous one; a cable solved "
             "as a network moves with all of it ('network': its cables, the elements every pose "
             "is solved with, and how far that resolution is from the refined relax at the "
             "drawn pose, m); 'tracks': the path of each tracked point (its place at every pose, "
             "the length travelled, the farthest it gets from its first place). Per cable "
             "'motion': per pose min bend radius, max tension, support reactions (force on the "
             "cable, N and N m), stability of the equilibrium reached, least clearance; 'worst' "
             "the pose of each extreme; 'stability_lost' the first pose where the branch "
             "followed ends (an unstable equilibrium, or a jump: snap-through), after which the "
             "sweep follows the stable branch it lands on; 'back_to_start' [m] the largest "
             "distance between the first and last pose's centrelines"}};
  if (m.config.kind == MotionConfig::Kind::kRotation) j["point"] = json::ToJson(m.config.point);
  return j;
}

std::vector<std::string> MotionLines(const FileMotion& m) {
  std::vector<std::string> lines;
  const MotionConfig& c = m.config;
  for (const CableMotion& cm : m.cables) {
    char buf[1024];
    int n = std::snprintf(buf, sizeof buf,
                          "motion '%s' (%s %g..%g %s, %zu poses): %s: ", c.name.c_str(),
                          c.KindName(), Shown(c, c.from), Shown(c, c.to), ShownUnit(c),
                          cm.poses.size(), cm.name.c_str());
    std::string text(buf, static_cast<size_t>(std::max(0, n)));
    if (cm.poses.empty()) {
      lines.push_back(text + "FAILED: " + cm.message);
      continue;
    }
    const MotionPose* bend = &cm.poses[0];
    const MotionPose* tension = &cm.poses[0];
    const MotionPose* reaction = &cm.poses[0];
    const MotionPose* clearance = nullptr;
    double largest = -1;
    for (const MotionPose& p : cm.poses) {
      if (p.min_bend_radius < bend->min_bend_radius) bend = &p;
      if (p.max_tension > tension->max_tension) tension = &p;
      int support = 0;
      const double f = LargestReaction(p, &support);
      if (f > largest) {
        largest = f;
        reaction = &p;
      }
      if (p.clearance.found() &&
          (!clearance || p.clearance.clearance < clearance->clearance.clearance))
        clearance = &p;
    }
    std::snprintf(buf, sizeof buf,
                  "min bend radius %.1f mm%s at %g %s, max tension %.3g N at %g %s, largest "
                  "support force %.3g N at %g %s",
                  1e3 * bend->min_bend_radius, bend->bend_flag ? " (TOO TIGHT)" : "",
                  Shown(c, bend->q), ShownUnit(c), tension->max_tension, Shown(c, tension->q),
                  ShownUnit(c), largest, Shown(c, reaction->q), ShownUnit(c));
    text += buf;
    if (clearance) {
      const bool violation = clearance->clearance_required > 0 &&
                             clearance->clearance.clearance < clearance->clearance_required;
      std::snprintf(buf, sizeof buf, ", least clearance %.1f mm%s at %g %s (to %s, s=%.0f mm)",
                    1e3 * clearance->clearance.clearance, violation ? " (CLEARANCE)" : "",
                    Shown(c, clearance->q), ShownUnit(c), clearance->clearance_to.c_str(),
                    1e3 * clearance->clearance.s);
      text += buf;
    }
    if (cm.branch_lost_pose >= 0) {
      const MotionPose& p = cm.poses[static_cast<size_t>(cm.branch_lost_pose)];
      std::snprintf(buf, sizeof buf, ", STABILITY LOST at pose %d (%g %s: %s)", cm.branch_lost_pose,
                    Shown(c, p.q), ShownUnit(c),
                    p.escaped_unstable ? "unstable equilibrium" : "jump");
      text += buf;
    } else {
      text += ", stable throughout";
    }
    if (std::isfinite(cm.back_to_start)) {
      std::snprintf(buf, sizeof buf, ", back to start within %.2g m", cm.back_to_start);
      text += buf;
    }
    if (cm.held_still) text += " (nothing holding it moves: its relaxed shape at every pose)";
    if (!cm.network.empty()) {
      std::snprintf(buf, sizeof buf, " (swept as one network with %s, %d elements",
                    cm.network.c_str(), cm.elements);
      text += buf;
      if (std::isfinite(cm.resolution_error)) {
        std::snprintf(buf, sizeof buf, ", %.2g m from the refined relax at the drawn pose",
                      cm.resolution_error);
        text += buf;
      }
      text += ")";
    }
    if (!cm.completed) text += "; STOPPED: " + cm.message;
    std::snprintf(buf, sizeof buf, ", %.3f s", cm.seconds);
    lines.push_back(text + buf);
  }
  for (const MotionTrack& t : m.tracks) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "motion '%s': %s at s=%.0f mm moves up to %.1f mm from its first place (pose "
                  "%d, %g %s), travelling %.1f mm",
                  c.name.c_str(), t.cable.c_str(), 1e3 * t.s, 1e3 * t.excursion, t.excursion_pose,
                  Shown(c, m.q[static_cast<size_t>(t.excursion_pose)]), ShownUnit(c),
                  1e3 * t.travel);
    lines.push_back(buf);
  }
  for (const std::string& p : m.problems) lines.push_back("motion '" + c.name + "': " + p);
  return lines;
}

std::string MotionReportSection(const std::vector<RelaxedFile>& files) {
  std::ostringstream h;
  bool any = false;
  for (const RelaxedFile& f : files) {
    if (!f.motion) continue;
    if (!any) h << "<section class=\"card\"><h2>Motion</h2><ul class=\"notes\">";
    any = true;
    for (const std::string& line : MotionLines(*f.motion))
      h << "<li>" << HtmlEscape(f.stem) << ": " << HtmlEscape(line) << "</li>";
  }
  if (!any) return "";
  h << "</ul><p>Per pose figures in the JSON's per-cable <code>motion</code>.</p>";
  int figure = 0;
  for (const RelaxedFile& f : files) {
    const MotionPictures& pictures = f.motion_pictures;
    if (pictures.animation.empty()) continue;
    const std::string id = "motion" + std::to_string(figure++);  // also a JavaScript name
    h << "<figure><a href=\"" << HtmlEscape(pictures.animation) << "\"><img src=\""
      << HtmlEscape(pictures.animation) << "\" alt=\"" << HtmlEscape(f.stem)
      << " motion\"></a><figcaption>" << HtmlEscape(f.stem)
      << ": the motion, every pose (animated PNG); colour = distance from pose 0, grey line = "
         "pose 0.</figcaption></figure>";
    if (pictures.frames.empty()) continue;
    // The still frames under a slider: pick a pose and look at it.
    h << "<figure><img id=\"" << id << "\" src=\"" << HtmlEscape(pictures.frames[0])
      << "\" alt=\"" << HtmlEscape(f.stem) << " pose\"><figcaption><input type=\"range\" min=\"0\" "
      << "max=\"" << pictures.frames.size() - 1 << "\" value=\"0\" style=\"width:60%\" "
      << "aria-label=\"pose\" oninput=\"var f=" << id << "_frames[this.value];document."
      << "getElementById('" << id << "').src=f[0];document.getElementById('" << id
      << "-caption').textContent=f[1];\"> <span id=\"" << id << "-caption\">"
      << HtmlEscape(pictures.captions[0]) << "</span></figcaption></figure><script>var " << id
      << "_frames=[";
    for (size_t k = 0; k < pictures.frames.size(); ++k) {
      // JSON strings are valid JavaScript literals; '<' escaped so no "</script>" can appear.
      std::string pair = json::Json::array({pictures.frames[k], pictures.captions[k]})
                             .dump(-1, ' ', false, json::Json::error_handler_t::replace);
      std::string safe;
      for (char c : pair) safe += c == '<' ? std::string("\\u003c") : std::string(1, c);
      h << (k ? "," : "") << safe;
    }
    h << "];</script>";
  }
  h << "</section>\n";
  return h.str();
}

}  // namespace cablefit::addin
