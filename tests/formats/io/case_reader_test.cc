#include "cablefit/formats/case_reader.h"

#include <gtest/gtest.h>

#include <functional>
#include <nlohmann/json.hpp>

#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::FreshTempDir;
using testing::PublicCasesDir;
using testing::WriteText;

fs::path PublicCases() { return PublicCasesDir(); }

std::vector<fs::path> PublicCaseDirs() {
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(PublicCases()))
    if (fs::exists(e.path() / "case.json")) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

TEST(CaseReader, AllPublicCasesLoad) {
  const auto dirs = PublicCaseDirs();
  ASSERT_EQ(dirs.size(), 11u);
  for (const auto& dir : dirs) {
    SCOPED_TRACE(dir.string());
    const RecordingCase rc = ReadRecordingCase((dir / "case.json").string());
    EXPECT_EQ(rc.name, dir.filename().string());
    EXPECT_EQ(rc.nominal.name, rc.name);
    EXPECT_GT(rc.nominal.length, 0.0);
    EXPECT_GE(rc.nominal.supports.size(), 1u);
    EXPECT_NEAR(rc.nominal.supports.front().s, 0.0, 1e-12);
    ASSERT_FALSE(rc.recordings.empty());
    for (const auto& r : rc.recordings) EXPECT_TRUE(fs::is_regular_file(r.path)) << r.path;
  }
}

TEST(CaseReader, PublicCaseFieldsAreMapped) {
  const RecordingCase rc = ReadRecordingCase((PublicCases() / "sample-anisotropic_bending").string());
  EXPECT_EQ(rc.case_file, (PublicCases() / "sample-anisotropic_bending" / "case.json").string());
  EXPECT_DOUBLE_EQ(rc.nominal.length, 0.5247);
  EXPECT_DOUBLE_EQ(rc.nominal.material.diameter, 0.0053);
  EXPECT_DOUBLE_EQ(rc.nominal.material.bending_stiffness, 0.0071701);
  EXPECT_DOUBLE_EQ(rc.nominal.material.torsional_stiffness, 0.0065062);
  EXPECT_DOUBLE_EQ(rc.nominal.material.linear_density, 0.038089);
  EXPECT_EQ(rc.nominal.gravity, Vec3(0, 0, -9.81));
  ASSERT_EQ(rc.nominal.supports.size(), 2u);
  const SupportSpec& c1 = rc.nominal.supports[1];
  EXPECT_EQ(c1.kind, SupportKind::kClamp);
  EXPECT_DOUBLE_EQ(c1.s, 0.5247);
  EXPECT_EQ(c1.position, Vec3(-0.3605, 0.0074, 0.5055));
  EXPECT_EQ(c1.tangent, Vec3(-0.00291, -0.951724, 0.306942));
  ASSERT_EQ(rc.recordings.size(), 1u);
  EXPECT_EQ(rc.recordings[0].kind, RecordingKind::kScan);
  EXPECT_EQ(rc.recordings[0].file, "scan.ply");
  EXPECT_EQ(rc.recordings[0].path, (PublicCases() / "sample-anisotropic_bending" / "scan.ply").string());
}

TEST(CaseReader, ForceCasesCarryTestAndPinKinds) {
  const RecordingCase bending = ReadRecordingCase((PublicCases() / "sample-force-hysteresis").string());
  ASSERT_EQ(bending.recordings.size(), 1u);
  EXPECT_EQ(bending.recordings[0].kind, RecordingKind::kForceCurve);
  EXPECT_EQ(bending.recordings[0].test.type, ForceTestType::kPinnedBending);
  EXPECT_DOUBLE_EQ(bending.recordings[0].test.prebend, 0.00828);
  EXPECT_DOUBLE_EQ(bending.recordings[0].test.max_displacement, 0.02445);
  EXPECT_EQ(bending.nominal.supports[0].kind, SupportKind::kPin);
  EXPECT_EQ(bending.nominal.gravity, Vec3::Zero());

  const RecordingCase torsion = ReadRecordingCase((PublicCases() / "sample-force-none").string());
  EXPECT_EQ(torsion.recordings[0].test.type, ForceTestType::kClampedTorsion);
  EXPECT_NEAR(torsion.recordings[0].test.max_angle, 0.20943951023931956, 1e-15);
}

// ---- malformed cases: each starts from a valid case and breaks one thing ----

json ValidCase() {
  return json::parse(R"({
    "format": "cable-recording/1",
    "name": "t",
    "cable": {"length": 0.6, "diameter": 0.006, "bending_stiffness": 0.012,
              "torsional_stiffness": 0.009, "linear_density": 0.05},
    "gravity": [0, 0, -9.81],
    "clamps": [
      {"s": 0.0, "position": [0, 0, 0], "tangent": [1, 0, 0], "normal": [0, 0, 1]},
      {"s": 0.6, "position": [0.45, 0.1, 0], "tangent": [1, 0, 0], "normal": [0, 0, 1]}
    ],
    "recordings": [
      {"kind": "scan", "file": "scan.ply"},
      {"kind": "force_curve", "file": "data/bending.csv",
       "test": {"type": "pinned_bending", "prebend": 0.005, "max_displacement": 0.011}}
    ]
  })");
}

fs::path WriteCase(const fs::path& dir, const std::string& text) {
  WriteText(dir / "scan.ply", "ply\n");
  WriteText(dir / "data" / "bending.csv", "step,displacement,force\n");
  WriteText(dir / "case.json", text);
  return dir / "case.json";
}

TEST(CaseReader, ValidSyntheticCaseLoadsWithRelativePaths) {
  const auto dir = FreshTempDir("io");
  const auto file = WriteCase(dir, ValidCase().dump());
  const RecordingCase rc = ReadRecordingCase(dir.string());  // the folder form
  EXPECT_EQ(rc.case_file, file.string());
  ASSERT_EQ(rc.recordings.size(), 2u);
  EXPECT_EQ(rc.recordings[1].path, (dir / "data" / "bending.csv").string());
  EXPECT_EQ(rc.recordings[1].file, "data/bending.csv");
}

TEST(CaseReader, ClipAndPinNeedLessFields) {
  json c = ValidCase();
  c["clamps"][0] = json::parse(R"({"s": 0.0, "position": [0,0,0], "kind": "pin"})");
  c["clamps"][1].erase("normal");
  c["clamps"][1]["kind"] = "clip";
  const auto dir = FreshTempDir("io");
  const RecordingCase rc = ReadRecordingCase(WriteCase(dir, c.dump()).string());
  EXPECT_EQ(rc.nominal.supports[0].kind, SupportKind::kPin);
  EXPECT_EQ(rc.nominal.supports[1].kind, SupportKind::kClip);
}

struct BadCase {
  const char* label;
  std::function<void(json&)> mutate;
  const char* message;
};

class CaseReaderRejects : public ::testing::TestWithParam<BadCase> {};

TEST_P(CaseReaderRejects, WithOneLineMessage) {
  json c = ValidCase();
  GetParam().mutate(c);
  const auto dir = FreshTempDir(std::string("io-") + GetParam().label);
  const auto file = WriteCase(dir, c.dump());
  try {
    ReadRecordingCase(file.string());
    ADD_FAILURE() << "accepted";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), file.string());
    EXPECT_NE(std::string(e.what()).find(GetParam().message), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

const BadCase kBadCases[] = {
    {"format", [](json& c) { c["format"] = "cable-recording/2"; }, "format is 'cable-recording/2'"},
    {"format_type", [](json& c) { c["format"] = 1; }, "format must be a string"},
    {"no_name", [](json& c) { c.erase("name"); }, "missing field name"},
    {"no_cable", [](json& c) { c.erase("cable"); }, "missing field cable"},
    {"cable_array", [](json& c) { c["cable"] = json::array(); }, "cable must be an object"},
    {"no_length", [](json& c) { c["cable"].erase("length"); }, "missing field cable.length"},
    {"length_string", [](json& c) { c["cable"]["length"] = "0.6"; },
     "cable.length must be a number, got string \"0.6\""},
    {"length_nan", [](json& c) { c["cable"]["length"] = "NaN"; }, "cable.length must be a number"},
    {"length_neg", [](json& c) { c["cable"]["length"] = -0.6; }, "cable.length must be positive"},
    {"diameter_zero", [](json& c) { c["cable"]["diameter"] = 0; }, "cable.diameter must be positive"},
    {"ei_neg", [](json& c) { c["cable"]["bending_stiffness"] = -1; },
     "cable.bending_stiffness must be positive"},
    {"gj_zero", [](json& c) { c["cable"]["torsional_stiffness"] = 0.0; },
     "cable.torsional_stiffness must be positive"},
    {"density_null", [](json& c) { c["cable"]["linear_density"] = nullptr; },
     "cable.linear_density must be a number, got null"},
    {"gravity_short", [](json& c) { c["gravity"] = {0, -9.81}; }, "gravity must be an array of 3"},
    {"gravity_bool", [](json& c) { c["gravity"][2] = true; }, "gravity[2] must be a number"},
    {"no_clamps", [](json& c) { c["clamps"] = json::array(); }, "at least one clamp"},
    {"clamps_object", [](json& c) { c["clamps"] = json::object(); }, "clamps must be an array"},
    {"clamp_not_object", [](json& c) { c["clamps"][1] = 3; }, "clamps[1]: must be a JSON object"},
    {"clamp_no_s", [](json& c) { c["clamps"][1].erase("s"); }, "missing field clamps[1].s"},
    {"clamp_kind", [](json& c) { c["clamps"][0]["kind"] = "weld"; },
     "clamps[0].kind 'weld' is unknown"},
    {"clamp_no_normal", [](json& c) { c["clamps"][0].erase("normal"); },
     "missing field clamps[0].normal"},
    {"zero_tangent", [](json& c) { c["clamps"][1]["tangent"] = {0, 0, 0}; },
     "clamps[1].tangent has zero length"},
    {"parallel_normal", [](json& c) { c["clamps"][0]["normal"] = {-2, 0, 0}; },
     "clamps[0]: normal is parallel to the tangent"},
    {"unsorted", [](json& c) {
       c["clamps"][0]["s"] = 0.3;
       c["clamps"][1]["s"] = 0.1;
     },
     "sorted by increasing s"},
    {"same_s", [](json& c) { c["clamps"][1]["s"] = 0.0; }, "sorted by increasing s"},
    {"s_beyond", [](json& c) { c["clamps"][1]["s"] = 0.7; }, "is outside [0, 0.6]"},
    {"s_negative", [](json& c) { c["clamps"][0]["s"] = -0.01; }, "clamps[0].s = -0.01 is outside"},
    {"too_far_apart", [](json& c) { c["clamps"][1]["position"] = {0.71, 0, 0}; },
     "clamps 0 and 1 are 0.71 m apart but only 0.6 m of cable between them"},
    {"huge", [](json& c) { c["clamps"][1]["position"][0] = 1e300; }, "apart but only"},
    {"no_recordings", [](json& c) { c.erase("recordings"); }, "missing field recordings"},
    {"empty_recordings", [](json& c) { c["recordings"] = json::array(); }, "recordings is empty"},
    {"kind_unknown", [](json& c) { c["recordings"][0]["kind"] = "video"; },
     "recordings[0].kind 'video' is unknown"},
    {"file_missing", [](json& c) { c["recordings"][0]["file"] = "gone.ply"; },
     "recorded file 'gone.ply' not found"},
    {"file_empty", [](json& c) { c["recordings"][0]["file"] = ""; }, "recordings[0].file is empty"},
    {"no_test", [](json& c) { c["recordings"][1].erase("test"); },
     "recordings[1].test is missing"},
    {"test_type", [](json& c) { c["recordings"][1]["test"]["type"] = "tensile"; },
     "recordings[1].test.type 'tensile' is unknown"},
    {"test_no_prebend", [](json& c) { c["recordings"][1]["test"].erase("prebend"); },
     "missing field recordings[1].test.prebend"},
    {"test_neg_prebend", [](json& c) { c["recordings"][1]["test"]["prebend"] = -0.001; },
     "prebend must not be negative"},
    {"test_prebend_gt_max", [](json& c) { c["recordings"][1]["test"]["prebend"] = 0.02; },
     "exceeds max_displacement"},
    {"test_max_gt_length", [](json& c) { c["recordings"][1]["test"]["max_displacement"] = 0.7; },
     "must be shorter than cable.length"},
    {"torsion_no_angle", [](json& c) { c["recordings"][1]["test"] = {{"type", "clamped_torsion"}}; },
     "missing field recordings[1].test.max_angle"},
    {"torsion_zero_angle",
     [](json& c) { c["recordings"][1]["test"] = {{"type", "clamped_torsion"}, {"max_angle", 0}}; },
     "max_angle must not be zero"},
    {"root_array", [](json& c) { c = json::array({1, 2}); }, "must be a JSON object"},
};

INSTANTIATE_TEST_SUITE_P(Malformed, CaseReaderRejects, ::testing::ValuesIn(kBadCases),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(CaseReader, RejectsTextThatIsNotJson) {
  const auto dir = FreshTempDir("io");
  WriteText(dir / "case.json", "{\"format\": \"cable-recording/1\",\n \"cable\": {\"length\": NaN}}");
  EXPECT_THROW_WITH(ReadRecordingCase((dir / "case.json").string()), FileError,
                    "not valid JSON: parse error at line 2");
  WriteText(dir / "case.json", "{\"cable\": {\"length\": 1e999}}");
  EXPECT_THROW_WITH(ReadRecordingCase((dir / "case.json").string()), FileError,
                    "not valid JSON: number overflow parsing '1e999'");
  WriteText(dir / "case.json", "");
  EXPECT_THROW_WITH(ReadRecordingCase((dir / "case.json").string()), FileError, "not valid JSON");
}

TEST(CaseReader, HugeLiteralIsRejected) {
  json c = ValidCase();
  std::string text = c.dump();
  const std::string from = "\"length\":0.6";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "\"length\":1e999");
  const auto dir = FreshTempDir("io");
  EXPECT_THROW_WITH(ReadRecordingCase(WriteCase(dir, text).string()), FileError,
                    "number overflow");
}

TEST(CaseReader, MissingFileOrFolder) {
  const auto dir = FreshTempDir("io");
  EXPECT_THROW_WITH(ReadRecordingCase((dir / "nope.json").string()), FileError, "no such file");
  EXPECT_THROW_WITH(ReadRecordingCase(dir.string()), FileError, "folder holds no case.json");
}

// ---- FindCaseFiles ----

void MakeCase(const fs::path& dir, const std::string& name) {
  WriteText(dir / "case.json", "{\"format\": \"cable-recording/1\", \"name\": \"" + name + "\"}");
}

TEST(FindCaseFiles, ExpandsFilesFoldersAndFoldersOfFolders) {
  const auto root = FreshTempDir("io");
  MakeCase(root / "set" / "b", "b");
  MakeCase(root / "set" / "a", "a");
  fs::create_directories(root / "set" / "empty");
  MakeCase(root / "single", "c");
  MakeCase(root / "loose", "d");
  const auto list = FindCaseFiles({(root / "set").string(), (root / "single").string(),
                                   (root / "loose" / "case.json").string(),
                                   (root / "set" / "a").string()});  // repeated: counts once
  EXPECT_TRUE(list.errors.empty());
  ASSERT_EQ(list.files.size(), 4u);
  EXPECT_TRUE(std::is_sorted(list.files.begin(), list.files.end()));
  EXPECT_NE(list.files[0].find("loose"), std::string::npos);
  EXPECT_NE(list.files[1].find("set/a/case.json"), std::string::npos);
}

TEST(FindCaseFiles, ReportsEachDuplicateName) {
  const auto root = FreshTempDir("io");
  MakeCase(root / "x1", "same");
  MakeCase(root / "x2", "same");
  MakeCase(root / "x3", "same");
  MakeCase(root / "y", "other");
  WriteText(root / "broken" / "case.json", "{not json");
  const auto list = FindCaseFiles({root.string()});
  ASSERT_EQ(list.files.size(), 3u);  // broken, x1, y
  ASSERT_EQ(list.errors.size(), 2u);
  EXPECT_NE(std::string(list.errors[0].what()).find("duplicate case name 'same'"), std::string::npos);
  EXPECT_NE(list.errors[0].file().find("x2"), std::string::npos);
  EXPECT_NE(list.errors[1].file().find("x3"), std::string::npos);
  EXPECT_THROW_WITH(ReadRecordingCase(list.files[0]), FileError, "not valid JSON");
}

TEST(FindCaseFiles, PublicCasesAllFound) {
  const auto list = FindCaseFiles({PublicCases().string()});
  EXPECT_EQ(list.files.size(), 11u);
  EXPECT_TRUE(list.errors.empty());
}

TEST(FindCaseFiles, BadPaths) {
  const auto root = FreshTempDir("io");
  EXPECT_THROW_WITH(FindCaseFiles({(root / "missing").string()}), FileError, "no such file or folder");
  EXPECT_THROW_WITH(FindCaseFiles({root.string()}), FileError, "holds no case.json");
}

}  // namespace
}  // namespace cablefit
