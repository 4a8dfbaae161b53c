// Helpers shared by the relax CLI tests.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "cablefit/formats/json_util.h"

namespace cablefit::testing {

/// Shell-quoted path. Built with append: GCC 12 warns (-Wrestrict, a false positive) on
/// "'" + std::string.
inline std::string Q(const std::filesystem::path& p) {
  std::string q(1, '\'');
  q.append(p.string()).push_back('\'');
  return q;
}

/// The cable object named `name` of a `cablefit-relax/1` file.
inline const json::Json& CableNamed(const json::Json& file, const std::string& name) {
  for (const json::Json& c : file.at("cables"))
    if (c.at("name") == name) return c;
  throw std::runtime_error("no cable " + name);
}

}  // namespace cablefit::testing
