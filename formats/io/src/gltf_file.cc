#include "cablefit/formats/gltf_file.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <nlohmann/json.hpp>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"

namespace cablefit {
namespace {

static_assert(std::endian::native == std::endian::little, "GLB is little-endian");

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

void PutU32(std::string* out, std::uint32_t x) {
  char b[4];
  std::memcpy(b, &x, 4);
  out->append(b, 4);
}

void PutFloat(std::string* out, float x) {
  char b[4];
  std::memcpy(b, &x, 4);
  out->append(b, 4);
}

void Pad4(std::string* s, char with) {
  while (s->size() % 4 != 0) s->push_back(with);
}

}  // namespace

std::string EncodeGlb(const std::vector<GltfMesh>& meshes, const std::string& generator) {
  using nlohmann::json;
  std::string bin;
  json nodes = json::array(), gmeshes = json::array(), accessors = json::array(),
       views = json::array(), materials = json::array(), children = json::array();
  nodes.push_back({{"name", "cablefit (z up)"},
                   // -90 degrees about x: (x, y, z) -> (x, z, -y), the CAD frame's z up to y up.
                   {"rotation", {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)}}});
  for (const GltfMesh& m : meshes) {
    const Eigen::Index nv = m.mesh.vertices.cols(), nf = m.mesh.faces.cols();
    if (nv == 0 || nf == 0) continue;
    CABLEFIT_REQUIRE(m.mesh.faces.minCoeff() >= 0 && m.mesh.faces.maxCoeff() < nv,
                     "glTF mesh '" + m.name + "' has a face index out of range");
    const int k = static_cast<int>(gmeshes.size());
    // Positions (the accessor's min and max are required for POSITION).
    const std::size_t pos_at = bin.size();
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    for (Eigen::Index v = 0; v < nv; ++v)
      for (int i = 0; i < 3; ++i) {
        const float x = static_cast<float>(m.mesh.vertices(i, v));
        PutFloat(&bin, x);
        lo[i] = std::min(lo[i], static_cast<double>(x));
        hi[i] = std::max(hi[i], static_cast<double>(x));
      }
    const std::size_t pos_bytes = bin.size() - pos_at;
    const std::size_t idx_at = bin.size();
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int i = 0; i < 3; ++i) PutU32(&bin, static_cast<std::uint32_t>(m.mesh.faces(i, f)));
    const std::size_t idx_bytes = bin.size() - idx_at;
    views.push_back({{"buffer", 0}, {"byteOffset", pos_at}, {"byteLength", pos_bytes},
                     {"target", kArrayBuffer}});
    views.push_back({{"buffer", 0}, {"byteOffset", idx_at}, {"byteLength", idx_bytes},
                     {"target", kElementArrayBuffer}});
    accessors.push_back({{"bufferView", 2 * k}, {"componentType", kFloat}, {"count", nv},
                         {"type", "VEC3"}, {"min", {lo[0], lo[1], lo[2]}},
                         {"max", {hi[0], hi[1], hi[2]}}});
    accessors.push_back({{"bufferView", 2 * k + 1}, {"componentType", kUnsignedInt},
                         {"count", 3 * nf}, {"type", "SCALAR"}});
    json material = {{"name", m.name},
                     {"pbrMetallicRoughness",
                      {{"baseColorFactor", m.colour}, {"metallicFactor", 0.0},
                       {"roughnessFactor", 0.8}}},
                     {"doubleSided", true}};
    if (m.colour[3] < 1) material["alphaMode"] = "BLEND";
    materials.push_back(material);
    gmeshes.push_back({{"name", m.name},
                       {"primitives",
                        {{{"attributes", {{"POSITION", 2 * k}}},
                          {"indices", 2 * k + 1},
                          {"material", k},
                          {"mode", 4}}}}});
    children.push_back(static_cast<int>(nodes.size()));
    nodes.push_back({{"name", m.name}, {"mesh", k}});
  }
  if (!children.empty()) nodes[0]["children"] = children;
  json doc = {{"asset", {{"version", "2.0"}, {"generator", generator}}},
              {"scene", 0},
              {"scenes", {{{"nodes", {0}}}}},
              {"nodes", nodes}};
  if (!gmeshes.empty()) {
    doc["meshes"] = gmeshes;
    doc["materials"] = materials;
    doc["accessors"] = accessors;
    doc["bufferViews"] = views;
    doc["buffers"] = {{{"byteLength", bin.size()}}};
  }
  std::string text = doc.dump(-1, ' ', false, json::error_handler_t::replace);
  Pad4(&text, ' ');
  Pad4(&bin, '\0');
  std::string out;
  const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
  CABLEFIT_REQUIRE(total <= 0xffffffffULL, "glTF too large for one GLB file");
  PutU32(&out, kMagic);
  PutU32(&out, 2);
  PutU32(&out, static_cast<std::uint32_t>(total));
  PutU32(&out, static_cast<std::uint32_t>(text.size()));
  PutU32(&out, kChunkJson);
  out += text;
  if (!bin.empty()) {
    PutU32(&out, static_cast<std::uint32_t>(bin.size()));
    PutU32(&out, kChunkBin);
    out += bin;
  }
  return out;
}

void WriteGlb(const std::string& path, const std::vector<GltfMesh>& meshes,
              const std::string& generator) {
  WriteFileAtomically(path, EncodeGlb(meshes, generator));
}

}  // namespace cablefit
