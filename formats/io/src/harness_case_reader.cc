#include "cablefit/formats/harness_case_reader.h"

#include <filesystem>
#include <map>

#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/json_util.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using json::FieldReader;
using json::Json;

SupportSpec ReadSupport(const FieldReader& r) {
  SupportSpec sp;
  if (r.Has("kind")) {
    const std::string kind = r.RequireString("kind");
    try {
      sp.kind = SupportKindFromString(kind);
    } catch (const InvalidInput&) {
      r.Fail("kind", "'" + kind + "' is unknown (expected clamp, clip or pin)");
    }
  }
  sp.s = r.RequireNonNegative("s");
  sp.position = r.RequireVec3("position");
  if (sp.kind != SupportKind::kPin) sp.tangent = r.RequireVec3("tangent");
  if (sp.kind == SupportKind::kClamp || r.Has("normal")) sp.normal = r.RequireVec3("normal");
  if (sp.kind != SupportKind::kPin) {
    try {
      Frame::FromTangentNormal(sp.tangent, sp.normal.norm() > 0 ? sp.normal : sp.tangent.unitOrthogonal());
    } catch (const InvalidInput& e) {
      r.FailHere(e.what());
    }
  }
  return sp;
}

}  // namespace

HarnessRecording ReadHarnessRecording(const std::string& path) {
  HarnessRecording rec;
  rec.case_file = CaseFilePath(path);
  const Json doc = json::ReadJsonFile(rec.case_file);
  const FieldReader root(doc, rec.case_file);
  const std::string format = root.RequireString("format");
  if (format != kHarnessRecordingFormat)
    root.Fail("format", "is '" + format + "', expected '" + kHarnessRecordingFormat + "'");
  rec.name = root.RequireString("name");
  if (rec.name.empty()) root.Fail("name", "is empty");
  const std::string dir = fs::path(rec.case_file).parent_path().string();
  NetworkSpec& net = rec.nominal;
  net.name = rec.name;
  net.gravity = root.RequireVec3("gravity");

  std::map<std::string, int> junction_of;
  if (root.Has("junctions")) {
    const Json& js = root.RequireArray("junctions");
    for (size_t i = 0; i < js.size(); ++i) {
      const FieldReader j(js[i], rec.case_file, json::IndexKey("junctions", i));
      JunctionSpec spec;
      spec.name = j.RequireString("name");
      spec.compliance = j.OptionalNumber("compliance", 0.0);
      spec.mass = j.OptionalNumber("mass", 0.0);
      if (spec.compliance < 0 || spec.mass < 0) j.FailHere("compliance and mass must not be negative");
      if (!junction_of.emplace(spec.name, static_cast<int>(i)).second) j.Fail("name", "'" + spec.name + "' repeats");
      net.junctions.push_back(spec);
    }
  }
  const Json& bs = root.RequireArray("branches");
  if (bs.empty()) root.Fail("branches", "is empty: a harness has at least one branch");
  std::map<std::string, int> branch_of;
  for (size_t i = 0; i < bs.size(); ++i) {
    const FieldReader b(bs[i], rec.case_file, json::IndexKey("branches", i));
    BranchSpec br;
    br.name = b.RequireString("name");
    if (!branch_of.emplace(br.name, static_cast<int>(i)).second) b.Fail("name", "'" + br.name + "' repeats");
    const std::string route = CaseRelativeFile(b, "route", dir);
    br.route = ReadCenterlineCsv(route);
    if (br.route.size() < 2) throw FileError(route, "a route needs at least two points");
    br.route.ParameteriseByChords();
    br.length = b.Has("length") ? b.RequirePositive("length") : br.route.s[br.route.size() - 1];
    br.material.diameter = b.RequirePositive("diameter");
    br.material.bending_stiffness = b.RequirePositive("bending_stiffness");
    br.material.torsional_stiffness = b.RequirePositive("torsional_stiffness");
    br.material.linear_density = b.RequirePositive("linear_density");
    br.material.axial_stiffness = b.OptionalNumber("axial_stiffness", 0.0);
    if (b.Has("supports")) {
      const Json& ss = b.RequireArray("supports");
      for (size_t k = 0; k < ss.size(); ++k) {
        const FieldReader sr(ss[k], rec.case_file, b.where() + "." + json::IndexKey("supports", k));
        br.supports.push_back(ReadSupport(sr));
        if (br.supports.back().s > br.length * (1 + 1e-9))
          sr.Fail("s", "lies beyond the branch (" + std::to_string(br.length) + " m long)");
      }
    }
    for (const char* end : {"start_junction", "end_junction"}) {
      if (!b.Has(end)) continue;
      const std::string name = b.RequireString(end);
      const auto it = junction_of.find(name);
      if (it == junction_of.end()) b.Fail(end, "names no junction ('" + name + "')");
      (std::string(end) == "start_junction" ? br.start_junction : br.end_junction) = it->second;
    }
    net.branches.push_back(br);
  }
  if (root.Has("solids")) {
    const Json& ss = root.RequireArray("solids");
    for (size_t i = 0; i < ss.size(); ++i) {
      const FieldReader s(ss[i], rec.case_file, json::IndexKey("solids", i));
      const Vec3 lo = s.RequireVec3("min"), hi = s.RequireVec3("max");
      if (!((hi - lo).minCoeff() > 0)) s.FailHere("max must exceed min in every coordinate");
      net.obstacles.push_back({s.RequireString("name"), BoxMesh(lo, hi)});
    }
  }
  const Json& rs = root.RequireArray("recordings");
  if (rs.empty()) root.Fail("recordings", "is empty: nothing was recorded");
  for (size_t i = 0; i < rs.size(); ++i) {
    const FieldReader r(rs[i], rec.case_file, json::IndexKey("recordings", i));
    HarnessRecordingRef ref;
    const std::string kind = r.RequireString("kind");
    if (kind == "scan") {
      ref.kind = HarnessRecordingRef::Kind::kScan;
    } else if (kind == "centerline") {
      ref.kind = HarnessRecordingRef::Kind::kCenterline;
      const std::string branch = r.RequireString("branch");
      const auto it = branch_of.find(branch);
      if (it == branch_of.end()) r.Fail("branch", "names no branch ('" + branch + "')");
      ref.branch = it->second;
    } else {
      r.Fail("kind", "'" + kind + "' is unknown (expected scan or centerline)");
    }
    ref.file = r.RequireString("file");
    ref.path = CaseRelativeFile(r, "file", dir);
    rec.recordings.push_back(ref);
  }
  return rec;
}

}  // namespace cablefit
