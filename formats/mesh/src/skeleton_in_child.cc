// The curve skeleton computed in the helper process. CGAL's mean-curvature-flow skeleton depends
// on the heap history of the process that runs it (the same branched STL gave cable lengths
// 0.0988/0.1156/0.1212 m alone, 0.0990/0.1161/0.1206 m after another mesh, and other values
// again with --jobs 2). A fresh process per skeleton makes the routes a function of the mesh.
// The two sides talk through memory files in a plain binary layout (same machine, same build).
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/helper_process.h"
#include "cablefit/formats/internal/skeleton_helper.h"
#include "mcf_skeleton.h"

namespace cablefit {
namespace {

template <typename T>
void Put(std::ostream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
bool Get(std::istream& in, T* value) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(value), sizeof(T)));
}

// Counts read from a file are bounded by what the file can hold, so a damaged file cannot make
// a reader allocate without limit.
bool PlausibleCount(std::uint64_t count, std::uint64_t bytes_each, std::uint64_t file_bytes) {
  return bytes_each == 0 || count <= file_bytes / bytes_each;
}

std::uint64_t FileBytes(std::istream& in) {
  const auto here = in.tellg();
  in.seekg(0, std::ios::end);
  const auto end = in.tellg();
  in.seekg(here);
  return end > 0 ? static_cast<std::uint64_t>(end) : 0;
}

void WriteMesh(std::ostream& out, const TriangleMesh& mesh) {
  Put<std::uint64_t>(out, static_cast<std::uint64_t>(mesh.vertices.cols()));
  Put<std::uint64_t>(out, static_cast<std::uint64_t>(mesh.faces.cols()));
  out.write(reinterpret_cast<const char*>(mesh.vertices.data()),
            static_cast<std::streamsize>(sizeof(double) * mesh.vertices.size()));
  out.write(reinterpret_cast<const char*>(mesh.faces.data()),
            static_cast<std::streamsize>(sizeof(int) * mesh.faces.size()));
}

bool ReadMesh(std::istream& in, TriangleMesh* mesh) {
  const std::uint64_t bytes = FileBytes(in);
  std::uint64_t nv = 0, nf = 0;
  if (!Get(in, &nv) || !Get(in, &nf) || !PlausibleCount(nv, 3 * sizeof(double), bytes) ||
      !PlausibleCount(nf, 3 * sizeof(int), bytes)) {
    return false;
  }
  mesh->vertices.resize(3, static_cast<Eigen::Index>(nv));
  mesh->faces.resize(3, static_cast<Eigen::Index>(nf));
  in.read(reinterpret_cast<char*>(mesh->vertices.data()),
          static_cast<std::streamsize>(sizeof(double) * mesh->vertices.size()));
  in.read(reinterpret_cast<char*>(mesh->faces.data()),
          static_cast<std::streamsize>(sizeof(int) * mesh->faces.size()));
  if (!in) return false;
  return mesh->faces.size() == 0 ||
         (mesh->faces.minCoeff() >= 0 && mesh->faces.maxCoeff() < mesh->vertices.cols());
}

void WriteSkeleton(std::ostream& out, const CurveSkeleton& s) {
  Put<std::uint64_t>(out, static_cast<std::uint64_t>(s.nodes.cols()));
  out.write(reinterpret_cast<const char*>(s.nodes.data()),
            static_cast<std::streamsize>(sizeof(double) * s.nodes.size()));
  Put<std::uint64_t>(out, s.edges.size());
  for (const auto& [a, b] : s.edges) {
    Put<std::int32_t>(out, a);
    Put<std::int32_t>(out, b);
  }
  for (const auto& points : s.vertex_points) {
    Put<std::uint64_t>(out, points.size());
    for (const Eigen::Vector3d& p : points) out.write(reinterpret_cast<const char*>(p.data()), 24);
  }
}

bool ReadSkeleton(std::istream& in, CurveSkeleton* s) {
  const std::uint64_t bytes = FileBytes(in);
  std::uint64_t n = 0, edges = 0;
  if (!Get(in, &n) || !PlausibleCount(n, 3 * sizeof(double), bytes)) return false;
  s->nodes.resize(3, static_cast<Eigen::Index>(n));
  in.read(reinterpret_cast<char*>(s->nodes.data()),
          static_cast<std::streamsize>(sizeof(double) * s->nodes.size()));
  if (!Get(in, &edges) || !PlausibleCount(edges, 2 * sizeof(std::int32_t), bytes)) return false;
  s->edges.resize(edges);
  for (auto& [a, b] : s->edges) {
    std::int32_t ia = 0, ib = 0;
    if (!Get(in, &ia) || !Get(in, &ib)) return false;
    if (ia < 0 || ib < 0 || static_cast<std::uint64_t>(ia) >= n ||
        static_cast<std::uint64_t>(ib) >= n) {
      return false;
    }
    a = ia;
    b = ib;
  }
  s->vertex_points.assign(n, {});
  for (auto& points : s->vertex_points) {
    std::uint64_t count = 0;
    if (!Get(in, &count) || !PlausibleCount(count, 24, bytes)) return false;
    points.resize(count);
    for (Eigen::Vector3d& p : points) in.read(reinterpret_cast<char*>(p.data()), 24);
  }
  return static_cast<bool>(in);
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

double SkeletonSecondsFor(const TriangleMesh& mesh) {
  return 60.0 + 1e-3 * static_cast<double>(mesh.faces.cols());
}

CurveSkeleton ComputeMcfSkeletonInHelper(const TriangleMesh& mesh, double max_seconds) {
  const MemoryFile mesh_file("cablefit-mesh");
  const MemoryFile skeleton_file("cablefit-skeleton");
  if (!mesh_file.ok() || !skeleton_file.ok()) return ComputeMcfSkeleton(mesh);
  {
    std::ofstream out(mesh_file.path(), std::ios::binary | std::ios::trunc);
    WriteMesh(out, mesh);
    if (!out.flush()) return ComputeMcfSkeleton(mesh);
  }
  const auto outcome =
      RunHelper(kMeshHelper, {"skeleton", "3", "4"}, max_seconds, {{mesh_file.fd(), 3}, {skeleton_file.fd(), 4}});
  if (!outcome) return ComputeMcfSkeleton(mesh);  // no helper: same skeleton, history-dependent
  if (outcome->timed_out) {
    throw InvalidInput("the mesh skeleton did not finish within " +
                       std::to_string(static_cast<int>(max_seconds)) + " s");
  }
  if (outcome->signal != 0) {
    throw InvalidInput("the mesh skeleton crashed in CGAL (signal " +
                       std::to_string(outcome->signal) + ": " + ::strsignal(outcome->signal) +
                       ")");
  }
  if (outcome->exit_code == internal::kSkeletonInvalidExit) {
    throw InvalidInput(ReadText(skeleton_file.path()));
  }
  CurveSkeleton skeleton;
  std::ifstream in(skeleton_file.path(), std::ios::binary);
  if (outcome->exit_code != 0 || !ReadSkeleton(in, &skeleton)) {
    throw InvalidInput("the mesh skeleton failed (exit status " +
                       std::to_string(outcome->exit_code) + ")");
  }
  return skeleton;
}

namespace internal {

int SkeletonInHelper(int mesh_fd, int skeleton_fd) {
  const std::string mesh_path = "/proc/self/fd/" + std::to_string(mesh_fd);
  const std::string skeleton_path = "/proc/self/fd/" + std::to_string(skeleton_fd);
  TriangleMesh mesh;
  {
    std::ifstream in(mesh_path, std::ios::binary);
    if (!in || !ReadMesh(in, &mesh)) return 4;
  }
  std::ofstream out(skeleton_path, std::ios::binary | std::ios::trunc);
  if (!out) return 4;
  try {
    WriteSkeleton(out, ComputeMcfSkeleton(mesh));
  } catch (const InvalidInput& e) {
    out << e.what();
    return out.flush() ? kSkeletonInvalidExit : 4;
  }
  return out.flush() ? 0 : 4;
}

}  // namespace internal
}  // namespace cablefit
