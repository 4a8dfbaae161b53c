// Small file helpers for the formats/io tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "test_support.h"

namespace cablefit::testing {

inline void WriteText(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// Writes `bytes` to `name` in a fresh temporary folder for `tag`; returns the file's path.
inline std::string WriteTempFile(const std::string& tag, const std::string& name,
                                 const std::string& bytes) {
  const std::filesystem::path path = FreshTempDir(tag) / name;
  WriteText(path, bytes);
  return path.string();
}

inline std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// Names of the entries of `dir` (to spot stray temporary files).
inline std::vector<std::string> ListDir(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  return names;
}

}  // namespace cablefit::testing
