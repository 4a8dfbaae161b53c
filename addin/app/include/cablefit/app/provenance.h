// Where a result came from, in every JSON the tool writes: the tool's version and each input
// file with its SHA-256, so that a signed-off result can be traced to the exact files behind it.
// No date and no command line here: the same inputs give the same JSON on every run (the
// relax report carries the date).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace cablefit::addin {

/// "cablefit <version>".
std::string ToolVersion();

/// {"tool": ToolVersion(), "inputs": [{"role", "path", "sha256"}...]} for (role, path) pairs;
/// an empty path is left out, an unreadable file gets "sha256": null.
nlohmann::json ProvenanceJson(const std::vector<std::pair<std::string, std::string>>& inputs);

}  // namespace cablefit::addin
