// `cablefit relax` on a made-up drawing of flat cables (tests/data/flat/flat_cables.step: a
// 10 x 2 mm ribbon along a turning spline, a 12 x 4.4 mm flat house wire with its three cores
// drawn inside it): two cables with their sections, held at their clamps by the drawn wide axes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/json_util.h"
#include "cli_runner.h"
#include "relax_test_util.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using json::Json;

Vec3 Vector(const Json& j) { return Vec3(j[0].get<double>(), j[1].get<double>(), j[2].get<double>()); }

TEST(RelaxFlatCli, FlatCablesRelaxAsOneCableEachWithTheirSectionsAndDrawnAxes) {
  const fs::path input = testing::SourceDir() / "tests/data/flat/flat_cables.step";
  const fs::path out = testing::FreshTempDir("relax_flat");
  const auto run = testing::RunCablefit("relax " + testing::Q(input) + " --out " + testing::Q(out));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  std::printf("%s%s", run.err.c_str(), run.out.c_str());
  EXPECT_NE(run.out.find("house wire: L=503 mm, flat 12 x 4.39 mm"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("2 cables from 1 input: 2 relaxed, 0 failed"), std::string::npos);
  EXPECT_NE(run.out.find("0 taut, 0 unstable"), std::string::npos);
  const Json j = json::ReadJsonFile((out / "flat_cables.json").string());
  ASSERT_EQ(j.at("cables").size(), 2u);
  const Json& ribbon = testing::CableNamed(j, "ribbon");
  const Json& house = testing::CableNamed(j, "house wire");
  EXPECT_NEAR(ribbon.at("flat").at("width").get<double>(), 0.010, 2e-4);
  EXPECT_NEAR(ribbon.at("flat").at("thickness").get<double>(), 0.002, 1e-4);
  EXPECT_EQ(ribbon.at("flat").at("profile"), "rectangle");
  EXPECT_EQ(house.at("flat").at("profile"), "stadium");
  EXPECT_NEAR(ribbon.at("material").at("bending_ratio").get<double>(), 25.0, 1.0);
  for (const Json* c : {&ribbon, &house}) {
    EXPECT_TRUE(c->at("solver").at("converged").get<bool>());
    ASSERT_EQ(c->at("supports").size(), 2u);
    // Each clamp's normal is square to its tangent.
    for (const Json& s : c->at("supports")) {
      EXPECT_EQ(s.at("kind"), "clamp");
      EXPECT_LT(std::abs(Vector(s.at("normal")).dot(Vector(s.at("tangent")))), 1e-9);
    }
  }
  // The house wire was drawn flat side up: its clamps hold its wide axis across, along y.
  for (const Json& s : house.at("supports"))
    EXPECT_NEAR(std::abs(Vector(s.at("normal")).y()), 1.0, 1e-3);
  // Drawn with a little sag between clamps 0.5 m apart, it moves under a millimetre.
  EXPECT_GT(house.at("deviation").at("max").get<double>(), 0.0);
  EXPECT_LT(house.at("deviation").at("max").get<double>(), 1e-3);
  // The relaxed STEP holds both cables as their flat strips: read back, each is the same flat
  // cable (section within 2 %, its relaxed length), its wide axis at each end the relaxed
  // frame's d1 there, which the clamp holds (its normal).
  const HarnessDrawing back = ReadCadFile((out / "flat_cables.step").string());
  ASSERT_EQ(back.cables.size(), 2u);
  for (const DrawnCable& c : back.cables) {
    const Json& relaxed = testing::CableNamed(j, c.name);
    ASSERT_TRUE(c.flat.has_value()) << c.name << " was written as a round tube";
    EXPECT_NEAR(c.flat->width, relaxed.at("flat").at("width").get<double>(),
                0.02 * relaxed.at("flat").at("width").get<double>()) << c.name;
    EXPECT_NEAR(c.flat->thickness, relaxed.at("flat").at("thickness").get<double>(),
                0.02 * relaxed.at("flat").at("thickness").get<double>()) << c.name;
    EXPECT_EQ(c.flat->rounded_edges, relaxed.at("flat").at("profile") == "stadium") << c.name;
    const double length = c.centreline.s[c.centreline.size() - 1];
    EXPECT_NEAR(length, relaxed.at("length").get<double>(), 0.005 * length) << c.name;
    for (const Json& s : relaxed.at("supports")) {
      const Vec3 at = Vector(s.at("position"));
      Eigen::Index k = 0;
      const double gap = (c.centreline.points.colwise() - at).colwise().norm().minCoeff(&k);
      EXPECT_LT(gap, 1e-4) << c.name;
      EXPECT_GT(std::abs(c.flat->wide_axes.col(k).dot(Vector(s.at("normal")))), std::cos(0.02))
          << c.name << " at s=" << s.at("s").get<double>();
    }
  }
}

}  // namespace
}  // namespace cablefit
