#include "cablefit/app/config/harness_config.h"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/section/section.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/app/config/section_json.h"

namespace cablefit::addin {
namespace {

using json::FieldReader;
using json::Json;

using json::RequireKnownKeys;

bool OptionalBool(const FieldReader& r, const std::string& key, bool fallback) {
  if (!r.Has(key)) return fallback;
  const Json& v = r.object().at(key);
  if (!v.is_boolean()) r.Fail(key, "must be true or false, got " + json::Describe(v));
  return v.get<bool>();
}

SupportKind ReadKind(const FieldReader& r, const std::string& key) {
  const std::string text = r.RequireString(key);
  try {
    return SupportKindFromString(text);
  } catch (const InvalidInput&) {
    r.Fail(key, "must be \"clamp\", \"clip\" or \"pin\", got \"" + text + "\"");
  }
}

// "clamp" | "clip" | "pin" | "free" | {"kind": ..., "sliding": bool}.
EndConfig ReadEnd(const FieldReader& parent, const std::string& key) {
  const Json& v = parent.object().at(key);
  EndConfig end;
  if (v.is_string()) {
    if (v.get<std::string>() == "free") {
      end.free = true;
      return end;
    }
    end.kind = ReadKind(parent, key);
    return end;
  }
  if (!v.is_object()) {
    parent.Fail(key, "must be \"clamp\", \"clip\", \"pin\", \"free\" or {\"kind\", \"sliding\"}");
  }
  const FieldReader r = parent.Child(key);
  RequireKnownKeys(r, {"kind", "sliding"});
  if (r.Has("kind") && r.RequireString("kind") == "free") {
    end.free = true;
  } else if (r.Has("kind")) {
    end.kind = ReadKind(r, "kind");
  }
  end.sliding = OptionalBool(r, "sliding", false);
  if (end.sliding && (end.free || end.kind == SupportKind::kPin)) {
    r.Fail("sliding", "only a clamp or clip can slide");
  }
  return end;
}

ExtraSupportConfig ReadSupport(const FieldReader& r) {
  RequireKnownKeys(r, {"kind", "s", "point", "sliding"});
  ExtraSupportConfig sp;
  sp.kind = r.Has("kind") ? ReadKind(r, "kind") : SupportKind::kClip;
  if (r.Has("s") == r.Has("point")) r.FailHere("needs exactly one of \"s\" or \"point\"");
  if (r.Has("s")) sp.s = r.RequireNonNegative("s");
  if (r.Has("point")) sp.point = r.RequireVec3("point");
  sp.sliding = OptionalBool(r, "sliding", false);
  if (sp.sliding && sp.kind == SupportKind::kPin) r.Fail("sliding", "a pin cannot slide");
  return sp;
}

// {"bending_stiffness", "torsional_stiffness", "linear_density"} or {"section": SECTION.json}.
void ReadMaterial(const FieldReader& r, CableConfig* c) {
  if (r.Has("section")) {
    RequireKnownKeys(r, {"section"});
    std::filesystem::path p = r.RequireString("section");
    if (p.is_relative()) p = std::filesystem::path(r.file()).parent_path() / p;
    const SectionInput in = ReadSectionFile(p.lexically_normal().string());
    MaterialSpec m = SectionToMaterial(ComputeSection(in.spec, in.torsion));
    c->diameter = c->diameter.value_or(m.diameter);
    m.diameter = 0.0;
    c->material = m;
    c->material_source = p.lexically_normal().string();
    return;
  }
  RequireKnownKeys(r, {"bending_stiffness", "torsional_stiffness", "linear_density",
                       "axial_stiffness", "note"});
  MaterialSpec m;
  m.bending_stiffness = r.RequirePositive("bending_stiffness");
  m.torsional_stiffness = r.RequirePositive("torsional_stiffness");
  m.linear_density = r.RequireNonNegative("linear_density");
  if (r.Has("axial_stiffness")) m.axial_stiffness = r.RequirePositive("axial_stiffness");
  c->material = m;
  c->material_source = r.file();
}

// "drawn" | metres | "+2%" / "-1.5%".
CableLength ReadLength(const FieldReader& r, bool is_default) {
  const Json& v = r.object().at("length");
  CableLength length;
  if (v.is_number()) {
    if (is_default) r.Fail("length", "a length in metres is for one cable; the default takes \"+2%\" or \"drawn\"");
    length.kind = CableLength::Kind::kMetres;
    length.value = r.RequirePositive("length");
    return length;
  }
  const std::string text = v.is_string() ? v.get<std::string>() : "";
  if (text == "drawn") return length;
  std::size_t used = 0;
  double percent = std::numeric_limits<double>::quiet_NaN();
  if (text.size() >= 2 && text.back() == '%' && (text[0] == '+' || text[0] == '-')) {
    try {
      percent = std::stod(text.substr(0, text.size() - 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
  }
  if (used + 1 != text.size() || !std::isfinite(percent))
    r.Fail("length", "must be \"drawn\", a length in metres or a signed percentage such as \"+2%\", got " +
                         json::Describe(v));
  // Beyond these a "cable length" is a different cable, most likely a typo.
  if (percent <= -50 || percent > 100)
    r.Fail("length", "must change the drawn length by more than -50% and at most +100%, got " + text);
  length.kind = CableLength::Kind::kRelative;
  length.value = percent / 100;
  return length;
}

CableConfig ReadCable(const FieldReader& r, bool is_default) {
  std::set<std::string> keys = {"material",   "diameter", "gravity", "start",        "end",
                                "auto_clips", "length",   "note",    "min_clearance"};
  if (!is_default) keys.insert("supports");
  RequireKnownKeys(r, keys);
  CableConfig c;
  if (r.Has("diameter")) c.diameter = r.RequirePositive("diameter");
  if (r.Has("length")) c.length = ReadLength(r, is_default);
  if (r.Has("material")) ReadMaterial(r.Child("material"), &c);
  if (r.Has("gravity")) c.gravity = r.RequireVec3("gravity");
  if (r.Has("start")) c.start = ReadEnd(r, "start");
  if (r.Has("end")) c.end = ReadEnd(r, "end");
  if (r.Has("auto_clips")) c.auto_clips = OptionalBool(r, "auto_clips", true);
  if (r.Has("min_clearance")) c.min_clearance = r.RequireNonNegative("min_clearance");
  if (r.Has("supports")) {
    const Json& list = r.RequireArray("supports");
    for (size_t i = 0; i < list.size(); ++i) {
      c.supports.push_back(ReadSupport(
          FieldReader(list[i], r.file(), json::IndexKey(json::JoinKey(r.where(), "supports"), i))));
    }
  }
  return c;
}

JunctionConfig ReadJunction(const FieldReader& r, int index) {
  RequireKnownKeys(r, {"name", "ends", "compliance", "mass", "note"});
  JunctionConfig j;
  j.name = r.Has("name") ? r.RequireString("name") : "junction " + std::to_string(index + 1);
  const Json& ends = r.RequireArray("ends");
  if (ends.size() < 2) r.Fail("ends", "a junction joins two or more cable ends");
  for (size_t i = 0; i < ends.size(); ++i) {
    const FieldReader e(ends[i], r.file(), json::IndexKey(json::JoinKey(r.where(), "ends"), i));
    RequireKnownKeys(e, {"cable", "end"});
    JunctionConfig::End end;
    end.cable = e.RequireString("cable");
    const std::string which = e.RequireString("end");
    if (which != "start" && which != "end") e.Fail("end", "must be \"start\" or \"end\"");
    end.at_start = which == "start";
    j.ends.push_back(end);
  }
  if (r.Has("compliance")) j.compliance = r.RequireNonNegative("compliance");
  if (r.Has("mass")) j.mass = r.RequireNonNegative("mass");
  return j;
}

// A non-empty array of non-empty name patterns.
std::vector<std::string> ReadPatterns(const FieldReader& r, const std::string& key) {
  const Json& list = r.RequireArray(key);
  if (list.empty()) r.Fail(key, "must list at least one name pattern");
  std::vector<std::string> patterns;
  for (size_t i = 0; i < list.size(); ++i) {
    if (!list[i].is_string() || list[i].get<std::string>().empty())
      r.Fail(json::IndexKey(key, i), "must be a non-empty name pattern, got " + json::Describe(list[i]));
    patterns.push_back(list[i].get<std::string>());
  }
  return patterns;
}

// A unit vector from a non-zero finite one.
Vec3 RequireDirection(const FieldReader& r, const std::string& key) {
  const Vec3 v = r.RequireVec3(key);
  if (!(v.norm() > 1e-12) || !v.allFinite()) r.Fail(key, "must be a non-zero direction");
  return v.normalized();
}

// [from, to] of finite numbers that differ.
void ReadRange(const FieldReader& r, const std::string& key, double scale, double max_span,
               const char* max_text, MotionConfig* m) {
  const Json& v = r.RequireArray(key);
  if (v.size() != 2 || !v[0].is_number() || !v[1].is_number())
    r.Fail(key, "must be [from, to], got " + json::Describe(v));
  const double from = v[0].get<double>(), to = v[1].get<double>();
  if (!std::isfinite(from) || !std::isfinite(to) || from == to)
    r.Fail(key, "must be two different finite numbers");
  if (std::abs(to - from) > max_span || std::abs(from) > max_span || std::abs(to) > max_span)
    r.Fail(key, std::string("must stay within ") + max_text);
  m->from = scale * from;
  m->to = scale * to;
}

// One listed pose: a rotation (about `axis` through `point` by `angle` degrees), then a
// translation [m]; at least one of them.
Eigen::Isometry3d ReadPose(const FieldReader& r) {
  RequireKnownKeys(r, {"rotation", "translation", "note"});
  if (!r.Has("rotation") && !r.Has("translation"))
    r.FailHere("needs a \"rotation\", a \"translation\" or both");
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  if (r.Has("rotation")) {
    const FieldReader rot = r.Child("rotation");
    RequireKnownKeys(rot, {"axis", "point", "angle", "note"});
    const Vec3 axis = RequireDirection(rot, "axis");
    const Vec3 point = rot.RequireVec3("point");
    const double angle = rot.RequireNumber("angle");
    if (!(std::abs(angle) <= 360)) rot.Fail("angle", "must stay within +-360 degrees");
    t.linear() = Eigen::AngleAxisd(angle * M_PI / 180, axis).toRotationMatrix();
    t.translation() = point - t.linear() * point;
  }
  if (r.Has("translation")) {
    const Vec3 shift = r.RequireVec3("translation");
    if (!shift.allFinite() || !(shift.norm() <= 100)) r.Fail("translation", "must stay within 100 m");
    t.pretranslate(shift);
  }
  return t;
}

// One reader for the "motion" object, field after field in the order docs/harness-json.md
// documents them, so that the two can be checked side by side.
MotionConfig ReadMotion(const FieldReader& r) {
  RequireKnownKeys(r, {"name", "rotation", "translation", "poses", "steps", "return", "moving",
                       "solids", "track", "note"});
  MotionConfig m;
  if (r.Has("name")) m.name = r.RequireString("name");
  if (r.Has("rotation") + r.Has("translation") + r.Has("poses") != 1)
    r.FailHere("needs exactly one of \"rotation\", \"translation\" or \"poses\"");
  if (r.Has("poses")) {
    m.kind = MotionConfig::Kind::kPoses;
    m.steps = 1;
    const Json& list = r.RequireArray("poses");
    if (list.empty() || list.size() > 10000) r.Fail("poses", "must list 1 to 10000 poses");
    for (size_t i = 0; i < list.size(); ++i)
      m.poses.push_back(ReadPose(
          FieldReader(list[i], r.file(), json::IndexKey(json::JoinKey(r.where(), "poses"), i))));
    m.from = 0.0;
    m.to = static_cast<double>(m.poses.size());
  } else if (r.Has("rotation")) {
    const FieldReader rot = r.Child("rotation");
    RequireKnownKeys(rot, {"axis", "point", "angles", "note"});
    m.kind = MotionConfig::Kind::kRotation;
    m.axis = RequireDirection(rot, "axis");
    m.point = rot.RequireVec3("point");
    ReadRange(rot, "angles", M_PI / 180, 360, "+-360 degrees", &m);
  } else {
    const FieldReader tr = r.Child("translation");
    RequireKnownKeys(tr, {"direction", "distances", "note"});
    m.kind = MotionConfig::Kind::kTranslation;
    m.axis = RequireDirection(tr, "direction");
    ReadRange(tr, "distances", 1.0, 100, "+-100 m", &m);
  }
  if (r.Has("steps")) {
    const Json& v = r.object().at("steps");
    // A sweep of more poses than this is a typo, not a study (each pose is a solve).
    if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 100000)
      r.Fail("steps", "must be a whole number from 1 to 100000, got " + json::Describe(v));
    m.steps = static_cast<int>(v.get<long long>());
    if (m.kind == MotionConfig::Kind::kPoses &&
        static_cast<long long>(m.steps) * static_cast<long long>(m.poses.size()) > 100000)
      r.Fail("steps", "times the number of poses must stay within 100000");
  }
  m.there_and_back = OptionalBool(r, "return", true);
  if (r.Has("solids")) {
    const Json& solids = r.RequireArray("solids");
    for (size_t i = 0; i < solids.size(); ++i) {
      if (!solids[i].is_string() || solids[i].get<std::string>().empty())
        r.Fail(json::IndexKey("solids", i),
               "must be a solid name or pattern, got " + json::Describe(solids[i]));
      m.solids.push_back(solids[i].get<std::string>());
    }
  }
  if (r.Has("track")) {
    const Json& list = r.RequireArray("track");
    for (size_t i = 0; i < list.size(); ++i) {
      const FieldReader e(list[i], r.file(), json::IndexKey(json::JoinKey(r.where(), "track"), i));
      RequireKnownKeys(e, {"cable", "s"});
      MotionConfig::TrackedPoint t;
      t.cable = e.RequireString("cable");
      t.s = e.RequireNumber("s");
      if (!(t.s >= 0) || !std::isfinite(t.s)) e.Fail("s", "must be a finite arc length >= 0 [m]");
      m.tracks.push_back(t);
    }
  }
  if (!r.Has("moving") && m.solids.empty())
    r.FailHere("needs \"moving\" supports or \"solids\" that move");
  const Json& list = r.Has("moving") ? r.RequireArray("moving") : Json::array();
  if (list.empty() && m.solids.empty())
    r.Fail("moving", "must list at least one moving support");
  for (size_t i = 0; i < list.size(); ++i) {
    const FieldReader e(list[i], r.file(), json::IndexKey(json::JoinKey(r.where(), "moving"), i));
    RequireKnownKeys(e, {"cable", "support"});
    MotionConfig::MovingSupport ms;
    ms.cable = e.RequireString("cable");
    if (!e.Has("support")) e.Fail("support", "is missing (\"start\", \"end\" or an index)");
    const Json& at = e.object().at("support");
    if (at.is_string() && (at.get<std::string>() == "start" || at.get<std::string>() == "end")) {
      ms.at = at.get<std::string>();
    } else if (at.is_number_integer() && at.get<long long>() >= 0 && at.get<long long>() < 100000) {
      ms.index = static_cast<int>(at.get<long long>());
    } else {
      e.Fail("support", "must be \"start\", \"end\" or a support index (0, 1, ...), got " +
                            json::Describe(at));
    }
    m.supports.push_back(ms);
  }
  return m;
}

bool Matches(const std::string& pattern, const std::string& name) {
  return ::fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
}

template <typename T>
void Overlay(std::optional<T>* base, const std::optional<T>& top) {
  if (top) *base = top;
}

}  // namespace

double CableConfig::DiameterFor(double drawn_diameter) const {
  if (diameter && !(diameter_from_default && drawn_diameter > 0)) return *diameter;
  return drawn_diameter > 0 ? drawn_diameter : 0.0;
}

CableConfig HarnessConfig::For(const std::string& name) const {
  CableConfig c = defaults;
  c.diameter_from_default = c.diameter.has_value();
  const auto it = cables.find(name);
  if (it == cables.end()) return c;
  const CableConfig& top = it->second;
  if (top.material) {
    c.material = top.material;
    c.material_source = top.material_source;
  }
  if (top.diameter) c.diameter_from_default = false;
  Overlay(&c.diameter, top.diameter);
  Overlay(&c.length, top.length);
  Overlay(&c.gravity, top.gravity);
  Overlay(&c.start, top.start);
  Overlay(&c.end, top.end);
  Overlay(&c.auto_clips, top.auto_clips);
  Overlay(&c.min_clearance, top.min_clearance);
  if (top.min_bend_radius) {
    c.min_bend_radius = top.min_bend_radius;
    c.min_bend_radius_source = top.min_bend_radius_source;
  }
  c.supports = top.supports;
  return c;
}

CableConfig Overlaid(CableConfig base, const CableConfig& top) {
  if (top.material) {
    base.material = top.material;
    base.material_source = top.material_source;
  }
  Overlay(&base.diameter, top.diameter);
  if (top.diameter) base.diameter_from_default = top.diameter_from_default;
  Overlay(&base.length, top.length);
  Overlay(&base.gravity, top.gravity);
  Overlay(&base.start, top.start);
  Overlay(&base.end, top.end);
  Overlay(&base.auto_clips, top.auto_clips);
  Overlay(&base.min_clearance, top.min_clearance);
  if (top.min_bend_radius) {
    base.min_bend_radius = top.min_bend_radius;
    base.min_bend_radius_source = top.min_bend_radius_source;
  }
  if (!top.supports.empty()) base.supports = top.supports;
  if (!top.sleeves.empty()) base.sleeves = top.sleeves;
  return base;
}

double CableLength::For(double drawn_length) const {
  switch (kind) {
    case Kind::kMetres: return value;
    case Kind::kRelative: return drawn_length * (1 + value);
    case Kind::kDrawn: break;
  }
  return drawn_length;
}

std::string CableLength::ToString() const {
  char buf[64];
  switch (kind) {
    case Kind::kMetres: std::snprintf(buf, sizeof buf, "%.6g m", value); return buf;
    case Kind::kRelative: std::snprintf(buf, sizeof buf, "%+.6g%%", 100 * value); return buf;
    case Kind::kDrawn: break;
  }
  return "drawn";
}

double HarnessConfig::SolidMinClearance(const std::string& name) const {
  // JSON objects carry no order, so no "first match": the safe side, the largest, applies.
  double largest = 0.0;
  for (const auto& [pattern, clearance] : solid_clearances)
    if (Matches(pattern, name)) largest = std::max(largest, clearance);
  return largest;
}

Eigen::Isometry3d MotionConfig::At(double q) const {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  if (kind == Kind::kPoses) {
    if (poses.empty()) return t;
    const double n = static_cast<double>(poses.size());
    const double x = std::clamp(q, 0.0, n);
    const int k = std::min(static_cast<int>(std::floor(x)), static_cast<int>(poses.size()) - 1);
    const double u = x - k;
    const Eigen::Isometry3d a = k == 0 ? Eigen::Isometry3d::Identity() : poses[static_cast<size_t>(k - 1)];
    const Eigen::Isometry3d& b = poses[static_cast<size_t>(k)];
    if (u == 0.0) return a;
    if (u == 1.0) return b;
    // Along the screw from a to b (Chasles): the turn about its axis and the shift along it, a
    // fraction u of each. A door between two listed poses swings on its hinge, not on the chord.
    const Eigen::Isometry3d rel = b * a.inverse();
    const Eigen::AngleAxisd turn(rel.linear());
    const Vec3 shift = rel.translation();
    if (!(turn.angle() > 1e-12)) {
      t.translation() = u * shift;
      return t * a;
    }
    const Vec3 axis_dir = turn.axis();
    const double along = axis_dir.dot(shift);
    const Vec3 across = shift - along * axis_dir;
    // The screw axis passes through c: (I - R) c = across, c square to the axis.
    const Vec3 c = 0.5 * (across + axis_dir.cross(across) / std::tan(0.5 * turn.angle()));
    t.linear() = Eigen::AngleAxisd(u * turn.angle(), axis_dir).toRotationMatrix();
    t.translation() = c - t.linear() * c + u * along * axis_dir;
    return t * a;
  }
  if (kind == Kind::kTranslation) {
    t.translation() = q * axis;
    return t;
  }
  // x -> point + R (x - point)
  t.linear() = Eigen::AngleAxisd(q, axis).toRotationMatrix();
  t.translation() = point - t.linear() * point;
  return t;
}

std::vector<double> MotionConfig::Poses() const {
  std::vector<double> q;
  // Each parameter from its integer step (not by adding increments), so that the way back
  // passes exactly the same poses as the way there.
  // A list of poses: `steps` from each listed pose to the next.
  const int n = kind == Kind::kPoses ? steps * static_cast<int>(poses.size()) : steps;
  for (int i = 0; i <= n; ++i) q.push_back(from + (to - from) * i / n);
  if (there_and_back)
    for (int i = n - 1; i >= 0; --i) q.push_back(from + (to - from) * i / n);
  return q;
}

const char* MotionConfig::KindName() const {
  return kind == Kind::kRotation ? "rotation" : kind == Kind::kTranslation ? "translation" : "poses";
}

std::string HarnessConfig::RigidReason(const std::string& name) const {
  for (const std::string& p : rigid)
    if (Matches(p, name)) return "a rigid part by harness.json (\"rigid\": \"" + p + "\")";
  if (only.empty()) return "";
  for (const std::string& p : only)
    if (Matches(p, name)) return "";
  return "a rigid part by harness.json (not matched by \"only\")";
}

std::string HarnessConfig::PreformedReason(const std::string& name) const {
  for (const std::string& p : preformed)
    if (Matches(p, name))
      return "pre-formed by harness.json (\"preformed\": \"" + p +
             "\"): its drawn shape is its rest shape, it only sags from it";
  return "";
}

HarnessConfig ReadHarnessConfig(const std::string& path) {
  const Json root = json::ReadJsonFile(path);
  if (!root.is_object()) throw FileError(path, "must hold a JSON object");
  if (root.contains("recordings") && root.contains("cable")) {
    throw FileError(path, "is a recording case (case.json), not a harness.json: recording cases go "
                          "to 'cablefit diagnose'");
  }
  const FieldReader r(root, path);
  RequireKnownKeys(r, {"format", "gravity", "min_bend_radius_factor", "default", "cables",
                       "junctions", "junction_defaults", "rigid", "only", "preformed", "note", "solids",
                       "motion", "tolerances"});
  if (r.Has("format") && r.RequireString("format") != "cablefit-harness/1") {
    r.Fail("format", "must be \"cablefit-harness/1\"");
  }
  HarnessConfig h;
  h.path = path;
  if (r.Has("gravity")) h.gravity = r.RequireVec3("gravity");
  if (r.Has("min_bend_radius_factor")) {
    h.min_bend_radius_factor = r.RequirePositive("min_bend_radius_factor");
  }
  if (r.Has("rigid")) h.rigid = ReadPatterns(r, "rigid");
  if (r.Has("only")) h.only = ReadPatterns(r, "only");
  if (r.Has("preformed")) h.preformed = ReadPatterns(r, "preformed");
  if (r.Has("junctions")) {
    const Json& list = r.RequireArray("junctions");
    for (size_t i = 0; i < list.size(); ++i)
      h.junctions.push_back(ReadJunction(
          FieldReader(list[i], path, json::IndexKey("junctions", i)), static_cast<int>(i)));
  }
  if (r.Has("junction_defaults")) {
    const FieldReader d = r.Child("junction_defaults");
    RequireKnownKeys(d, {"compliance", "mass", "note"});
    if (d.Has("compliance")) h.junction_compliance = d.RequireNonNegative("compliance");
    if (d.Has("mass")) h.junction_mass = d.RequireNonNegative("mass");
  }
  if (r.Has("solids")) {
    const FieldReader solids = r.Child("solids");
    for (auto it = solids.object().begin(); it != solids.object().end(); ++it) {
      const FieldReader one = solids.Child(it.key());
      RequireKnownKeys(one, {"min_clearance", "note"});
      if (it.key().empty()) solids.Fail(it.key(), "a solid name pattern must not be empty");
      h.solid_clearances.emplace_back(it.key(), one.RequireNonNegative("min_clearance"));
    }
  }
  if (r.Has("motion")) h.motion = ReadMotion(r.Child("motion"));
  if (r.Has("tolerances")) {
    const FieldReader t = r.Child("tolerances");
    RequireKnownKeys(t, {"length", "bending_stiffness", "linear_density", "clip_position", "note"});
    ToleranceConfig tc;
    // Fractions: beyond these it is another cable, not a tolerance (and EI or the mass would
    // reach zero).
    auto fraction = [&t](const std::string& key, double most) {
      if (!t.Has(key)) return 0.0;
      const double x = t.RequireNonNegative(key);
      if (x >= most) t.Fail(key, "must be a fraction below " + std::to_string(most).substr(0, 3) +
                                     " (0.02 = +-2 %)");
      return x;
    };
    tc.length = fraction("length", 0.5);
    tc.bending_stiffness = fraction("bending_stiffness", 0.9);
    tc.linear_density = fraction("linear_density", 0.9);
    if (t.Has("clip_position")) {
      tc.clip_position = t.RequireNonNegative("clip_position");
      // A metre is a different harness, not a fixing's tolerance (and a typo for millimetres).
      if (tc.clip_position >= 1.0)
        t.Fail("clip_position", "must be below 1 m (0.01 = +-10 mm along the cable)");
    }
    if (!tc.any())
      t.FailHere(
          "must vary at least one of length, bending_stiffness, linear_density, clip_position");
    h.tolerances = tc;
  }
  if (r.Has("default")) h.defaults = ReadCable(r.Child("default"), /*is_default=*/true);
  if (r.Has("cables")) {
    const FieldReader cables = r.Child("cables");
    for (auto it = cables.object().begin(); it != cables.object().end(); ++it) {
      h.cables[it.key()] = ReadCable(cables.Child(it.key()), /*is_default=*/false);
    }
  }
  return h;
}

}  // namespace cablefit::addin
