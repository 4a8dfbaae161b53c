// End to end: `cablefit diagnose` on all public cases. Checks the output contract of cli-v1 and
// recording-v1 (files, JSON fields and types, CSV rows) for every case, and that the force cases
// are identified as their truth.json says. The shape cases' identification is printed, not
// asserted here (that is the shape diagnosis' own test).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "cablefit/formats/case_reader.h"
#include "cablefit/formats/centerline_csv.h"
#include "cablefit/formats/file_digest.h"
#include "cablefit/formats/force_curve_csv.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/formats/truth_reader.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

std::string Slurp(const fs::path& p) { return testing::ReadTextFile(p); }

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);) out.push_back(line);
  return out;
}

const std::set<std::string> kCatalogue = {
    "none",      "intrinsic_curvature", "clamp_orientation", "twist_preload",
    "weight_stiffness_ratio", "anisotropic_bending", "support_contact", "clamp_compliance",
    "stiffness", "hysteresis"};

void CheckDiagnosisJson(const json::Json& j, const RecordingCase& rc) {
  EXPECT_EQ(j.at("format"), "cable-diagnosis/1");
  EXPECT_EQ(j.at("case"), rc.name);
  ASSERT_TRUE(j.at("effect").is_string());
  EXPECT_TRUE(kCatalogue.count(j.at("effect").get<std::string>())) << j.at("effect");
  ASSERT_TRUE(j.at("confidence").is_number());
  EXPECT_GE(j.at("confidence").get<double>(), 0.0);
  EXPECT_LE(j.at("confidence").get<double>(), 1.0);
  const json::Json& interval = j.at("interval");
  ASSERT_TRUE(interval.is_null() || (interval.is_array() && interval.size() == 2));
  if (interval.is_array()) {
    EXPECT_LE(interval[0].get<double>(), interval[1].get<double>());
    EXPECT_GE(interval[0].get<double>(), -1e-9);
    EXPECT_LE(interval[1].get<double>(), rc.nominal.length + 1e-9);
  }
  const json::Json& clamp = j.at("clamp");
  ASSERT_TRUE(clamp.is_null() || clamp.is_number_integer());
  if (clamp.is_number_integer()) {
    EXPECT_GE(clamp.get<int>(), 0);
    EXPECT_LT(clamp.get<int>(), static_cast<int>(rc.nominal.supports.size()));
  }
  ASSERT_TRUE(j.at("parameters").is_object());
  for (const auto& [name, value] : j.at("parameters").items()) {
    EXPECT_TRUE(value.is_number() || (value.is_array() && value.size() == 3)) << name;
  }
  // Every effect found, dominant first: none is an empty list, otherwise the first entry is the
  // top-level effect with its clamp, interval and parameters, and the shares are parts of the
  // baseline mismatch.
  const json::Json& effects = j.at("effects");
  ASSERT_TRUE(effects.is_array());
  if (j.at("effect") == "none") {
    EXPECT_TRUE(effects.empty());
  } else {
    ASSERT_GE(effects.size(), 1u);
    EXPECT_LE(effects.size(), 2u);
    EXPECT_EQ(effects[0].at("effect"), j.at("effect"));
    EXPECT_EQ(effects[0].at("clamp"), j.at("clamp"));
    EXPECT_EQ(effects[0].at("interval"), j.at("interval"));
    EXPECT_EQ(effects[0].at("parameters"), j.at("parameters"));
    double total = 0.0;
    for (const json::Json& e : effects) {
      EXPECT_TRUE(kCatalogue.count(e.at("effect").get<std::string>())) << e.at("effect");
      ASSERT_TRUE(e.at("share").is_number());
      total += e.at("share").get<double>();
    }
    if (j.at("explained").get<bool>()) {
      EXPECT_GT(total, 0.0);
      EXPECT_LE(total, 1.0 + 1e-9);
    }
    for (size_t k = 1; k < effects.size(); ++k)
      EXPECT_GE(effects[k - 1].at("share").get<double>(), effects[k].at("share").get<double>());
  }
  // Provenance: the case file and every recording, each with the SHA-256 of its bytes.
  const json::Json& inputs = j.at("provenance").at("inputs");
  ASSERT_EQ(inputs.size(), rc.recordings.size() + 1);
  EXPECT_EQ(inputs[0].at("role"), "case");
  EXPECT_EQ(inputs[0].at("sha256"), FileSha256(rc.case_file));
  for (size_t k = 0; k < rc.recordings.size(); ++k) {
    EXPECT_EQ(inputs[k + 1].at("role"), ToString(rc.recordings[k].kind));
    EXPECT_EQ(inputs[k + 1].at("sha256"), FileSha256(rc.recordings[k].path));
  }
  EXPECT_EQ(j.at("provenance").at("tool").get<std::string>().rfind("cablefit ", 0), 0u);
  for (const char* which : {"baseline", "fitted"}) {
    ASSERT_TRUE(j.at(which).at("max_deviation").is_number()) << which;
    ASSERT_TRUE(j.at(which).at("rms_deviation").is_number()) << which;
    EXPECT_GE(j.at(which).at("max_deviation").get<double>(),
              j.at(which).at("rms_deviation").get<double>());
  }
  ASSERT_TRUE(j.at("explanation").is_string());
  EXPECT_FALSE(j.at("explanation").get<std::string>().empty());
  const json::Json& candidates = j.at("candidates");
  ASSERT_TRUE(candidates.is_array());
  ASSERT_GE(candidates.size(), 2u);
  // The best single effect is the verdict unless a pair is (then `combinations` leads).
  if (j.at("effects").size() < 2) {
    EXPECT_EQ(candidates[0].at("effect"), j.at("effect"));
  }
  for (std::size_t i = 1; i < candidates.size(); ++i)
    EXPECT_GE(candidates[i - 1].at("score").get<double>(), candidates[i].at("score").get<double>());
  ASSERT_TRUE(j.at("explained").is_boolean());
  // The spec's thirteen fields, plus only the documented additions (the adequacy test behind
  // `explained`, notes on what was done to the recording, the provenance of the inputs, the
  // pairs of effects weighed).
  const std::set<std::string> spec = {"format",     "case",      "effect",      "confidence",
                                      "interval",   "clamp",     "parameters",  "baseline",
                                      "fitted",     "explained", "explanation", "candidates",
                                      "effects"};
  for (const std::string& key : spec) EXPECT_TRUE(j.contains(key)) << key;
  for (const auto& [key, value] : j.items())
    EXPECT_TRUE(spec.count(key) || key == "adequacy" || key == "notes" || key == "provenance" ||
                key == "combinations")
        << key;
}

// The public cases, or under sanitizers the force cases and every fourth shape case (linked into
// a scratch folder): each shape case takes minutes there.
fs::path CasesToRun(const fs::path& scratch, size_t* count) {
  const fs::path all = testing::PublicCasesDir();
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(all)) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  *count = dirs.size();
  if (!testing::SanitizerBuild()) return all;
  const fs::path some = scratch / "cases";
  fs::create_directories(some);
  size_t shape = 0;
  *count = 0;
  for (const fs::path& d : dirs) {
    if (fs::exists(d / "scan.ply") && shape++ % 4 != 0) continue;
    fs::create_directory_symlink(d, some / d.filename());
    ++*count;
  }
  return some;
}

TEST(DiagnosePublic, AllCasesWriteTheContractAndForceCasesAreIdentified) {
  const fs::path out = testing::FreshTempDir("diagnose-public");
  size_t expected = 0;
  const fs::path cases = CasesToRun(testing::FreshTempDir("diagnose-public-in"), &expected);
  const testing::CliRun run =
      testing::RunCablefit("diagnose '" + cases.string() + "' --out '" + out.string() + "' --jobs 2");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::cout << run.out;
  EXPECT_TRUE(run.err.empty()) << run.err;  // not a terminal: no progress bar

  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(cases)) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  ASSERT_EQ(dirs.size(), expected);
  const std::string summary = Slurp(out / "report.html");
  int force_cases = 0;
  for (const fs::path& dir : dirs) {
    const RecordingCase rc = ReadRecordingCase((dir / "case.json").string());
    SCOPED_TRACE(rc.name);
    const fs::path res = out / rc.name;
    // One stdout line per case: name, effect, confidence, seconds.
    const auto lines = Lines(run.out);
    EXPECT_EQ(std::count_if(lines.begin(), lines.end(),
                            [&](const std::string& l) { return l.rfind(rc.name + ": ", 0) == 0; }),
              1);
    const json::Json j = json::ReadJsonFile((res / "diagnosis.json").string());
    CheckDiagnosisJson(j, rc);
    const CaseTruth truth = ReadTruth((dir / "truth.json").string());
    std::cout << rc.name << ": truth " << truth.effect << ", diagnosed " << j.at("effect")
              << " (confidence " << j.at("confidence") << ")\n";
    // Every public recording is explained by its catalogue effect (or none).
    EXPECT_TRUE(j.at("explained").get<bool>());

    std::vector<const RecordingRef*> force;
    for (const RecordingRef& r : rc.recordings)
      if (r.kind == RecordingKind::kForceCurve) force.push_back(&r);
    if (force.empty()) {
      for (const char* name : {"nominal.csv", "fitted.csv"}) {
        SCOPED_TRACE(name);
        EXPECT_EQ(Lines(Slurp(res / name)).front(), "s,x,y,z");
        const Polyline line = ReadCenterlineCsv((res / name).string());
        ASSERT_EQ(line.size(), 401);
        EXPECT_DOUBLE_EQ(line.s[0], 0.0);
        EXPECT_NEAR(line.s[400], rc.nominal.length, 1e-12);
        // The simulated curve starts at the first clamp.
        EXPECT_LT((line.points.col(0) - rc.nominal.supports.front().position).norm(), 1e-6);
      }
      EXPECT_TRUE(fs::exists(res / "deviation-views.png"));
      EXPECT_TRUE(fs::exists(res / "deviation-along-s.png"));
    } else {
      ++force_cases;
      ASSERT_EQ(force.size(), 1u);
      const ForceCurve recorded = ReadForceCurveCsv(force[0]->path);
      const std::string header = Lines(Slurp(force[0]->path)).front();
      for (const char* name : {"nominal.csv", "fitted.csv"}) {
        SCOPED_TRACE(name);
        EXPECT_EQ(Lines(Slurp(res / name)).front(), header);
        const ForceCurve model = ReadForceCurveCsv((res / name).string());
        ASSERT_EQ(model.size(), recorded.size());
        EXPECT_EQ(model.step, recorded.step);
        EXPECT_TRUE(testing::MatricesNear(model.x, recorded.x, 0.0));
      }
      EXPECT_TRUE(fs::exists(res / "force-curve.png"));
      EXPECT_EQ(j.at("effect"), truth.effect);
      if (truth.effect == "none") {
        EXPECT_TRUE(j.at("interval").is_null());
      } else {
        EXPECT_DOUBLE_EQ(j.at("interval")[0].get<double>(), 0.0);
        EXPECT_DOUBLE_EQ(j.at("interval")[1].get<double>(), rc.nominal.length);
      }
      // The fitted model explains the recording at least as well as the nominal one.
      EXPECT_LE(j.at("fitted").at("rms_deviation").get<double>(),
                j.at("baseline").at("rms_deviation").get<double>() * (1 + 1e-9));
    }
    // The case report exists, names the case and the effect, and every picture it shows exists.
    const std::string report = Slurp(res / "report.html");
    EXPECT_NE(report.find(rc.name), std::string::npos);
    EXPECT_NE(report.find(j.at("effect").get<std::string>()), std::string::npos);
    EXPECT_EQ(report.find("http://"), std::string::npos);
    EXPECT_EQ(report.find("https://"), std::string::npos);
    for (std::size_t at = report.find("src=\""); at != std::string::npos;
         at = report.find("src=\"", at + 1)) {
      const std::string file = report.substr(at + 5, report.find('"', at + 5) - at - 5);
      EXPECT_TRUE(fs::exists(res / file)) << file;
    }
    EXPECT_NE(summary.find("href=\"" + rc.name + "/report.html\""), std::string::npos);
    // A force test has no interval or clamp along the cable; the report names its inputs with
    // their SHA-256 like diagnosis.json does.
    EXPECT_EQ(report.find("<div class=\"k\">interval</div>") == std::string::npos, !force.empty());
    EXPECT_NE(report.find("sha256 " + FileSha256(rc.case_file)), std::string::npos);
  }
  EXPECT_EQ(force_cases, 3);
}

}  // namespace
}  // namespace cablefit
