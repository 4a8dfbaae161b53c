#include "cablefit/formats/stl_file.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iterator>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"

namespace cablefit {
namespace {

static_assert(std::endian::native == std::endian::little, "STL is little-endian");
static_assert(sizeof(float) == 4);

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50;

void PutFloat(std::string* out, double x) {
  const float f = static_cast<float>(x);
  char b[4];
  std::memcpy(b, &f, 4);
  out->append(b, 4);
}

float GetFloat(const std::string& bytes, std::size_t at) {
  float f = 0;
  std::memcpy(&f, bytes.data() + at, 4);
  return f;
}

}  // namespace

std::string EncodeStl(const TriangleMesh& mesh, const std::string& header) {
  CABLEFIT_REQUIRE(header.rfind("solid", 0) != 0, "a binary STL header must not start with 'solid'");
  const Eigen::Index nf = mesh.faces.cols();
  CABLEFIT_REQUIRE(nf <= 0xffffffffLL, "too many triangles for STL");
  std::string out = header.substr(0, kHeaderBytes);
  out.resize(kHeaderBytes, ' ');
  const auto count = static_cast<std::uint32_t>(nf);
  char b[4];
  std::memcpy(b, &count, 4);
  out.append(b, 4);
  out.reserve(out.size() + static_cast<std::size_t>(nf) * kTriangleBytes);
  for (Eigen::Index f = 0; f < nf; ++f) {
    const Vec3 a = mesh.vertices.col(mesh.faces(0, f));
    const Vec3 v = mesh.vertices.col(mesh.faces(1, f));
    const Vec3 c = mesh.vertices.col(mesh.faces(2, f));
    Vec3 n = (v - a).cross(c - a);
    n = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    for (const Vec3* p : std::initializer_list<const Vec3*>{&n, &a, &v, &c})
      for (int i = 0; i < 3; ++i) PutFloat(&out, (*p)[i]);
    out.append(2, '\0');  // attribute byte count: unused
  }
  return out;
}

void WriteStl(const std::string& path, const TriangleMesh& mesh, const std::string& header) {
  WriteFileAtomically(path, EncodeStl(mesh, header));
}

TriangleMesh ReadBinaryStl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < kHeaderBytes + 4) throw FileError(path, "too short for a binary STL");
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + kHeaderBytes, 4);
  if (bytes.size() != kHeaderBytes + 4 + std::size_t{count} * kTriangleBytes)
    throw FileError(path, "binary STL size does not match its triangle count " +
                              std::to_string(count));
  TriangleMesh mesh;
  mesh.vertices.resize(3, 3 * static_cast<Eigen::Index>(count));
  mesh.faces.resize(3, count);
  for (std::uint32_t f = 0; f < count; ++f) {
    const std::size_t at = kHeaderBytes + 4 + std::size_t{f} * kTriangleBytes + 12;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index v = 3 * static_cast<Eigen::Index>(f) + k;
      for (int i = 0; i < 3; ++i)
        mesh.vertices(i, v) = GetFloat(bytes, at + static_cast<std::size_t>(12 * k + 4 * i));
      mesh.faces(k, f) = static_cast<int>(v);
    }
  }
  return mesh;
}

}  // namespace cablefit
