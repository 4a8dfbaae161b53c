#include "cablefit/formats/case_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "cablefit/core/base/distinct_numbers.h"
#include "cablefit/formats/input_file.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/formats/number_text.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using json::FieldReader;
using json::Json;

SupportSpec ReadClamp(const FieldReader& clamp) {
  SupportSpec support;
  if (clamp.Has("kind")) {
    const std::string kind = clamp.RequireString("kind");
    try {
      support.kind = SupportKindFromString(kind);
    } catch (const InvalidInput&) {
      clamp.Fail("kind", "'" + kind + "' is unknown (expected clamp, clip or pin)");
    }
  }
  support.s = clamp.RequireNumber("s");
  support.position = clamp.RequireVec3("position");
  // A pin fixes no direction, a clip no twist: only what the kind needs is required, but
  // whatever is given must make sense.
  const bool needs_tangent = support.kind != SupportKind::kPin;
  const bool needs_normal = support.kind == SupportKind::kClamp;
  if (needs_tangent || clamp.Has("tangent")) support.tangent = clamp.RequireVec3("tangent");
  if (needs_normal || clamp.Has("normal")) support.normal = clamp.RequireVec3("normal");
  if (support.tangent.norm() < 1e-12) clamp.Fail("tangent", "has zero length");
  if (needs_normal || clamp.Has("normal")) {
    if (support.normal.norm() < 1e-12) clamp.Fail("normal", "has zero length");
    try {
      Frame::FromTangentNormal(support.tangent, support.normal);
    } catch (const InvalidInput& e) {
      clamp.FailHere(e.what());
    }
  }
  return support;
}

void CheckClampLayout(const RodSpec& rod, const FieldReader& root) {
  const auto& supports = rod.supports;
  // Round-off slack for "exactly at the end" and "exactly straight" set-ups.
  const double tol = 1e-9 * std::max(1.0, rod.length);
  for (std::size_t i = 0; i < supports.size(); ++i) {
    const std::string name = json::IndexKey("clamps", i);
    const double s = supports[i].s;
    if (s < -tol || s > rod.length + tol)
      throw FileError(root.file(), name + ".s = " + FormatDouble(s) + " is outside [0, " +
                                       FormatDouble(rod.length) + "] (cable.length)");
    if (i == 0) continue;
    const double prev_s = supports[i - 1].s;
    if (!(s > prev_s))
      throw FileError(root.file(), "clamps must be sorted by increasing s: " + name + ".s = " +
                                       FormatDouble(s) + " after " + FormatDouble(prev_s));
    const double arc = s - prev_s;
    const double chord = (supports[i].position - supports[i - 1].position).norm();
    // Inextensible cable: the straight distance can never exceed the arc length between.
    if (chord > arc * (1.0 + 1e-6) + tol) {
      const auto [chord_text, arc_text] = DistinctNumbers(chord, arc);
      throw FileError(root.file(), "clamps " + std::to_string(i - 1) + " and " +
                                       std::to_string(i) + " are " + chord_text +
                                       " m apart but only " + arc_text + " m of cable between them");
    }
  }
}

ForceTestSpec ReadForceTest(const FieldReader& recording, double cable_length) {
  if (!recording.Has("test"))
    recording.Fail("test", "is missing: a force_curve recording needs its test set-up");
  const FieldReader test = recording.Child("test");
  ForceTestSpec spec;
  const std::string type = test.RequireString("type");
  if (type == "pinned_bending") {
    spec.type = ForceTestType::kPinnedBending;
    spec.prebend = test.RequireNonNegative("prebend");
    spec.max_displacement = test.RequirePositive("max_displacement");
    if (spec.prebend > spec.max_displacement)
      test.Fail("prebend", "(" + FormatDouble(spec.prebend) + ") exceeds max_displacement (" +
                               FormatDouble(spec.max_displacement) + ")");
    if (spec.max_displacement >= cable_length)
      test.Fail("max_displacement", "(" + FormatDouble(spec.max_displacement) +
                                        ") must be shorter than cable.length (" +
                                        FormatDouble(cable_length) + ")");
  } else if (type == "clamped_torsion") {
    spec.type = ForceTestType::kClampedTorsion;
    spec.max_angle = test.RequireNumber("max_angle");
    if (spec.max_angle == 0.0) test.Fail("max_angle", "must not be zero");
  } else {
    test.Fail("type", "'" + type + "' is unknown (expected pinned_bending or clamped_torsion)");
  }
  return spec;
}

RecordingRef ReadRecording(const FieldReader& recording, const fs::path& case_dir,
                           double cable_length) {
  RecordingRef ref;
  const std::string kind = recording.RequireString("kind");
  if (kind == "scan") {
    ref.kind = RecordingKind::kScan;
  } else if (kind == "centerline") {
    ref.kind = RecordingKind::kCenterline;
  } else if (kind == "force_curve") {
    ref.kind = RecordingKind::kForceCurve;
  } else {
    recording.Fail("kind", "'" + kind + "' is unknown (expected scan, centerline or force_curve)");
  }
  ref.file = recording.RequireString("file");
  ref.path = CaseRelativeFile(recording, "file", case_dir.string());
  if (ref.kind == RecordingKind::kForceCurve) ref.test = ReadForceTest(recording, cable_length);
  return ref;
}

}  // namespace

std::string CaseFilePath(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    const fs::path candidate = fs::path(path) / "case.json";
    if (!fs::exists(candidate, ec)) throw FileError(path, "folder holds no case.json");
    return candidate.string();
  }
  return path;
}

std::string CaseRelativeFile(const json::FieldReader& field, const std::string& key,
                             const std::string& case_dir) {
  const std::string name = field.RequireString(key);
  if (name.empty()) field.Fail(key, "is empty");
  // The format says recording paths are relative to the case: a case file must not make the tool
  // open (and copy into reports) a file outside its own folder, such as /etc/passwd.
  const fs::path file = fs::path(name).lexically_normal();
  if (file.is_absolute() || file.has_root_name() || file.has_root_directory()) {
    field.Fail(key, "'" + name + "' is absolute; recording paths are relative to the case folder");
  }
  if (!file.empty() && *file.begin() == "..") {
    field.Fail(key, "'" + name + "' leaves the case folder; recordings must be inside it");
  }
  const std::string path = (fs::path(case_dir) / file).lexically_normal().string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    field.FailHere("recorded file '" + name + "' not found (looked for " + path + ")");
  return path;
}

std::string CaseFormatOf(const std::string& path) {
  const Json doc = json::ReadJsonFile(CaseFilePath(path));
  return doc.is_object() && doc.contains("format") && doc["format"].is_string()
             ? doc["format"].get<std::string>()
             : "";
}

RecordingCase ReadRecordingCase(const std::string& path) {
  const std::string case_file = CaseFilePath(path);
  const Json doc = json::ReadJsonFile(case_file);
  const FieldReader root(doc, case_file);

  const std::string format = root.RequireString("format");
  if (format != kRecordingFormat)
    root.Fail("format", "is '" + format + "', expected '" + kRecordingFormat + "'");

  RecordingCase rc;
  rc.case_file = case_file;
  rc.name = root.RequireString("name");
  if (rc.name.empty()) root.Fail("name", "is empty");

  RodSpec& rod = rc.nominal;
  rod.name = rc.name;
  const FieldReader cable = root.Child("cable");
  rod.length = cable.RequirePositive("length");
  rod.material.diameter = cable.RequirePositive("diameter");
  rod.material.bending_stiffness = cable.RequirePositive("bending_stiffness");
  rod.material.torsional_stiffness = cable.RequirePositive("torsional_stiffness");
  rod.material.linear_density = cable.RequirePositive("linear_density");
  rod.gravity = root.RequireVec3("gravity");

  const Json& clamps = root.RequireArray("clamps");
  if (clamps.empty()) root.Fail("clamps", "is empty: a case needs at least one clamp");
  for (std::size_t i = 0; i < clamps.size(); ++i)
    rod.supports.push_back(ReadClamp(FieldReader(clamps[i], case_file, json::IndexKey("clamps", i))));
  CheckClampLayout(rod, root);

  const Json& recordings = root.RequireArray("recordings");
  if (recordings.empty()) root.Fail("recordings", "is empty: nothing was recorded");
  const fs::path case_dir = fs::path(case_file).parent_path();
  for (std::size_t i = 0; i < recordings.size(); ++i)
    rc.recordings.push_back(
        ReadRecording(FieldReader(recordings[i], case_file, json::IndexKey("recordings", i)), case_dir,
                      rod.length));
  return rc;
}

CaseFileList FindCaseFiles(const std::vector<std::string>& paths) {
  std::set<std::string> found;  // canonical paths, so "dir" and "dir/case.json" count once
  for (const std::string& p : paths) {
    std::error_code ec;
    if (!fs::exists(p, ec)) throw FileError(p, UnreachablePathProblem(p));
    if (!fs::is_directory(p, ec)) {
      found.insert(fs::weakly_canonical(p, ec).string());
      continue;
    }
    if (fs::is_regular_file(fs::path(p) / "case.json", ec)) {
      found.insert(fs::weakly_canonical(fs::path(p) / "case.json", ec).string());
      continue;
    }
    bool any = false;
    for (const auto& entry : fs::directory_iterator(p, ec)) {
      const fs::path candidate = entry.path() / "case.json";
      if (entry.is_directory(ec) && fs::is_regular_file(candidate, ec)) {
        found.insert(fs::weakly_canonical(candidate, ec).string());
        any = true;
      }
    }
    if (ec) throw FileError(p, "cannot list folder: " + ec.message());
    if (!any) throw FileError(p, "holds no case.json, neither directly nor in a sub-folder");
  }

  CaseFileList list;
  std::map<std::string, std::string> first_file_of_name;
  for (const std::string& file : found) {  // std::set iterates sorted
    std::string name;
    try {
      const Json doc = json::ReadJsonFile(file);
      if (doc.is_object() && doc.contains("name") && doc["name"].is_string())
        name = doc["name"].get<std::string>();
    } catch (const FileError&) {
      // Listed anyway: reading the case reports the problem where the user expects it.
    }
    if (!name.empty()) {
      const auto [it, inserted] = first_file_of_name.emplace(name, file);
      if (!inserted) {
        list.errors.emplace_back(file, "duplicate case name '" + name + "' (also in " +
                                           it->second + "); skipped");
        continue;
      }
    }
    list.files.push_back(file);
    list.names.push_back(name);
  }
  return list;
}

}  // namespace cablefit
