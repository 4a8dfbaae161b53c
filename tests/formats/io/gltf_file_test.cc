// Binary glTF: the container is consistent (header length, chunk types and lengths, buffer
// length = BIN chunk, every accessor inside its buffer view, every view inside the buffer) and
// the positions and indices read back as written.
#include "cablefit/formats/gltf_file.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include <nlohmann/json.hpp>

#include "io_test_files.h"

namespace cablefit {
namespace {

std::uint32_t U32(const std::string& b, std::size_t at) {
  std::uint32_t x = 0;
  std::memcpy(&x, b.data() + at, 4);
  return x;
}

TriangleMesh Square(double z) {
  TriangleMesh m;
  m.vertices.resize(3, 4);
  m.vertices << 0, 1, 1, 0,  //
      0, 0, 1, 1,            //
      z, z, z, z;
  m.faces.resize(3, 2);
  m.faces << 0, 0,  //
      1, 2,         //
      2, 3;
  return m;
}

TEST(GltfFile, GlbContainerIsConsistentAndReadsBack) {
  const auto dir = testing::FreshTempDir("gltf_file");
  const std::string path = (dir / "m.glb").string();
  WriteGlb(path, {{"a", Square(0.0)}, {"empty", TriangleMesh{}}, {"b", Square(0.5)}}, "test");
  const std::string b = testing::ReadText(path);
  ASSERT_GE(b.size(), 28u);
  EXPECT_EQ(U32(b, 0), 0x46546C67u);
  EXPECT_EQ(U32(b, 4), 2u);
  EXPECT_EQ(U32(b, 8), b.size());
  const std::uint32_t json_length = U32(b, 12);
  EXPECT_EQ(U32(b, 16), 0x4E4F534Au);
  EXPECT_EQ(json_length % 4, 0u);
  const auto doc = nlohmann::json::parse(b.substr(20, json_length));
  const std::size_t bin_at = 20 + json_length;
  const std::uint32_t bin_length = U32(b, bin_at);
  EXPECT_EQ(U32(b, bin_at + 4), 0x004E4942u);
  EXPECT_EQ(bin_at + 8 + bin_length, b.size());
  EXPECT_EQ(doc["buffers"][0]["byteLength"].get<std::size_t>(), bin_length);
  EXPECT_EQ(doc["asset"]["version"], "2.0");
  ASSERT_EQ(doc["meshes"].size(), 2u);  // the empty mesh is left out
  EXPECT_EQ(doc["meshes"][1]["name"], "b");
  for (const auto& view : doc["bufferViews"])
    EXPECT_LE(view["byteOffset"].get<std::size_t>() + view["byteLength"].get<std::size_t>(),
              bin_length);
  for (const auto& a : doc["accessors"]) {
    const auto& view = doc["bufferViews"][a["bufferView"].get<std::size_t>()];
    const std::size_t per = a["type"] == "VEC3" ? 12 : 4;
    EXPECT_EQ(a["count"].get<std::size_t>() * per, view["byteLength"].get<std::size_t>());
  }
  // Mesh "b": positions and indices as written.
  const auto& pos = doc["accessors"][2];
  const auto& idx = doc["accessors"][3];
  EXPECT_EQ(pos["count"], 4);
  EXPECT_EQ(idx["count"], 6);
  EXPECT_DOUBLE_EQ(pos["max"][2].get<double>(), 0.5);
  const std::size_t p0 = bin_at + 8 + doc["bufferViews"][2]["byteOffset"].get<std::size_t>();
  float z = 0;
  std::memcpy(&z, b.data() + p0 + 8, 4);
  EXPECT_FLOAT_EQ(z, 0.5f);
  const std::size_t i0 = bin_at + 8 + doc["bufferViews"][3]["byteOffset"].get<std::size_t>();
  EXPECT_EQ(U32(b, i0 + 20), 3u);  // the last index of face (0, 2, 3)
}

}  // namespace
}  // namespace cablefit
