// Helpers shared by the relax CLI tests.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "cablefit/formats/json_util.h"

namespace cablefit::testing {

/// The cable object named `name` of a `cablefit-relax/1` file.
inline const json::Json& CableNamed(const json::Json& file, const std::string& name) {
  for (const json::Json& c : file.at("cables"))
    if (c.at("name") == name) return c;
  throw std::runtime_error("no cable " + name);
}

}  // namespace cablefit::testing
