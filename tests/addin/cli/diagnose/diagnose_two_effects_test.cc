// A recording with two pieces of physics left out (the sample case: a clamp held at another angle
// and a curvature set, concealed in a synthetic hand-held scan; hidden.json says what was hidden)
// is diagnosed as both, each where it acts, with shares that add up to what the fit removes; the
// report lists them and the command line names both.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cablefit/formats/json_util.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

TEST(DiagnoseTwoEffects, BothAreNamedWhereTheyActWithTheirShares) {
  const fs::path in = testing::SourceDir() / "samples" / "cases" / "sample-two-effects";
  const fs::path out = testing::FreshTempDir("two-effects");
  const testing::CliRun run =
      testing::RunCablefit("diagnose " + testing::Q(in) + " --out " + testing::Q(out));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("sample-two-effects: intrinsic_curvature + clamp_orientation"),
            std::string::npos)
      << run.out;
  const json::Json j = json::ReadJsonFile((out / "sample-two-effects" / "diagnosis.json").string());
  const json::Json hidden = json::ReadJsonFile((in / "hidden.json").string());
  const double length =
      json::ReadJsonFile((in / "case.json").string()).at("cable").at("length").get<double>();
  EXPECT_TRUE(j.at("explained").get<bool>());
  const json::Json& effects = j.at("effects");
  ASSERT_EQ(effects.size(), 2u) << effects.dump();
  double total = 0.0;
  for (const json::Json& truth : hidden.at("effects")) {
    bool found = false;
    for (const json::Json& e : effects) {
      if (e.at("effect") != truth.at("effect")) continue;
      found = true;
      if (!truth.at("clamp").is_null()) {
        EXPECT_EQ(e.at("clamp"), truth.at("clamp"));
      }
      if (!truth.at("interval").is_null()) {
        // The curvature span where it was set, within 5 % of the cable's length.
        const double tolerance = 0.05 * length;
        EXPECT_NEAR(e.at("interval")[0].get<double>(), truth.at("interval")[0].get<double>(),
                    tolerance);
        EXPECT_NEAR(e.at("interval")[1].get<double>(), truth.at("interval")[1].get<double>(),
                    tolerance);
      }
    }
    EXPECT_TRUE(found) << truth.at("effect");
  }
  for (const json::Json& e : effects) {
    EXPECT_GT(e.at("share").get<double>(), 0.0);
    total += e.at("share").get<double>();
  }
  // What the joint fit removes of the baseline's sum of squares: nearly all of it.
  EXPECT_GT(total, 0.99);
  EXPECT_LE(total, 1.0 + 1e-9);
  EXPECT_EQ(j.at("effect"), effects[0].at("effect"));
  EXPECT_GT(j.at("baseline").at("max_deviation").get<double>(),
            30.0 * j.at("fitted").at("max_deviation").get<double>());
  ASSERT_TRUE(j.at("combinations").is_array());
  ASSERT_FALSE(j.at("combinations").empty());
  std::ifstream report(out / "sample-two-effects" / "report.html");
  std::stringstream html;
  html << report.rdbuf();
  EXPECT_NE(html.str().find("Effects found"), std::string::npos);
}

}  // namespace
}  // namespace cablefit
