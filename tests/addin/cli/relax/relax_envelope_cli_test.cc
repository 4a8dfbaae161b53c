// `cablefit relax` writes the swept envelopes of the door-hinge sample: the motion envelope
// (STL and GLB) holds every pose's centreline inside (winding number >= 1 over the STL's
// triangles), the tolerance envelope every corner's farthest point, and the GLB is a consistent
// container whose mesh is the STL's.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "cablefit/app/output/swept_envelope.h"
#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/formats/stl_file.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;
using json::Json;
using testing::Q;
using testing::RunCablefit;

fs::path Sample(const std::string& name) { return testing::SourceDir() / "samples/harness" / name; }

std::uint32_t U32(const std::string& b, std::size_t at) {
  std::uint32_t x = 0;
  std::memcpy(&x, b.data() + at, 4);
  return x;
}

Vec3 Point(const Json& row, int first) {
  return {row[first].get<double>(), row[first + 1].get<double>(), row[first + 2].get<double>()};
}

TEST(RelaxEnvelopeCli, TheEnvelopesHoldEveryPoseAndEveryCorner) {
  const fs::path dir = testing::FreshTempDir("relax_envelope_door");
  Json config = json::ReadJsonFile(Sample("door_hinge.json").string());
  config["tolerances"] = {{"length", 0.02}, {"bending_stiffness", 0.3}};
  std::ofstream(dir / "harness.json") << config.dump(1);
  const fs::path out = dir / "out";
  const auto run = RunCablefit("relax " + Q(Sample("door_hinge.stl")) + " --config " +
                               Q(dir / "harness.json") + " --out " + Q(out) + " --no-pictures");
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const Json j = json::ReadJsonFile((out / "door_hinge.json").string());
  ASSERT_TRUE(j.contains("envelopes"));
  ASSERT_EQ(j["envelopes"].size(), 2u);
  const Json& motion = j["envelopes"][0];
  const Json& tolerance = j["envelopes"][1];
  EXPECT_EQ(motion["kind"], "motion");
  EXPECT_EQ(motion["stl"], "door_hinge-motion-envelope.stl");
  EXPECT_EQ(tolerance["glb"], "door_hinge-tolerance-envelope.glb");
  const Json& cable = j["cables"][0];
  const Json& row = motion["cables"][0];
  EXPECT_EQ(row["name"], cable["name"]);
  EXPECT_EQ(row["shapes"].get<size_t>(), cable["motion"]["poses"].size());
  // There and back: the way back repeats the way there.
  EXPECT_EQ(row["shapes_used"].get<size_t>(), (cable["motion"]["poses"].size() + 1) / 2);

  // Motion: every pose's centreline (ends excepted: they sit on the caps) is inside.
  const TriangleMesh stl = ReadBinaryStl((out / motion["stl"].get<std::string>()).string());
  ASSERT_GT(stl.faces.cols(), 0);
  EXPECT_EQ(stl.faces.cols(), row["triangles"].get<long>());
  Eigen::Vector3d lo = stl.vertices.rowwise().minCoeff(), hi = stl.vertices.rowwise().maxCoeff();
  for (const Json& pose : cable["motion"]["poses"]) {
    const Json& rows = pose["centreline"]["rows"];
    for (size_t i = 1; i + 1 < rows.size(); i += 5) {
      const Vec3 p = Point(rows[i], 1);
      EXPECT_GE(addin::WindingNumber(stl, p), 1.0 - 1e-3) << pose["q"] << " " << i;
      EXPECT_TRUE((p.array() >= lo.array()).all() && (p.array() <= hi.array()).all());
    }
  }
  // The door swings 75 degrees about a vertical axis 0.3 m from the origin: the envelope spans
  // more than the relaxed cable alone.
  const Json& relaxed = cable["relaxed_centreline"]["rows"];
  double relaxed_min_y = 1e9;
  for (const Json& r : relaxed) relaxed_min_y = std::min(relaxed_min_y, r[2].get<double>());
  EXPECT_LT(lo.y(), relaxed_min_y - 0.02);

  // Tolerance: the nominal shape and the point where each corner went farthest are inside.
  const TriangleMesh tol = ReadBinaryStl((out / tolerance["stl"].get<std::string>()).string());
  // The nominal and the corners; the interior checks stayed within them.
  ASSERT_TRUE(cable["tolerance"]["interior_within_corners"].get<bool>());
  EXPECT_EQ(tolerance["cables"][0]["shapes"].get<int>(), 1 + 4);
  for (const Json& c : cable["tolerance"]["corners"]) {
    if (c["s"].get<double>() <= 0.01 || c["s"].get<double>() >= 0.28) continue;  // near a clamp
    EXPECT_GE(addin::WindingNumber(tol, Point(c["point"], 0)), 1.0 - 1e-3);
  }
  for (size_t i = 1; i + 1 < relaxed.size(); i += 25)
    EXPECT_GE(addin::WindingNumber(tol, Point(relaxed[i], 1)), 1.0 - 1e-3);

  // GLB: header, chunks and buffer agree; its one mesh has the STL's vertex ring count.
  std::ifstream in(out / motion["glb"].get<std::string>(), std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GE(b.size(), 28u);
  EXPECT_EQ(U32(b, 0), 0x46546C67u);
  EXPECT_EQ(U32(b, 8), b.size());
  const std::uint32_t json_length = U32(b, 12);
  const Json doc = Json::parse(b.substr(20, json_length));
  const std::uint32_t bin_length = U32(b, 20 + json_length);
  EXPECT_EQ(20 + json_length + 8 + bin_length, b.size());
  EXPECT_EQ(doc["buffers"][0]["byteLength"].get<std::uint32_t>(), bin_length);
  ASSERT_EQ(doc["meshes"].size(), 1u);
  EXPECT_EQ(doc["meshes"][0]["name"], cable["name"]);
  EXPECT_EQ(doc["accessors"][1]["count"].get<long>(), 3 * stl.faces.cols());
  size_t views = 0;
  for (const Json& v : doc["bufferViews"])
    views += v["byteLength"].get<size_t>();
  EXPECT_EQ(views, bin_length);

  // STEP: one swept tube per shape in the mesh, which cablefit's own reader recovers as cables
  // ending where the poses end.
  ASSERT_TRUE(motion["step"].is_string()) << motion.dump();
  const HarnessDrawing back = ReadCadFile((out / motion["step"].get<std::string>()).string());
  EXPECT_EQ(back.cables.size(), row["shapes_used"].get<size_t>());
  EXPECT_TRUE(back.solids.empty());
  for (const DrawnCable& c : back.cables) {
    EXPECT_EQ(c.name.rfind(cable["name"].get<std::string>(), 0), 0u) << c.name;
    const Vec3 a = c.centreline.points.col(0), b = c.centreline.points.rightCols<1>();
    double best = 1e9;
    for (const Json& pose : cable["motion"]["poses"]) {
      const Json& rows = pose["centreline"]["rows"];
      const Vec3 p0 = Point(rows.front(), 1), p1 = Point(rows.back(), 1);
      best = std::min(best, std::min(std::max((a - p0).norm(), (b - p1).norm()),
                                     std::max((a - p1).norm(), (b - p0).norm())));
    }
    EXPECT_LT(best, 1e-4) << c.name;  // within a tenth of a millimetre of a pose's ends
  }
  EXPECT_TRUE(tolerance["step"].is_string());
}

}  // namespace
}  // namespace cablefit
