#include "cablefit/app/input/input_kind.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/file_kind.h"

namespace cablefit::addin {
namespace {

std::string LowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

bool IsCadPath(const std::string& path) {
  const std::string ext = LowerExtension(path);
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

bool IsMeshPath(const std::string& path) {
  static const char* const kExt[] = {".stl", ".obj", ".ply", ".gltf", ".glb",
                                     ".3mf", ".off", ".dae", ".fbx"};
  const std::string ext = LowerExtension(path);
  return std::any_of(std::begin(kExt), std::end(kExt), [&](const char* e) { return ext == e; });
}

double UnitInMetres(const std::string& name) {
  static const std::map<std::string, double> kUnits = {
      {"m", 1.0},     {"cm", 0.01},     {"mm", 0.001}, {"um", 1e-6},
      {"in", 0.0254}, {"inch", 0.0254}, {"ft", 0.3048}};
  const auto it = kUnits.find(name);
  if (it == kUnits.end()) {
    throw InvalidInput("unknown length unit '" + name + "' (use m, cm, mm, um, in or ft)");
  }
  return it->second;
}

bool IsKblPath(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".kbl";
}

bool IsKblInput(const std::string& path) {
  return IsKblPath(path) || (!IsCadPath(path) && SniffFileKind(path) == FileKind::kKbl);
}

}  // namespace cablefit::addin
