// Mesh files through assimp: read (any format it knows) into one welded TriangleMesh, and write.
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/mesh_file.h"

namespace cablefit {

TriangleMesh ReadTriangleMesh(const std::string& path, double unit) {
  if (!(unit > 0)) throw InvalidInput("mesh unit must be > 0 m");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path, "no such file");
  if (std::filesystem::file_size(path, ec) == 0) throw FileError(path, "the file is empty");
  // assimp reads the whole file and builds its scene next to it: the limit bounds that memory
  // (a binary STL takes 50 bytes a triangle; 1 GiB is 21 million triangles).
  constexpr std::uintmax_t kMaxMeshBytes = std::uintmax_t{1} << 30;
  if (const std::uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxMeshBytes)
    throw FileError(path, "is " + std::to_string(size) + " bytes, more than the limit of " +
                              std::to_string(kMaxMeshBytes) + " bytes for a mesh file");
  Assimp::Importer importer;
  // STL faces carry their own normals, so vertices would not be welded without dropping them
  // (docs/stack.md, traps). PreTransformVertices applies node transforms (OBJ/glTF scenes).
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_DropNormals | aiProcess_JoinIdenticalVertices |
                aiProcess_PreTransformVertices);
  if (!scene || !scene->HasMeshes()) {
    std::string why = importer.GetErrorString();
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw FileError(path, "not a readable mesh" + (why.empty() ? "" : " (" + why + ")"));
  }
  // Weld again across meshes: a tube split into several meshes must stay one component.
  std::map<std::array<float, 3>, int> index_of;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    std::vector<int> local(mesh->mNumVertices);
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      // Checked before the weld: a NaN key would break the map's ordering.
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw FileError(path, "vertex " + std::to_string(v + 1) + " of mesh " + std::to_string(m + 1) +
                                  " has a coordinate that is not a finite number");
      const auto [it, fresh] =
          index_of.try_emplace({p.x, p.y, p.z}, static_cast<int>(vertices.size()));
      if (fresh) vertices.emplace_back(p.x * unit, p.y * unit, p.z * unit);
      local[v] = it->second;
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by Triangulate
      const Eigen::Vector3i tri(local[face.mIndices[0]], local[face.mIndices[1]],
                                local[face.mIndices[2]]);
      if (tri(0) == tri(1) || tri(1) == tri(2) || tri(0) == tri(2)) continue;  // degenerate
      faces.push_back(tri);
    }
  }
  if (faces.empty()) throw FileError(path, "the mesh has no triangles");
  TriangleMesh result;
  result.vertices.resize(3, static_cast<Eigen::Index>(vertices.size()));
  for (size_t i = 0; i < vertices.size(); ++i) result.vertices.col(static_cast<Eigen::Index>(i)) = vertices[i];
  result.faces.resize(3, static_cast<Eigen::Index>(faces.size()));
  for (size_t i = 0; i < faces.size(); ++i) result.faces.col(static_cast<Eigen::Index>(i)) = faces[i];
  return result;
}

MeshContents ReadMeshContents(const std::string& path, double unit, double min_aspect) {
  const TriangleMesh mesh = ReadTriangleMesh(path, unit);
  return RecoverMeshContents(mesh, min_aspect);
}

std::vector<MeshTube> ReadMeshFile(const std::string& path, double unit) {
  const TriangleMesh mesh = ReadTriangleMesh(path, unit);
  try {
    return RecoverTubes(mesh);
  } catch (const FileError&) {
    throw;
  } catch (const InvalidInput& e) {
    throw FileError(path, e.what());
  }
}

void WriteMeshFile(const std::string& path, const TriangleMesh& mesh, double unit) {
  if (!(unit > 0)) throw InvalidInput("mesh unit must be > 0 m");
  namespace fs = std::filesystem;
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const char* format = ext == ".stl" ? "stlb" : ext == ".obj" ? "obj" : ext == ".ply" ? "plyb" : nullptr;
  if (!format) throw FileError(path, "unknown mesh extension '" + ext + "' (expected .stl, .obj, .ply)");

  // The scene owns (and its destructor frees) every array below.
  aiScene scene;
  scene.mRootNode = new aiNode();
  scene.mRootNode->mMeshes = new unsigned[1]{0};
  scene.mRootNode->mNumMeshes = 1;
  scene.mMaterials = new aiMaterial*[1]{new aiMaterial()};
  scene.mNumMaterials = 1;
  auto* out = new aiMesh();
  scene.mMeshes = new aiMesh*[1]{out};
  scene.mNumMeshes = 1;
  out->mMaterialIndex = 0;
  out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  out->mNumVertices = static_cast<unsigned>(mesh.vertices.cols());
  out->mVertices = new aiVector3D[out->mNumVertices];
  for (unsigned v = 0; v < out->mNumVertices; ++v) {
    const Eigen::Vector3d p = mesh.vertices.col(v) / unit;
    out->mVertices[v] = aiVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                   static_cast<float>(p.z()));
  }
  out->mNumFaces = static_cast<unsigned>(mesh.faces.cols());
  out->mFaces = new aiFace[out->mNumFaces];
  for (unsigned f = 0; f < out->mNumFaces; ++f) {
    out->mFaces[f].mNumIndices = 3;
    out->mFaces[f].mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) out->mFaces[f].mIndices[k] = static_cast<unsigned>(mesh.faces(k, f));
  }
  AtomicFile file(path);
  Assimp::Exporter exporter;
  if (exporter.Export(&scene, format, file.temp_path().string()) != aiReturn_SUCCESS)
    throw FileError(path, std::string("could not write mesh: ") + exporter.GetErrorString());
  file.Commit();
}

}  // namespace cablefit
